#pragma once
/// \file FuzzUtil.h
/// Shared by the libFuzzer targets: readers that take a path get the input through a file in a
/// per-process scratch folder; any std::exception is an accepted outcome (a clean rejection),
/// crashes, sanitizer reports, leaks, timeouts and out-of-memory are findings.

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

namespace simp_fuzz {

inline std::string scratchDir() {
    static const std::string dir = [] {
        const auto d = std::filesystem::temp_directory_path() / ("simp_fuzz_" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d.string();
    }();
    return dir;
}

inline std::string writeInput(const std::string& name, const std::uint8_t* data, std::size_t size) {
    const std::string path = scratchDir() + "/" + name;
    std::ofstream f(path, std::ios::binary | std::ios::trunc);
    f.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    return path;
}

/// Runs `f`; exceptions are the expected way to reject bad input, except running out of memory:
/// a reader must bound what it allocates by its input, so std::bad_alloc escapes (a finding).
template <typename F>
void expectNoCrash(F&& f) {
    try {
        f();
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::exception&) {
    }
}

}  // namespace simp_fuzz
