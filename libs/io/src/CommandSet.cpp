/// \file CommandSet.cpp
#include <simp/io/CommandSet.h>

#include <sstream>
#include <stdexcept>

namespace simp::io {

CommandSet::CommandSet(std::string program, std::string summary)
    : m_program(std::move(program)), m_summary(std::move(summary)) {}

CommandLine& CommandSet::add(const std::string& command, const std::string& summary) {
    m_commands.emplace_back(command, CommandLine(m_program + " " + command, summary));
    m_commands.back().second.setCommand(command);
    return m_commands.back().second;
}

CommandSet& CommandSet::notes(const std::string& text) {
    m_notes = text;
    return *this;
}

std::string CommandSet::commandNames() const {
    std::string s;
    for (const auto& [name, cl] : m_commands) s += (s.empty() ? "" : ", ") + name;
    return s;
}

const CommandLine* CommandSet::parse(int argc, const char* const* argv, std::ostream& out) {
    return parse(std::vector<std::string>(argv + (argc > 0 ? 1 : 0), argv + (argc > 0 ? argc : 0)), out);
}

const CommandLine* CommandSet::parse(const std::vector<std::string>& args, std::ostream& out) {
    for (const std::string& a : args) {
        if (a == "--") break;
        if (a == "--help" || a == "-h" || (&a == &args.front() && a == "help")) {
            out << help();
            return nullptr;
        }
    }
    if (args.empty()) throw std::invalid_argument("missing command: " + commandNames() + " (see --help)");
    for (auto& [name, cl] : m_commands)
        if (name == args.front()) {
            std::ostringstream unused;  // no --help left to print
            cl.parse(std::vector<std::string>(args.begin() + 1, args.end()), unused);
            return &cl;
        }
    throw std::invalid_argument("unknown command '" + args.front() + "' (expected " + commandNames() + "; see --help)");
}

std::string CommandSet::help() const {
    std::string out = m_summary + (m_summary.empty() || m_summary.back() == '\n' ? "" : "\n") + "\nUsage:\n";
    for (const auto& [name, cl] : m_commands) {
        std::string usage = "  " + cl.usageLine();
        for (std::size_t p = usage.find('\n'); p != std::string::npos; p = usage.find('\n', p + 1)) usage.insert(p + 1, "  ");
        out += usage + "\n";
        if (!cl.summary().empty()) {
            std::string s = "      " + cl.summary();
            for (std::size_t p = s.find('\n'); p != std::string::npos && p + 1 < s.size(); p = s.find('\n', p + 1))
                s.insert(p + 1, "      ");
            out += s + (s.back() == '\n' ? "" : "\n");
        }
        std::string list = cl.optionList(4);
        list = list.substr(0, list.rfind("    -h, --help"));  // --help is listed once, below
        out += list + "\n";
    }
    out += "  -h, --help  print this help and exit\n";
    if (!m_notes.empty()) out += "\n" + m_notes + (m_notes.back() == '\n' ? "" : "\n");
    return out;
}

}  // namespace simp::io
