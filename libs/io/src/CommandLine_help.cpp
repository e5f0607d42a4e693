/// \file CommandLine_help.cpp
/// The --help text of a CommandLine, made from its declarations.
#include <simp/io/CommandLine.h>

#include <algorithm>

namespace simp::io {
namespace {

constexpr std::size_t kWidth = 100;     ///< usage lines wrap here
constexpr std::size_t kMaxColumn = 24;  ///< option help starts at most this far right

std::string left(const CommandOption& o) {
    std::string s = "--" + o.name;
    if (!o.alias.empty()) s += ", --" + o.alias;
    return o.value_name.empty() ? s : s + " " + o.value_name;
}

/// `text` with every line after the first indented by `indent` spaces.
std::string indentLines(const std::string& text, std::size_t indent) {
    std::string out;
    for (char c : text) {
        out += c;
        if (c == '\n') out += std::string(indent, ' ');
    }
    return out;
}

}  // namespace

std::string CommandLine::usageLine() const {
    std::vector<std::string> words;
    for (const auto& o : m_options) {
        const std::string w = "--" + o.name + (o.value_name.empty() ? "" : " " + o.value_name);
        words.push_back(o.required ? w : "[" + w + "]");
    }
    for (const auto& p : m_positional_specs) words.push_back(p.required ? p.value_name : "[" + p.value_name + "]");
    std::string out = m_name, line = m_name;
    const std::size_t indent = m_name.size() + 1;
    for (const auto& w : words) {
        if (line.size() + 1 + w.size() > kWidth && line.size() > indent) {
            out += "\n" + std::string(indent, ' ');
            line = std::string(indent, ' ');
        } else {
            out += " ";
            line += " ";
        }
        out += w;
        line += w;
    }
    return out;
}

std::string CommandLine::optionList(std::size_t indent) const {
    std::vector<std::pair<std::string, std::string>> rows;
    for (const auto& p : m_positional_specs) rows.emplace_back(p.value_name, p.help);
    for (const auto& o : m_options) rows.emplace_back(left(o), o.help + (o.unit.empty() ? "" : " (" + o.unit + ")"));
    rows.emplace_back("-h, --help", "print this help and exit");
    if (!m_version.empty()) rows.emplace_back("--version", "print the version and exit");
    std::size_t column = 0;
    for (const auto& r : rows) column = std::max(column, r.first.size());
    column = std::min(column, kMaxColumn) + 2;
    const std::string pad(indent, ' ');
    std::string out;
    for (const auto& [l, h] : rows) {
        out += pad + l;
        if (l.size() + 2 > column) out += "\n" + pad + std::string(column, ' ');
        else out += std::string(column - l.size(), ' ');
        out += indentLines(h, indent + column) + "\n";
    }
    return out;
}

std::string CommandLine::help() const {
    std::string out = "Usage: " + usageLine() + "\n";
    if (!m_summary.empty()) out += m_summary + (m_summary.back() == '\n' ? "" : "\n");
    out += "\nOptions:\n" + optionList(2);
    if (!m_notes.empty()) out += "\n" + m_notes + (m_notes.back() == '\n' ? "" : "\n");
    return out;
}

}  // namespace simp::io
