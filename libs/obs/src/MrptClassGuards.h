#pragma once
/// \file MrptClassGuards.h (private to libs/obs)
/// Checks on the objects of MRPT classes a rawlog reader lets MRPT deserialize, made from the bytes
/// that follow the object's header *before* MRPT's serializeFrom runs: MRPT 2.5's readers resize
/// strings, vectors and matrices to the sizes in the file, so each size is compared with the bytes
/// left; versions and layouts the checks do not know are rejected (nothing unchecked reaches MRPT).

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mrpt::rtti {
struct TRuntimeClassId;
}

namespace simp::obs::detail {

/// The bytes after an object's name, not consumed: `peek(n)` returns at least n of them (fewer at the
/// end of the data); `left` is how many the data still holds from there on.
struct Ahead {
    std::function<const std::vector<std::uint8_t>&(std::size_t)> peek;
    std::uint64_t left = 0;
    std::size_t version_bytes = 1;  ///< 1 (MRPT >= 0.5.5), 4 (older format: i32 version, no end flag)
};

std::uint32_t u32At(const std::vector<std::uint8_t>& b, std::size_t at);

/// The classes the project's rawlog readers let MRPT create, at any depth (see rawlogClasses()).
/// Each is checked by checkObject() where MRPT would allocate from the file.
const std::vector<const mrpt::rtti::TRuntimeClassId*>& guardedRawlogClasses();

/// The short names of the observation, action and container classes among them, for messages.
std::string rawlogClassesText();

/// Checks an object of class `id` (one of guardedRawlogClasses(), not a container: the archive counts
/// those itself) whose header MRPT has just read. Returns the Thrun motion-model particles MRPT will
/// draw for it (robot movements), else 0. \throw std::invalid_argument starting with `where`.
std::uint64_t checkObject(const mrpt::rtti::TRuntimeClassId* id, const Ahead& a, const std::string& where);

}  // namespace simp::obs::detail
