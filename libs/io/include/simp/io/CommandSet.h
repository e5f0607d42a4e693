#pragma once
/// \file CommandSet.h
/// A program with sub-commands, `PROGRAM COMMAND [options]` (simp-sim world|sequence, simp-eval
/// traj|map|...): one CommandLine per command, one help text for all.

#include <simp/io/CommandLine.h>

#include <ostream>
#include <string>
#include <vector>

namespace simp::io {

class CommandSet {
   public:
    /// `summary`: printed first in the help.
    CommandSet(std::string program, std::string summary);

    /// Declares a command; declare its options on the returned CommandLine (named "PROGRAM COMMAND").
    CommandLine& add(const std::string& command, const std::string& summary);
    /// Text printed at the end of the help.
    CommandSet& notes(const std::string& text);

    /// args[0] is the command. Returns the parsed command, or nullptr when help was asked (`PROGRAM
    /// --help`, `PROGRAM help`, or --help/-h anywhere after the command): then help() went to `out`.
    /// \throw std::invalid_argument for a missing or unknown command, and CommandLine::parse's errors.
    const CommandLine* parse(const std::vector<std::string>& args, std::ostream& out);
    /// argv[0] is the program name (skipped).
    const CommandLine* parse(int argc, const char* const* argv, std::ostream& out);

    /// Every command: its usage line, summary and options.
    std::string help() const;
    /// "world, sequence"
    std::string commandNames() const;

   private:
    std::string m_program, m_summary, m_notes;
    std::vector<std::pair<std::string, CommandLine>> m_commands;
};

}  // namespace simp::io
