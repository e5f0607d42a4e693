#include <simp/eval/BatchTables.h>
#include <simp/eval/Report.h>

#include <sstream>

namespace simp::eval {
namespace {

/// Mean of the present values, nullopt when none.
std::optional<double> meanOf(const std::vector<std::optional<double>>& v) {
    double sum = 0;
    int n = 0;
    for (const auto& x : v)
        if (x) {
            sum += *x;
            ++n;
        }
    return n ? std::optional<double>(sum / n) : std::nullopt;
}

std::string csvNumber(const std::optional<double>& v) { return v ? fmt(*v, 6) : std::string(); }

std::string csvQuote(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += (c == '"') ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
    return q + "\"";
}

std::string header(const BatchSummary& s) {
    std::ostringstream o;
    o << "| Method | Map |";
    for (const auto& q : s.sequences) o << " " << q << " |";
    o << " AVG |\n|---|---|";
    for (std::size_t i = 0; i <= s.sequences.size(); ++i) o << "---:|";
    o << "\n";
    return o.str();
}

}  // namespace

BatchSummary summarize(const BatchConfig& cfg, const std::vector<RunRecord>& records) {
    BatchSummary s;
    for (const auto& m : cfg.methods)
        for (const auto& v : cfg.variants()) s.rows.push_back({m, v.name});
    for (const auto& q : cfg.sequences) s.sequences.push_back(q.name);
    s.cells.assign(s.rows.size(), std::vector<BatchCell>(s.sequences.size()));
    for (std::size_t mi = 0; mi < s.rows.size(); ++mi) {
        std::vector<std::optional<double>> rot_cols, trans_cols, conv_cols;
        double rate_sum = 0;
        for (std::size_t si = 0; si < s.sequences.size(); ++si) {
            BatchCell& c = s.cells[mi][si];
            std::vector<std::optional<double>> rot, trans, conv;
            for (const auto& r : records) {
                if (r.method != s.rows[mi].method || r.variant != s.rows[mi].variant || r.sequence != s.sequences[si])
                    continue;
                ++c.runs;
                if (!r.success) continue;
                ++c.successes;
                rot.push_back(r.ate_rot_rad);
                trans.push_back(r.ate_trans_m);
                conv.push_back(r.convergence_time_s);
            }
            c.success_rate = c.runs ? static_cast<double>(c.successes) / c.runs : 0.0;
            c.ate_rot_rad = meanOf(rot);
            c.ate_trans_m = meanOf(trans);
            c.convergence_time_s = meanOf(conv);
            rate_sum += c.success_rate;
            rot_cols.push_back(c.ate_rot_rad);
            trans_cols.push_back(c.ate_trans_m);
            conv_cols.push_back(c.convergence_time_s);
        }
        BatchCell a;
        for (const auto& c : s.cells[mi]) {
            a.runs += c.runs;
            a.successes += c.successes;
        }
        a.success_rate = s.sequences.empty() ? 0.0 : rate_sum / static_cast<double>(s.sequences.size());
        a.ate_rot_rad = meanOf(rot_cols);
        a.ate_trans_m = meanOf(trans_cols);
        a.convergence_time_s = meanOf(conv_cols);
        s.avg.push_back(a);
    }
    return s;
}

std::string batchMarkdown(const BatchConfig& cfg, const BatchSummary& s) {
    std::ostringstream o;
    const auto table = [&](const std::string& title, auto cellText) {
        o << "### " << title << "\n\n" << header(s);
        for (std::size_t mi = 0; mi < s.rows.size(); ++mi) {
            o << "| " << s.rows[mi].label() << " | " << cfg.map_name << " |";
            for (const auto& c : s.cells[mi]) o << " " << cellText(c) << " |";
            o << " " << cellText(s.avg[mi]) << " |\n";
        }
        o << "\n";
    };
    table("Success rate", [](const BatchCell& c) { return fmt(100.0 * c.success_rate, 0) + "%"; });
    table("ATE after convergence [rad/m] (mean over successful runs)", [](const BatchCell& c) {
        if (!c.ate_rot_rad || !c.ate_trans_m) return std::string("-/-");
        return fmt(*c.ate_rot_rad, 3) + "/" + fmt(*c.ate_trans_m, 2);
    });
    table("Convergence time [s] (mean over successful runs)", [](const BatchCell& c) {
        return c.convergence_time_s ? fmt(*c.convergence_time_s, 1) : std::string("-");
    });
    return o.str();
}

std::string runsCsv(const std::vector<RunRecord>& records) {
    std::ostringstream o;
    o << "sequence,method,seed,status,success,converged,convergence_time_s,ate_trans_m,ate_rot_rad,duration_s,error,variant\n";
    for (const auto& r : records)
        o << r.sequence << "," << r.method << "," << r.seed << "," << r.status << "," << (r.success ? 1 : 0) << ","
          << (r.converged ? 1 : 0) << "," << csvNumber(r.convergence_time_s) << "," << csvNumber(r.ate_trans_m) << ","
          << csvNumber(r.ate_rot_rad) << "," << fmt(r.duration_s, 6) << "," << csvQuote(r.error) << "," << r.variant << "\n";
    return o.str();
}

std::string summaryCsv(const BatchConfig& cfg, const BatchSummary& s) {
    std::ostringstream o;
    o << "method,map,sequence,runs,successes,success_rate,ate_rot_rad,ate_trans_m,convergence_time_s,variant\n";
    const auto line = [&](const BatchRow& row, const std::string& seq, const BatchCell& c) {
        o << row.method << "," << cfg.map_name << "," << seq << "," << c.runs << "," << c.successes << ","
          << fmt(c.success_rate, 6) << "," << csvNumber(c.ate_rot_rad) << "," << csvNumber(c.ate_trans_m) << ","
          << csvNumber(c.convergence_time_s) << "," << row.variant << "\n";
    };
    for (std::size_t mi = 0; mi < s.rows.size(); ++mi) {
        for (std::size_t si = 0; si < s.sequences.size(); ++si) line(s.rows[mi], s.sequences[si], s.cells[mi][si]);
        line(s.rows[mi], "AVG", s.avg[mi]);
    }
    return o.str();
}

}  // namespace simp::eval
