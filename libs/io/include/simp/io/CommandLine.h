#pragma once
/// \file CommandLine.h
/// The one command-line parser of the apps and rawlog tools. Each option is declared once (name, value
/// or flag, required or not, unit, help text); parse() checks a command line against the declarations
/// and help() documents them, so the two cannot disagree. Programs with sub-commands (simp-sim world,
/// simp-eval traj, ...) hold one CommandLine per command in a CommandSet.
///
/// Syntax: `--name VALUE` or `--name=VALUE` (the token after `--name` is its value even when it starts
/// with '-', e.g. `--kidnap-at -1`), `--flag`, positional arguments where declared, `--` ends the options.
/// `--help` or `-h` anywhere prints help() and nothing is checked; `--version` where a version is set.
/// Errors (std::invalid_argument) say what is wrong and with which option, e.g.
/// "unknown option '--foo' (see --help)", "option --out needs a value (see --help)",
/// "option --seed given twice (see --help)", "option --particles: 'abc' is not an integer".

#include <cstdint>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace simp::io {

/// One declared option (or positional argument).
struct CommandOption {
    std::string name;        ///< without "--", e.g. "particles"; for a positional, its VALUE_NAME
    std::string value_name;  ///< "N", "FILE", ... shown in the help; empty: a flag (takes no value)
    std::string help;        ///< help text; '\n' starts an indented continuation line
    bool required = false;
    std::string alias;       ///< a second name (without "--"), e.g. "world-in"; empty: none
    std::string unit;        ///< named in value errors, "option --duration (s): ..."; empty: none
};

class CommandLine {
   public:
    /// `name`: the program, or "program command" for a command of a CommandSet (shown in the usage line).
    /// `summary`: what the program does, printed under the usage line.
    explicit CommandLine(std::string name, std::string summary = {});

    /// @name Declarations (each returns *this to chain)
    /// @{
    CommandLine& required(const std::string& name, const std::string& value_name, const std::string& help);
    CommandLine& option(const std::string& name, const std::string& value_name, const std::string& help);
    CommandLine& flag(const std::string& name, const std::string& help);
    /// A positional argument (in order of declaration; required ones first).
    CommandLine& positional(const std::string& value_name, const std::string& help, bool required);
    /// A second name of the last declared option (e.g. "world-in" for "world").
    CommandLine& alias(const std::string& other_name);
    /// The unit of the last declared option, named in its value errors: "option --duration (s): ...".
    CommandLine& unit(const std::string& unit);
    /// Accepts `--version`, which prints "NAME VERSION".
    CommandLine& version(const std::string& text);
    /// Text printed after the option list (constraints between options, references).
    CommandLine& notes(const std::string& text);
    /// @}

    /// Checks `args` (without the program name) and keeps the values. Returns false when --help/-h
    /// (or --version) was given: the text went to `out`, nothing was checked.
    /// \throw std::invalid_argument: unknown option, missing value, value given to a flag, option given
    /// twice, missing required option or an empty value for it, unexpected or missing positional argument.
    bool parse(const std::vector<std::string>& args, std::ostream& out);
    /// argv[0] is the program name (skipped).
    bool parse(int argc, const char* const* argv, std::ostream& out);

    /// @name Values after parse()
    /// @{
    bool has(const std::string& name) const;
    /// The value ("" when absent or a flag).
    const std::string& value(const std::string& name) const;
    /// The value as a finite number in [lo, hi]; nullopt when absent.
    /// \throw std::invalid_argument "option --NAME: 'x' is not a finite number" / "... must be in [lo, hi]".
    std::optional<double> number(const std::string& name, double lo, double hi) const;
    /// The value as a decimal integer in [lo, hi]; nullopt when absent.
    /// \throw std::invalid_argument "option --NAME: 'x' is not an integer" / "... must be in [lo, hi]".
    std::optional<std::int64_t> integer(const std::string& name, std::int64_t lo, std::int64_t hi) const;
    const std::vector<std::string>& positionals() const { return m_positionals; }
    /// @}

    /// "simp-x --a A [--b B] [--flag] ARG [ARG2]", wrapped at about 100 columns.
    std::string usageLine() const;
    /// The option list, one entry per declared option and --help, indented by `indent` spaces.
    std::string optionList(std::size_t indent) const;
    /// The whole --help text: usage line, summary, option list, notes.
    std::string help() const;

    const std::string& name() const { return m_name; }
    const std::string& summary() const { return m_summary; }
    const std::vector<CommandOption>& options() const { return m_options; }

    /// Set by CommandSet: "for command 'world'" is added to unknown-option errors.
    void setCommand(const std::string& command) { m_command = command; }

   private:
    const CommandOption* find(const std::string& name) const;
    const CommandOption& declared(const std::string& name) const;  ///< \throw std::logic_error if not declared
    std::string what(const CommandOption& o) const;                 ///< "option --name (unit)"
    CommandOption& add(CommandOption o);

    std::string m_name, m_summary, m_notes, m_version, m_command;
    std::vector<CommandOption> m_options, m_positional_specs;
    std::map<std::string, std::string> m_values;  ///< canonical name -> value ("" for flags)
    std::vector<std::string> m_positionals;
};

}  // namespace simp::io
