#pragma once
/// \file OptionTable.h
/// The .ini keys of an options struct declared once: key (= field name), field, unit, allowed values
/// and meaning. Loading, range checks, the dump of what was used and the documentation table are made
/// from the one declaration (as MRPT's CLoadableOptions fields with MRPT_LOAD_CONFIG_VAR, plus the
/// range, unit and comment MRPT keeps elsewhere). The known keys of StrictIni::checkUnknown are the
/// keys load() reads, so they derive from it as well. The default of each key is its field's
/// in-class initializer. Example: simp::stats::StatsOptions::table().

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace simp::io {

/// The values a numeric key allows: lo <= v (lo < v when lo_open) and v <= hi.
struct ValueRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;

    static ValueRange positive() { return {0, std::numeric_limits<double>::infinity(), true}; }
    static ValueRange atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false}; }
    static ValueRange between(double lo, double hi) { return {lo, hi, false}; }

    bool contains(double v) const { return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && v <= hi; }
    /// "> 0", ">= 3", "in [0, 1]"
    std::string text() const {
        std::ostringstream s;
        if (std::isinf(hi)) s << (lo_open ? "> " : ">= ") << lo;
        else s << "in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
        return s.str();
    }
};

template <class Options>
class OptionTable {
   public:
    explicit OptionTable(std::string section) : m_section(std::move(section)) {}

    /// @name Declarations, in the order of the dump and the documentation
    /// @{
    OptionTable& number(std::string key, double Options::*field, std::string unit, ValueRange range, std::string meaning) {
        m_entries.push_back({std::move(key), field, std::move(unit), range, {}, std::move(meaning)});
        return *this;
    }
    OptionTable& integer(std::string key, int Options::*field, ValueRange range, std::string meaning) {
        m_entries.push_back({std::move(key), field, {}, range, {}, std::move(meaning)});
        return *this;
    }
    OptionTable& choice(std::string key, std::string Options::*field, std::vector<std::string> choices, std::string meaning) {
        m_entries.push_back({std::move(key), field, {}, {}, std::move(choices), std::move(meaning)});
        return *this;
    }
    /// @}

    /// Reads every declared key of `section` (an absent key keeps the field's value), then validate().
    void load(const mrpt::config::CConfigFileBase& cfg, const std::string& section, Options& o) const {
        for (const auto& e : m_entries) {
            if (const auto* d = std::get_if<double Options::*>(&e.field)) o.*(*d) = cfg.read_double(section, e.key, o.*(*d));
            else if (const auto* i = std::get_if<int Options::*>(&e.field)) o.*(*i) = cfg.read_int(section, e.key, o.*(*i));
            else if (const auto* s = std::get_if<std::string Options::*>(&e.field)) o.*(*s) = cfg.read_string(section, e.key, o.*(*s));
        }
        validate(o);
    }

    /// \throw std::invalid_argument "[section] key: must be > 0 (m), got -1" naming the first bad key.
    void validate(const Options& o) const {
        for (const auto& e : m_entries) {
            if (const auto* s = std::get_if<std::string Options::*>(&e.field)) {
                bool ok = false;
                for (const auto& c : e.choices) ok = ok || c == o.*(*s);
                if (!ok) throw std::invalid_argument(where(e) + "must be " + choicesText(e) + ", got '" + o.*(*s) + "'");
                continue;
            }
            const double v = numeric(e, o);
            if (!e.range.contains(v))
                throw std::invalid_argument(where(e) + "must be " + e.range.text() + (e.unit.empty() ? "" : " (" + e.unit + ")") +
                                            ", got " + value(e, o));
        }
    }

    /// "[section]" and one "key = value  // meaning (unit)" line per key: readable back as an .ini.
    void dump(const Options& o, std::ostream& out) const {
        std::size_t width = 0;
        for (const auto& e : m_entries) width = std::max(width, e.key.size());
        out << "[" << m_section << "]\n";
        for (const auto& e : m_entries)
            out << e.key << std::string(width - e.key.size(), ' ') << " = " << value(e, o) << "  // " << e.meaning
                << (e.unit.empty() ? "" : " (" + e.unit + ")") << "\n";
    }

    /// The documentation: a Markdown table "| key | default | unit | allowed | meaning |" from `defaults`.
    std::string markdown(const Options& defaults) const {
        std::string s = "| key | default | unit | allowed | meaning |\n|---|---|---|---|---|\n";
        for (const auto& e : m_entries) {
            const bool text = std::holds_alternative<std::string Options::*>(e.field);
            s += "| `" + e.key + "` | " + (text ? "`" + value(e, defaults) + "`" : value(e, defaults)) + " | " + e.unit + " | " +
                 (text ? choicesText(e) : e.range.text()) + " | " + e.meaning + " |\n";
        }
        return s;
    }

    const std::string& section() const { return m_section; }
    std::vector<std::string> keys() const {
        std::vector<std::string> k;
        for (const auto& e : m_entries) k.push_back(e.key);
        return k;
    }

   private:
    struct Entry {
        std::string key;
        std::variant<double Options::*, int Options::*, std::string Options::*> field;
        std::string unit;
        ValueRange range;
        std::vector<std::string> choices;
        std::string meaning;
    };

    std::string where(const Entry& e) const { return "[" + m_section + "] " + e.key + ": "; }
    static double numeric(const Entry& e, const Options& o) {
        if (const auto* d = std::get_if<double Options::*>(&e.field)) return o.*(*d);
        return o.*std::get<int Options::*>(e.field);
    }
    static std::string value(const Entry& e, const Options& o) {
        if (const auto* s = std::get_if<std::string Options::*>(&e.field)) return o.*(*s);
        std::ostringstream out;
        if (const auto* d = std::get_if<double Options::*>(&e.field)) out << o.*(*d);
        else out << o.*std::get<int Options::*>(e.field);
        return out.str();
    }
    static std::string choicesText(const Entry& e) {
        std::string s;
        for (std::size_t k = 0; k < e.choices.size(); ++k)
            s += (k == 0 ? "" : k + 1 == e.choices.size() ? " or " : ", ") + ("'" + e.choices[k] + "'");
        return s;
    }

    std::string m_section;
    std::vector<Entry> m_entries;
};

}  // namespace simp::io
