#pragma once
/// \file OptionTable.h
/// The .ini keys of an options struct declared once: key (= field name), field, unit, allowed values
/// and meaning. Loading, range checks, the dump of what was used and the documentation table are made
/// from the one declaration (as MRPT's CLoadableOptions fields with MRPT_LOAD_CONFIG_VAR, plus the
/// range, unit and comment MRPT keeps elsewhere). The known keys of StrictIni::checkUnknown are the
/// keys load() reads, so they derive from it as well. The default of each key is its field's
/// in-class initializer. Example: simp::stats::StatsOptions::table().
///
/// A field is a data-member pointer (&O::x) or, for a member of a member, an accessor
/// `[](auto& o) -> auto& { return o.sub.x; }`. Every value is parsed strictly here (the whole value a
/// finite number, a whole number, true/false or one of the choices), whatever the config source: the
/// same checks hold for io::StrictIni in the apps and for MRPT's own CConfigFile in its tools.

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace simp::io {

/// The values a numeric key allows: lo <= v (lo < v when lo_open) and v <= hi (v < hi when hi_open).
struct ValueRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;

    static ValueRange positive() { return {0, std::numeric_limits<double>::infinity(), true, false}; }
    static ValueRange atLeast(double lo) { return {lo, std::numeric_limits<double>::infinity(), false, false}; }
    static ValueRange atMost(double hi) { return {-std::numeric_limits<double>::infinity(), hi, false, false}; }
    static ValueRange between(double lo, double hi) { return {lo, hi, false, false}; }
    /// [0, 1]: fractions and probabilities.
    static ValueRange fraction() { return between(0, 1); }
    static ValueRange nonNegative() { return atLeast(0); }
    /// (lo, hi] / (lo, hi): probabilities and rates that must not be 0 (or 1).
    static ValueRange aboveUpTo(double lo, double hi) { return {lo, hi, true, false}; }
    static ValueRange open(double lo, double hi) { return {lo, hi, true, true}; }
    /// Any finite number.
    static ValueRange finite() { return {}; }

    bool contains(double v) const;
    /// "> 0", ">= 3", "<= 1", "in [0, 1]", "in (0, 1]", "in [0, 4294967295]" (whole bounds exact), "finite"
    std::string text() const;
};

/// The parsing and formatting behind OptionTable (non-template, libs/io/src/OptionTable.cpp).
namespace option_text {
/// `text` as a finite number. \throw std::invalid_argument "`at` = 'text' is not a finite number".
double number(const std::string& text, const std::string& at);
/// `text` as a whole number in [lo, hi] (digits, or a number such as 5e3 that is whole).
/// \throw std::invalid_argument "`at` = 'text' is not an integer" / "is out of the integer range".
std::int64_t integer(const std::string& text, const std::string& at, double lo, double hi);
/// true/false, yes/no, 1/0. \throw std::invalid_argument naming `at`.
bool flag(const std::string& text, const std::string& at);
/// "'a', 'b' or 'c'"
std::string choices(const std::vector<std::string>& names);
/// The value of `key` in `section` with blanks (and quotes) trimmed, or false when absent.
bool read(const mrpt::config::CConfigFileBase& cfg, const std::string& section, const std::string& key, std::string& text);
}  // namespace option_text

template <class Options>
class OptionTable {
   public:
    explicit OptionTable(std::string section) : m_section(std::move(section)) {}

    /// @name Declarations, in the order of the dump and the documentation
    /// @{
    /// A real number (double or float field) in `range`.
    template <class Field>
    OptionTable& number(std::string key, Field field, std::string unit, ValueRange range, std::string meaning) {
        using T = FieldType<Field>;
        static_assert(std::is_floating_point_v<T>, "number(): a double or float field");
        Entry e(std::move(key), std::move(unit), range.text(), std::move(meaning), false);
        e.parse = [field](Options& o, const std::string& t, const std::string& at) {
            std::invoke(field, o) = static_cast<T>(option_text::number(t, at));
        };
        e.print = [field](const Options& o, int precision) { return format(std::invoke(field, o), precision); };
        e.check = [field, range](const Options& o) { return range.contains(static_cast<double>(std::invoke(field, o))); };
        m_entries.push_back(std::move(e));
        return *this;
    }
    /// A whole number (int, unsigned, std::size_t ... field) in `range`.
    template <class Field>
    OptionTable& integer(std::string key, Field field, std::string unit, ValueRange range, std::string meaning) {
        using T = FieldType<Field>;
        static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>, "integer(): an integer field");
        Entry e(std::move(key), std::move(unit), range.text(), std::move(meaning), false);
        e.parse = [field](Options& o, const std::string& t, const std::string& at) {
            std::invoke(field, o) = static_cast<T>(option_text::integer(t, at, static_cast<double>(std::numeric_limits<T>::min()),
                                                                         static_cast<double>(std::numeric_limits<T>::max())));
        };
        e.print = [field](const Options& o, int) { return format(std::invoke(field, o), 6); };
        e.check = [field, range](const Options& o) { return range.contains(static_cast<double>(std::invoke(field, o))); };
        m_entries.push_back(std::move(e));
        return *this;
    }
    template <class Field>
    OptionTable& integer(std::string key, Field field, ValueRange range, std::string meaning) {
        return integer(std::move(key), field, "", range, std::move(meaning));
    }
    /// true / false.
    template <class Field>
    OptionTable& flag(std::string key, Field field, std::string meaning) {
        Entry e(std::move(key), "", "true or false", std::move(meaning), false);
        e.parse = [field](Options& o, const std::string& t, const std::string& at) { std::invoke(field, o) = option_text::flag(t, at); };
        e.print = [field](const Options& o, int) { return std::string(std::invoke(field, o) ? "true" : "false"); };
        m_entries.push_back(std::move(e));
        return *this;
    }
    /// A string field that must be one of `choices`.
    template <class Field>
    OptionTable& choice(std::string key, Field field, std::vector<std::string> choices, std::string meaning) {
        static_assert(std::is_same_v<FieldType<Field>, std::string>, "choice(): a std::string field");
        Entry e(std::move(key), "", option_text::choices(choices), std::move(meaning), true);
        e.parse = [field](Options& o, const std::string& t, const std::string&) { std::invoke(field, o) = t; };
        e.print = [field](const Options& o, int) { return std::invoke(field, o); };
        e.check = [field, choices](const Options& o) {
            return std::find(choices.begin(), choices.end(), std::invoke(field, o)) != choices.end();
        };
        e.got = [field](const Options& o) { return "'" + std::invoke(field, o) + "'"; };
        m_entries.push_back(std::move(e));
        return *this;
    }
    /// An enum field, written in the .ini as one of the names of `values`.
    template <class Field, class Enum>
    OptionTable& choice(std::string key, Field field, std::vector<std::pair<std::string, Enum>> values, std::string meaning) {
        std::vector<std::string> names;
        for (const auto& v : values) names.push_back(v.first);
        Entry e(std::move(key), "", option_text::choices(names), std::move(meaning), true);
        e.parse = [field, values, names](Options& o, const std::string& t, const std::string& at) {
            for (const auto& [name, value] : values)
                if (name == t) return void(std::invoke(field, o) = value);
            throw std::invalid_argument(at + ": must be " + option_text::choices(names) + ", got '" + t + "'");
        };
        e.print = [field, values](const Options& o, int) {
            for (const auto& [name, value] : values)
                if (value == std::invoke(field, o)) return name;
            return std::string("?");
        };
        m_entries.push_back(std::move(e));
        return *this;
    }
    /// A key with its own syntax (e.g. a "class:value" list): `parse` sets the field from the trimmed
    /// text (possibly empty) and throws naming `at`; `print` writes it back with numbers of
    /// `precision` significant digits; `check` (optional) is its range check; `allowed` documents it.
    OptionTable& custom(std::string key, std::string unit, std::string allowed, std::string meaning,
                        std::function<void(Options&, const std::string& text, const std::string& at)> parse,
                        std::function<std::string(const Options&, int precision)> print,
                        std::function<bool(const Options&)> check = {}) {
        Entry e(std::move(key), std::move(unit), std::move(allowed), std::move(meaning), false);
        e.parse = std::move(parse);
        e.print = std::move(print);
        e.check = std::move(check);
        e.allow_empty = true;
        m_entries.push_back(std::move(e));
        return *this;
    }
    /// A check across keys, reported at `key`: "[section] key: must `must`".
    OptionTable& rule(std::string key, std::function<bool(const Options&)> holds, std::string must) {
        m_rules.push_back({std::move(key), std::move(holds), std::move(must)});
        return *this;
    }
    /// @}

    /// Reads every declared key of `section` (an absent key keeps the field's value), then validate().
    /// \throw std::invalid_argument "[section] key = 'text' is not ..." naming the first bad key.
    void load(const mrpt::config::CConfigFileBase& cfg, const std::string& section, Options& o) const {
        for (const auto& e : m_entries) {
            std::string text;
            if (!option_text::read(cfg, section, e.key, text)) continue;
            const std::string at = "[" + section + "] " + e.key;
            if (text.empty() && !e.allow_empty && !e.text) throw std::invalid_argument(at + " has no value");
            e.parse(o, text, at);
        }
        validate(o, section);
    }

    /// \throw std::invalid_argument "[section] key: must be > 0 (m), got -1" naming the first bad key.
    void validate(const Options& o) const { validate(o, m_section); }
    void validate(const Options& o, const std::string& section) const {
        for (const auto& e : m_entries)
            if (e.check && !e.check(o))
                throw std::invalid_argument("[" + section + "] " + e.key + ": must be " + e.allowed +
                                            (e.unit.empty() ? "" : " (" + e.unit + ")") + ", got " + (e.got ? e.got(o) : e.print(o, 6)));
        for (const auto& r : m_rules)
            if (!r.holds(o)) throw std::invalid_argument("[" + section + "] " + r.key + ": must " + r.must);
    }

    /// "[section]" and one "key = value  // meaning (unit)" line per key: readable back as an .ini
    /// (an empty value is written "": with nothing before it, the comment would be read as the value).
    void dump(const Options& o, std::ostream& out) const { dump(o, out, m_section); }
    void dump(const Options& o, std::ostream& out, const std::string& section) const {
        std::size_t width = 0;
        for (const auto& e : m_entries) width = std::max(width, e.key.size());
        out << "[" << section << "]\n";
        for (const auto& e : m_entries)
            out << e.key << std::string(width - e.key.size(), ' ') << " = " << dumpValue(e.print(o, 6)) << "  // " << e.meaning
                << (e.unit.empty() ? "" : " (" + e.unit + ")") << "\n";
    }

    /// The documentation: a Markdown table "| key | default | unit | allowed | meaning |" from `defaults`
    /// (an empty default reads "(empty)"; a '|' in a cell is escaped so it does not split the row).
    std::string markdown(const Options& defaults) const {
        std::string s = "| key | default | unit | allowed | meaning |\n|---|---|---|---|---|\n";
        for (const auto& e : m_entries) {
            const std::string v = e.print(defaults, 6);
            const std::string value = v.empty() ? std::string("(empty)") : e.text ? "`" + v + "`" : v;
            s += "| `" + cell(e.key) + "` | " + cell(value) + " | " + cell(e.unit) + " | " + cell(e.allowed) + " | " + cell(e.meaning) + " |\n";
        }
        return s;
    }

    /// Every key with its value, numbers to 17 significant digits (compare loaded options exactly).
    std::vector<std::pair<std::string, std::string>> values(const Options& o) const {
        std::vector<std::pair<std::string, std::string>> v;
        for (const auto& e : m_entries) v.emplace_back(e.key, e.print(o, 17));
        return v;
    }

    const std::string& section() const { return m_section; }
    std::vector<std::string> keys() const {
        std::vector<std::string> k;
        for (const auto& e : m_entries) k.push_back(e.key);
        return k;
    }

   private:
    template <class Field>
    using FieldType = std::remove_cv_t<std::remove_reference_t<std::invoke_result_t<Field, Options&>>>;

    struct Entry {
        Entry(std::string k, std::string u, std::string a, std::string m, bool t)
            : key(std::move(k)), unit(std::move(u)), allowed(std::move(a)), meaning(std::move(m)), text(t) {}
        std::string key;
        std::string unit;
        std::string allowed;  ///< the allowed values as documented and in messages
        std::string meaning;
        bool text;  ///< a name, not a number: quoted in the documentation, may be empty
        std::function<void(Options&, const std::string&, const std::string&)> parse;
        std::function<std::string(const Options&, int)> print;
        std::function<bool(const Options&)> check;      ///< none: every value the parser accepts is valid
        std::function<std::string(const Options&)> got;  ///< the value in messages (default: print)
        bool allow_empty = false;
    };
    struct Rule {
        std::string key;
        std::function<bool(const Options&)> holds;
        std::string must;
    };

    static std::string dumpValue(const std::string& v) { return v.empty() ? std::string("\"\"") : v; }
    /// GitHub Markdown ends a table cell at every unescaped '|', also inside `code`.
    static std::string cell(const std::string& text) {
        std::string out;
        for (const char c : text) {
            if (c == '|') out += '\\';
            out += c;
        }
        return out;
    }

    template <class T>
    static std::string format(const T& v, int precision) {
        std::ostringstream out;
        out.precision(precision);
        if constexpr (std::is_floating_point_v<T>) out << static_cast<double>(v);
        else out << v;
        return out.str();
    }

    std::string m_section;
    std::vector<Entry> m_entries;
    std::vector<Rule> m_rules;
};

}  // namespace simp::io
