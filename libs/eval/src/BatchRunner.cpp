#include <simp/eval/BatchRunner.h>
#include <simp/eval/Report.h>
#include <simp/eval/Subprocess.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace fs = std::filesystem;

namespace simp::eval {
namespace {

struct Job {
    const BatchSequence* seq;
    BatchVariant variant;
    std::string method;
    int seed;
};

std::optional<double> optionalAt(const nlohmann::json& j, const char* key) {
    return j.at(key).is_null() ? std::nullopt : std::optional<double>(j.at(key).get<double>());
}

void writeJsonAtomically(const nlohmann::json& j, const fs::path& path) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream f(tmp);
        if (!f) throw std::runtime_error("cannot write '" + tmp.string() + "'");
        f << j.dump(2) << "\n";
    }
    fs::rename(tmp, path);
}

/// Runs simp-localize (unless resumable) and evaluates its estimate.
RunRecord executeRun(const BatchConfig& cfg, const std::string& bin, const Job& job, const std::string& out_dir) {
    const fs::path dir = runDir(out_dir, job.seq->name, job.method, job.seed, job.variant.name);
    const fs::path est = dir / "estimate.tum", result = dir / "result.json";
    if (fs::exists(est) && fs::exists(result)) {
        std::ifstream f(result);
        try {
            auto r = runRecordFromJson(nlohmann::json::parse(f), result.string());
            r.resumed = true;
            return r;
        } catch (const std::exception&) {
            // unreadable result: run again
        }
    }
    fs::create_directories(dir);
    fs::remove(est);
    fs::remove(result);
    RunRecord r;
    r.sequence = job.seq->name;
    r.method = job.method;
    r.variant = job.variant.name;
    r.seed = job.seed;
    const fs::path log = dir / "localize.log";
    fs::remove(log);
    int code = 0;
    try {
        code = runProcess(localizeCommand(cfg, bin, *job.seq, job.variant, job.method, job.seed, dir.string()), log.string());
    } catch (const std::exception& e) {
        r.status = "localize_failed";
        r.error = e.what();
        writeJsonAtomically(toJson(r), result);
        return r;
    }
    if (code != 0 || !fs::exists(est)) {
        r.status = "localize_failed";
        r.error = code != 0 ? "simp-localize exited with status " + std::to_string(code) + " (see " + log.string() + ")"
                            : "simp-localize wrote no " + est.string();
        writeJsonAtomically(toJson(r), result);
        return r;
    }
    try {
        const auto m = evaluateTrajectoryFiles((fs::path(job.seq->dir) / "groundtruth.tum").string(), est.string(),
                                               cfg.metrics);
        r.success = m.success;
        r.converged = m.converged;
        r.convergence_time_s = m.convergence_time_s;
        r.ate_trans_m = m.ate_trans_m;
        r.ate_rot_rad = m.ate_rot_rad;
        r.duration_s = m.duration_s;
    } catch (const std::exception& e) {
        r.status = "eval_failed";
        r.error = e.what();
    }
    writeJsonAtomically(toJson(r), result);
    return r;
}

/// A progress bar redrawn in place on a terminal, one line per finished run otherwise.
void drawProgress(std::ostream& out, std::size_t done, std::size_t total, std::size_t resumed, bool terminal,
                  const RunRecord* last) {
    if (!terminal) {
        if (!last) return;
        out << "[" << done << "/" << total << " runs] " << last->sequence << " " << last->method
            << (last->variant.empty() ? "" : " (" + last->variant + ")") << " seed "
            << last->seed << ": " << (last->resumed ? "resumed, " : "") << last->status
            << (last->status == "ok" ? (last->success ? ", success" : ", no success") : "") << "\n";
        out.flush();
        return;
    }
    constexpr int kWidth = 40;
    const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
    out << "\r[" << std::string(filled, '#') << std::string(kWidth - filled, ' ') << "] " << done << "/" << total
        << " runs";
    if (resumed) out << " (" << resumed << " resumed)";
    if (done == total) out << "\n";
    out.flush();
}

}  // namespace

nlohmann::json toJson(const RunRecord& r) {
    const auto opt = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    return {{"sequence", r.sequence},
            {"method", r.method},
            {"variant", r.variant},
            {"seed", r.seed},
            {"status", r.status},
            {"error", r.error},
            {"success", r.success},
            {"converged", r.converged},
            {"convergence_time_s", opt(r.convergence_time_s)},
            {"ate_trans_m", opt(r.ate_trans_m)},
            {"ate_rot_rad", opt(r.ate_rot_rad)},
            {"duration_s", r.duration_s}};
}

RunRecord runRecordFromJson(const nlohmann::json& j, const std::string& where) {
    try {
        RunRecord r;
        r.sequence = j.at("sequence").get<std::string>();
        r.method = j.at("method").get<std::string>();
        r.variant = j.contains("variant") ? j.at("variant").get<std::string>() : std::string();
        r.seed = j.at("seed").get<int>();
        r.status = j.at("status").get<std::string>();
        r.error = j.at("error").get<std::string>();
        r.success = j.at("success").get<bool>();
        r.converged = j.at("converged").get<bool>();
        r.convergence_time_s = optionalAt(j, "convergence_time_s");
        r.ate_trans_m = optionalAt(j, "ate_trans_m");
        r.ate_rot_rad = optionalAt(j, "ate_rot_rad");
        r.duration_s = j.at("duration_s").get<double>();
        return r;
    } catch (const nlohmann::json::exception& e) {
        throw std::runtime_error("run result '" + where + "': " + e.what());
    }
}

std::string runDir(const std::string& out_dir, const std::string& sequence, const std::string& method, int seed,
                   const std::string& variant) {
    // an unnamed variant keeps the layout of batches before localize_configs, so they resume
    const fs::path group = variant.empty() ? fs::path(method) : fs::path(variant) / method;
    return (fs::path(out_dir) / "runs" / sequence / group / ("seed" + std::to_string(seed))).string();
}

std::vector<std::string> localizeCommand(const BatchConfig& cfg, const std::string& bin, const BatchSequence& seq,
                                         const BatchVariant& variant, const std::string& method, int seed,
                                         const std::string& run_dir) {
    std::vector<std::string> a{bin,      "--world", cfg.world, "--rawlog", (fs::path(seq.dir) / "sequence.rawlog").string(),
                               "--out",  run_dir,   "--method", method,    "--seed",
                               std::to_string(seed)};
    if (!variant.config.empty()) a.insert(a.end(), {"--config", variant.config});
    if (cfg.particles > 0) a.insert(a.end(), {"--particles", std::to_string(cfg.particles)});
    a.insert(a.end(), cfg.extra_args.begin(), cfg.extra_args.end());
    return a;
}

std::vector<RunRecord> runBatch(const BatchConfig& cfg, const std::string& out_dir, std::ostream& progress,
                                bool terminal) {
    std::string bin = cfg.localize_bin;
    if (bin.empty()) bin = (fs::path(executableDir()) / "simp-localize").string();
    if (!fs::is_regular_file(bin))
        throw std::runtime_error("simp-localize not found at '" + bin + "' (set [batch] localize_bin)");
    if (!fs::is_directory(cfg.world)) throw std::runtime_error("batch: world directory '" + cfg.world + "' not found");
    const auto variants = cfg.variants();
    for (const auto& v : variants)
        if (!v.config.empty() && !fs::is_regular_file(v.config))
            throw std::runtime_error("batch: localization config '" + v.config + "'" +
                                     (v.name.empty() ? "" : " (" + v.name + ")") + " not found");
    for (const auto& s : cfg.sequences)
        for (const char* f : {"groundtruth.tum", "sequence.rawlog"})
            if (!fs::is_regular_file(fs::path(s.dir) / f))
                throw std::runtime_error("batch: sequence '" + s.name + "': '" + (fs::path(s.dir) / f).string() +
                                         "' not found");

    std::vector<Job> jobs;
    for (const auto& s : cfg.sequences)
        for (const auto& m : cfg.methods)
            for (const auto& v : variants)  // a method's variants side by side, as the tables' rows
                for (int k = 0; k < cfg.repetitions; ++k) jobs.push_back({&s, v, m, cfg.first_seed + k});
    std::vector<RunRecord> records(jobs.size());
    std::atomic<std::size_t> next{0};
    std::size_t done = 0, resumed = 0;
    std::mutex mutex;
    drawProgress(progress, 0, jobs.size(), 0, terminal, nullptr);
    const auto worker = [&] {
        for (std::size_t i; (i = next++) < jobs.size();) {
            RunRecord r;
            try {
                r = executeRun(cfg, bin, jobs[i], out_dir);
            } catch (const std::exception& e) {  // file-system trouble: record, keep going
                r.sequence = jobs[i].seq->name;
                r.method = jobs[i].method;
                r.variant = jobs[i].variant.name;
                r.seed = jobs[i].seed;
                r.status = "localize_failed";
                r.error = e.what();
            }
            std::lock_guard<std::mutex> lock(mutex);
            records[i] = r;
            resumed += r.resumed ? 1 : 0;
            drawProgress(progress, ++done, jobs.size(), resumed, terminal, &r);
        }
    };
    std::vector<std::thread> pool;
    const int n_threads = std::max(1, std::min<int>(cfg.cores, static_cast<int>(jobs.size())));
    for (int t = 0; t < n_threads; ++t) pool.emplace_back(worker);
    for (auto& t : pool) t.join();
    return records;
}

}  // namespace simp::eval
