/// \file CommandLine.cpp
/// Declarations, parse() and the typed values; the help text is in CommandLine_help.cpp.
#include <simp/io/CommandLine.h>
#include <simp/io/StrictNumber.h>

#include <algorithm>
#include <stdexcept>

namespace simp::io {
namespace {

const std::string kSeeHelp = " (see --help)";

std::invalid_argument usageError(const std::string& text) { return std::invalid_argument(text + kSeeHelp); }

std::string integerRange(std::int64_t lo, std::int64_t hi) {
    return "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

}  // namespace

CommandLine::CommandLine(std::string name, std::string summary) : m_name(std::move(name)), m_summary(std::move(summary)) {}

CommandOption& CommandLine::add(CommandOption o) {
    if (o.name.empty() || o.name.rfind("-", 0) == 0 || find(o.name) || o.name == "help" || o.name == "version")
        throw std::logic_error("CommandLine " + m_name + ": bad or repeated option name '" + o.name + "'");
    m_options.push_back(std::move(o));
    return m_options.back();
}

CommandLine& CommandLine::required(const std::string& name, const std::string& value_name, const std::string& help) {
    add({name, value_name, help, true, {}, {}});
    return *this;
}

CommandLine& CommandLine::option(const std::string& name, const std::string& value_name, const std::string& help) {
    add({name, value_name, help, false, {}, {}});
    return *this;
}

CommandLine& CommandLine::flag(const std::string& name, const std::string& help) {
    add({name, {}, help, false, {}, {}});
    return *this;
}

CommandLine& CommandLine::positional(const std::string& value_name, const std::string& help, bool required) {
    if (required && !m_positional_specs.empty() && !m_positional_specs.back().required)
        throw std::logic_error("CommandLine " + m_name + ": a required positional after an optional one");
    m_positional_specs.push_back({value_name, value_name, help, required, {}, {}});
    return *this;
}

CommandLine& CommandLine::alias(const std::string& other_name) {
    if (m_options.empty() || find(other_name)) throw std::logic_error("CommandLine " + m_name + ": bad alias '" + other_name + "'");
    m_options.back().alias = other_name;
    return *this;
}

CommandLine& CommandLine::unit(const std::string& unit) {
    if (m_options.empty()) throw std::logic_error("CommandLine " + m_name + ": unit() before an option");
    m_options.back().unit = unit;
    return *this;
}

CommandLine& CommandLine::version(const std::string& text) {
    m_version = text;
    return *this;
}

CommandLine& CommandLine::notes(const std::string& text) {
    m_notes = text;
    return *this;
}

const CommandOption* CommandLine::find(const std::string& name) const {
    for (const auto& o : m_options)
        if (o.name == name || (!o.alias.empty() && o.alias == name)) return &o;
    return nullptr;
}

const CommandOption& CommandLine::declared(const std::string& name) const {
    const CommandOption* o = find(name);
    if (!o) throw std::logic_error("CommandLine " + m_name + ": option --" + name + " is not declared");
    return *o;
}

std::string CommandLine::what(const CommandOption& o) const {
    return "option --" + o.name + (o.unit.empty() ? "" : " (" + o.unit + ")");
}

bool CommandLine::parse(int argc, const char* const* argv, std::ostream& out) {
    return parse(std::vector<std::string>(argv + std::min(argc, 1), argv + std::max(argc, 0)), out);
}

bool CommandLine::parse(const std::vector<std::string>& args, std::ostream& out) {
    m_values.clear();
    m_positionals.clear();
    for (const std::string& a : args) {  // help wins over every other argument, wherever it is
        if (a == "--") break;
        if (a == "--help" || a == "-h") {
            out << help();
            return false;
        }
        if (a == "--version" && !m_version.empty()) {
            out << m_name << " " << m_version << "\n";
            return false;
        }
    }
    bool options_ended = false;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (!options_ended && a == "--") {
            options_ended = true;
            continue;
        }
        if (options_ended || a.size() < 2 || a[0] != '-') {
            if (m_positionals.size() >= m_positional_specs.size()) throw usageError("unexpected argument '" + a + "'");
            m_positionals.push_back(a);
            continue;
        }
        const auto eq = a.find('=');
        const std::string name = a.rfind("--", 0) == 0 ? a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2) : "";
        const CommandOption* o = find(name);
        if (!o)
            throw usageError("unknown option '" + a.substr(0, eq) + "'" +
                             (m_command.empty() ? "" : " for command '" + m_command + "'"));
        if (m_values.count(o->name))
            throw usageError("option --" + o->name + (o->alias.empty() ? "" : " (--" + o->alias + ")") + " given twice");
        std::string value;
        if (o->value_name.empty()) {
            if (eq != std::string::npos) throw usageError("option --" + o->name + " is a flag and takes no value");
        } else if (eq != std::string::npos) {
            value = a.substr(eq + 1);
        } else {
            if (i + 1 >= args.size()) throw usageError("option --" + name + " needs a value");
            value = args[++i];
        }
        m_values[o->name] = value;
    }
    for (const auto& o : m_options) {
        if (!o.required) continue;
        const auto it = m_values.find(o.name);
        if (it == m_values.end()) throw usageError("missing required option --" + o.name + " " + o.value_name);
        if (it->second.empty()) throw usageError("option --" + o.name + " needs a non-empty value");
    }
    for (std::size_t k = m_positionals.size(); k < m_positional_specs.size(); ++k)
        if (m_positional_specs[k].required) throw usageError("missing argument " + m_positional_specs[k].value_name);
    return true;
}

bool CommandLine::has(const std::string& name) const {
    declared(name);
    return m_values.count(name) > 0;
}

const std::string& CommandLine::value(const std::string& name) const {
    static const std::string kEmpty;
    declared(name);
    const auto it = m_values.find(name);
    return it == m_values.end() ? kEmpty : it->second;
}

std::optional<double> CommandLine::number(const std::string& name, double lo, double hi) const {
    if (!has(name)) return std::nullopt;
    return parseNumber(value(name), what(declared(name)), lo, hi);
}

std::optional<std::int64_t> CommandLine::integer(const std::string& name, std::int64_t lo, std::int64_t hi) const {
    if (!has(name)) return std::nullopt;
    const std::string& text = value(name);
    const auto v = parseWholeInteger(text);
    if (!v)
        throw std::invalid_argument(what(declared(name)) + ": '" + text + "' is not an integer" +
                                    (parseFiniteNumber(text) ? " in " + integerRange(lo, hi) : ""));
    if (*v < lo || *v > hi)
        throw std::invalid_argument(what(declared(name)) + ": " + std::to_string(*v) + " must be in " + integerRange(lo, hi));
    return v;
}

}  // namespace simp::io
