#pragma once
/// \file ErrorOf.h
/// The message of the exception a call throws, for tests that check what an error names.

#include <exception>
#include <string>

namespace simp_test {

/// what() of the std::exception `f` throws; "" when it throws nothing.
template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace simp_test
