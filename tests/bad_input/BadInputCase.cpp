/// \file BadInputCase.cpp
#include "BadInputCase.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace fs = std::filesystem;

namespace simp_bad_input {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

/// Address-space limit of a case's process (not under ASan, which reserves terabytes of shadow):
/// a reader that believes a count in a file must fail to allocate, not take the machine.
constexpr rlim_t kAddressSpaceLimit = rlim_t(4) << 30;

std::vector<std::string> splitOn(const std::string& text, const std::string& sep) {
    std::vector<std::string> out;
    std::size_t pos = 0;
    while (true) {
        const auto next = text.find(sep, pos);
        out.push_back(text.substr(pos, next == std::string::npos ? std::string::npos : next - pos));
        if (next == std::string::npos) return out;
        pos = next + sep.size();
    }
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

/// \n \t \r \\ \0 \xHH
std::string unescape(const std::string& s) {
    std::string out;
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '\\' || i + 1 == s.size()) {
            out += s[i];
            continue;
        }
        const char c = s[++i];
        if (c == 'n') out += '\n';
        else if (c == 't') out += '\t';
        else if (c == 'r') out += '\r';
        else if (c == '0') out += '\0';
        else if (c == 'x' && i + 2 < s.size()) {
            out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else out += c;
    }
    return out;
}

std::string readAll(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    if (!f) throw std::runtime_error("cannot read '" + p.string() + "'");
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

void writeAll(const fs::path& p, const std::string& data) {
    if (p.has_parent_path()) fs::create_directories(p.parent_path());
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f << data;
    if (!f) throw std::runtime_error("cannot write '" + p.string() + "'");
}

}  // namespace

std::vector<Case> readCases(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error("cannot read " + path);
    std::vector<Case> out;
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        if (trim(line).empty() || trim(line)[0] == '#') continue;
        const auto cols = splitOn(line, "\t");
        if (cols.size() < 4 || cols.size() > 5)
            throw std::runtime_error(path + ":" + std::to_string(n) + ": expected 4 or 5 tab-separated columns");
        Case c;
        c.line = n;
        c.app = trim(cols[0]);
        c.exit_code = std::stoi(cols[1]);
        if (c.exit_code == 0) throw std::runtime_error(path + ":" + std::to_string(n) + ": expected exit code must be non-zero");
        c.fragment = cols[2];
        c.args = cols[3];
        if (cols.size() == 5) c.files = cols[4];
        out.push_back(c);
    }
    return out;
}

std::string substitute(const std::string& text, const Variables& vars) {
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '$') {
            out += text[i];
            continue;
        }
        std::size_t e = i + 1;
        while (e < text.size() && std::isupper(static_cast<unsigned char>(text[e]))) ++e;
        bool replaced = false;
        for (std::size_t len = e - i - 1; len > 0 && !replaced; --len) {
            const auto it = vars.find(text.substr(i + 1, len));
            if (it == vars.end()) continue;
            out += it->second;
            i += len;
            replaced = true;
        }
        if (!replaced) out += '$';
    }
    return out;
}

std::vector<std::string> splitArgs(const std::string& text) {
    std::vector<std::string> out;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        std::string tok;
        if (text[i] == '"') {
            ++i;
            while (i < text.size() && text[i] != '"') {
                if (text[i] == '\\' && i + 1 < text.size()) ++i;
                tok += text[i++];
            }
            ++i;
        } else {
            while (i < text.size() && text[i] != ' ') tok += text[i++];
        }
        out.push_back(tok);
    }
    return out;
}

void createFiles(const std::string& files, const fs::path& dir, const Variables& vars) {
    if (trim(files).empty()) return;
    for (const std::string& entry : splitOn(files, " || ")) {
        const auto eq = entry.find('=');
        if (eq == std::string::npos) throw std::runtime_error("file entry '" + entry + "' has no '='");
        const fs::path target = dir / trim(entry.substr(0, eq));
        const std::string spec = substitute(entry.substr(eq + 1), vars);
        if (spec == "@dir") {  // replaces a file of that name (e.g. of a copied world)
            if (fs::exists(target) && !fs::is_directory(target)) fs::remove(target);
            fs::create_directories(target);
        } else if (spec == "@empty") {
            writeAll(target, "");
        } else if (spec.rfind("@copy:", 0) == 0) {
            const fs::path src = spec.substr(6);
            if (target.has_parent_path()) fs::create_directories(target.parent_path());
            fs::copy(src, target, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
        } else if (spec.rfind("@head:", 0) == 0) {  // @head:SRC:N  first N bytes (N < 0: all but the last -N)
            const auto colon = spec.rfind(':');
            const std::string data = readAll(spec.substr(6, colon - 6));
            const long n = std::stol(spec.substr(colon + 1));
            const std::size_t keep = n >= 0 ? std::min<std::size_t>(data.size(), static_cast<std::size_t>(n))
                                            : data.size() - std::min<std::size_t>(data.size(), static_cast<std::size_t>(-n));
            writeAll(target, data.substr(0, keep));
        } else if (spec.rfind("@random:", 0) == 0) {  // @random:N:SEED
            const auto parts = splitOn(spec.substr(8), ":");
            std::mt19937 rng(static_cast<unsigned>(std::stoul(parts.at(1))));
            std::string data(std::stoul(parts.at(0)), '\0');
            for (auto& c : data) c = static_cast<char>(rng() & 0xff);
            writeAll(target, data);
        } else if (spec.rfind("@replace:", 0) == 0) {  // @replace:SRC|FROM|TO  every occurrence
            const auto parts = splitOn(spec.substr(9), "|");
            std::string data = readAll(parts.at(0));
            const std::string from = unescape(parts.at(1)), to = unescape(parts.at(2));
            std::size_t count = 0;
            for (std::size_t p = data.find(from); p != std::string::npos; p = data.find(from, p + to.size()), ++count)
                data.replace(p, from.size(), to);
            if (count == 0) throw std::runtime_error("@replace: '" + from + "' not found in " + parts.at(0));
            writeAll(target, data);
        } else if (spec.rfind("@flip:", 0) == 0) {  // @flip:SRC:OFFSET  one byte inverted
            const auto colon = spec.rfind(':');
            std::string data = readAll(spec.substr(6, colon - 6));
            const std::size_t at = std::stoul(spec.substr(colon + 1));
            if (at < data.size()) data[at] = static_cast<char>(~data[at]);
            writeAll(target, data);
        } else {
            writeAll(target, unescape(spec));
        }
    }
}

RunResult runProcess(const std::vector<std::string>& argv, const fs::path& log, double timeout_s) {
    std::vector<char*> cargv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    const std::string log_path = log.string(), cwd = log.parent_path().string();
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        // Only async-signal-safe calls between fork and exec.
        if (chdir(cwd.c_str()) != 0) _exit(126);
        const int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int null_fd = open("/dev/null", O_RDONLY);
        if (fd < 0 || null_fd < 0) _exit(126);
        dup2(null_fd, 0);
        dup2(fd, 1);
        dup2(fd, 2);
        if (!kSanitized) {
            const rlimit lim{kAddressSpaceLimit, kAddressSpaceLimit};
            setrlimit(RLIMIT_AS, &lim);
        }
        execv(cargv[0], cargv.data());
        _exit(127);
    }
    RunResult r;
    int status = 0;
    while (true) {
        const pid_t w = waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (r.seconds > timeout_s) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            r.timed_out = true;
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    r.exited = !r.timed_out && WIFEXITED(status);
    r.code = r.exited ? WEXITSTATUS(status) : (WIFSIGNALED(status) ? WTERMSIG(status) : -1);
    return r;
}

Outcome runCase(const Case& c, const fs::path& cases_root, Variables vars) {
    Outcome o;
    const fs::path dir = cases_root / ("line" + std::to_string(c.line));
    try {
        fs::remove_all(dir);
        fs::create_directories(dir);
        vars["T"] = dir.string();
        createFiles(c.files, dir, vars);
    } catch (const std::exception& e) {
        o.problem = std::string("cannot set the case up: ") + e.what();
        return o;
    }
    std::vector<std::string> argv{vars.at("BIN") + c.app};
    for (const auto& a : splitArgs(c.args)) argv.push_back(substitute(a, vars));
    const RunResult r = runProcess(argv, dir / "output.txt", 60);
    o.seconds = r.seconds;
    try {
        o.output = readAll(dir / "output.txt");
    } catch (const std::exception&) {
    }
    const std::string fragment = substitute(c.fragment, vars);
    std::ostringstream why;
    if (r.timed_out) why << "hang: killed after " << r.seconds << " s";
    else if (!r.exited) why << "crash: killed by signal " << r.code;
    else if (r.code == 0) why << "silent acceptance: exit code 0";
    else if (r.code != c.exit_code) why << "exit code " << r.code << ", expected " << c.exit_code;
    else if (o.output.find(fragment) == std::string::npos) why << "message fragment '" << fragment << "' missing";
    else if (o.output.find("Sanitizer") != std::string::npos || o.output.find("runtime error:") != std::string::npos)
        why << "sanitizer report";
    o.problem = why.str();
    o.ok = o.problem.empty();
    if (o.ok) fs::remove_all(dir);  // keep only the failures' folders
    return o;
}

}  // namespace simp_bad_input
