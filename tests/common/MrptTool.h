#pragma once
/// \file MrptTool.h
/// Running one of MRPT's own programs (rawlog-edit, pf-localization: Debian mrpt-apps, built without
/// sanitizers) on the project's plugins from a test. In an ASan build such a program aborts with "ASan
/// runtime does not come first in initial library list" as soon as it loads an instrumented plugin
/// (doc/sanitizers.md), so ASan's runtime, the one this test executable runs with, is preloaded ahead of
/// everything else, and leak checking is off for MRPT's program (its own allocations, reported by LSan
/// at its exit); a memory error in the plugin still aborts it. In a normal build nothing is added.
#include "common/UnderAsan.h"

#include <string>

#if SIMP_UNDER_ASAN
#include <dlfcn.h>
extern "C" void __asan_init();
#endif

namespace simp_test {

/// The ASan runtime library this process runs with (e.g. /usr/lib/x86_64-linux-gnu/libasan.so.8);
/// empty outside an ASan build.
inline std::string asanRuntime() {
#if SIMP_UNDER_ASAN
    Dl_info info{};
    if (dladdr(reinterpret_cast<void*>(&__asan_init), &info) != 0 && info.dli_fname != nullptr) return info.dli_fname;
#endif
    return {};
}

/// Environment assignments to write before an MRPT program's name in a shell command:
/// `mrptToolEnv() + "rawlog-edit --plugins ..."`. `preload`: ':'-separated libraries to LD_PRELOAD
/// besides ASan's runtime (may be empty). Empty in a normal build without `preload`.
inline std::string mrptToolEnv(const std::string& preload = "") {
    const std::string asan = asanRuntime();
    std::string list = asan;
    if (!preload.empty()) list += (list.empty() ? "" : ":") + preload;
    std::string env;
    if (!list.empty()) env += "LD_PRELOAD='" + list + "' ";
    if (!asan.empty()) env += "ASAN_OPTIONS=detect_leaks=0:abort_on_error=1:halt_on_error=1 ";
    return env;
}

}  // namespace simp_test
