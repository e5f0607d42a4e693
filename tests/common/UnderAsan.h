#pragma once
/// \file UnderAsan.h
/// SIMP_UNDER_ASAN is 1 in an AddressSanitizer build by GCC (__SANITIZE_ADDRESS__) or clang
/// (__has_feature; the libFuzzer build, -DSIMP_FUZZ=ON): ASan's quarantine keeps freed memory
/// resident, so tests that bound peak RSS skip those checks there.
#if defined(__SANITIZE_ADDRESS__)
#define SIMP_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SIMP_UNDER_ASAN 1
#endif
#endif
#ifndef SIMP_UNDER_ASAN
#define SIMP_UNDER_ASAN 0
#endif
