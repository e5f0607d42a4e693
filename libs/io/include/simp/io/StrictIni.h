#pragma once
/// \file StrictIni.h
/// The one strict .ini policy of every app (issue #14): an MRPT-style .ini read through this class
/// - must exist, be a regular file, and be text of `[section]`, `key = value` and comment lines
///   (';', '#', '//'), with at least one section and no key outside a section or twice in one;
/// - checks each value when it is read: a key read with a numeric default (MRPT's read_double,
///   read_float, read_int, read_bool, read_uint64_t format their default as a number) must hold a
///   whole finite number (an integer for an integer default, true/false also for 0/1);
/// - after the app loaded its options, checkUnknown() rejects every key that no option read in a
///   section the app read, and every section that the app neither read nor declared.
/// The known keys are thus the keys the option structs (the project's and MRPT's CLoadableOptions)
/// actually ask for: no second, hand-maintained list. Every message names the file, section and key.

#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace simp::io {

class StrictIni : public mrpt::config::CConfigFileBase {
   public:
    /// An empty configuration (no file given: every option keeps its default).
    StrictIni();
    /// Reads and checks the syntax of `path` ("" = no file: empty).
    /// \throw std::invalid_argument naming the file (and line).
    explicit StrictIni(const std::string& path);
    /// The same checks on `text`, `name` standing for the file in messages.
    StrictIni(const std::string& text, const std::string& name);
    StrictIni(const StrictIni&) = delete;
    StrictIni& operator=(const StrictIni&) = delete;

    const std::string& name() const { return m_name; }
    /// True when no file was given (or it holds no key).
    bool empty() const;

    /// Rejects keys not read in sections that were read, and sections neither read nor in
    /// `other_sections` (sections an app knows but does not read in this mode).
    /// \throw std::invalid_argument "FILE: [section] unknown key 'k' (known: ...)" / "unknown section".
    void checkUnknown(const std::vector<std::string>& other_sections = {}) const;

    /// Runs `load` (the app's option structs reading this .ini), names the file in any error it
    /// throws, then checkUnknown(other_sections). The usual way an app reads its .ini.
    void loadChecked(const std::function<void(const StrictIni&)>& load,
                     const std::vector<std::string>& other_sections = {}) const;

    /// Strict typed reads with a range (absent key: `def`), named "FILE: [section] key".
    double readNumber(const std::string& section, const std::string& key, double def, double lo, double hi) const;
    std::int64_t readInteger(const std::string& section, const std::string& key, std::int64_t def, std::int64_t lo,
                             std::int64_t hi) const;
    bool readBool(const std::string& section, const std::string& key, bool def) const;
    /// "FILE: [section] key" for messages of the callers' own checks.
    std::string where(const std::string& section, const std::string& key) const;

    void getAllSections(std::vector<std::string>& sections) const override;
    void getAllKeys(const std::string& section, std::vector<std::string>& keys) const override;
    void clear() override;

   protected:
    void writeString(const std::string& section, const std::string& name, const std::string& str) override;
    std::string readString(const std::string& section, const std::string& name, const std::string& defaultStr,
                           bool failIfNotFound = false) const override;

   private:
    std::string m_name = "(no .ini)";
    mrpt::config::CConfigFileMemory m_ini;
    /// lower-case section -> lower-case keys read (the .ini is case-insensitive, as MRPT's)
    mutable std::map<std::string, std::set<std::string>> m_read;
};

}  // namespace simp::io
