#pragma once
namespace simp::maps {
/// Registers the library's classes with MRPT's RTTI. Runs automatically when the shared
/// library is loaded; call it from a program that links the library only for its classes.
void registerAllClasses();
}  // namespace simp::maps
