#pragma once
namespace simp::mapping {
/// Installs the map construction of CObjectMap::insertObservation (BuilderInserter.h) in libs/maps.
/// Runs automatically when the shared library is loaded; call it from a program that links the
/// library only for this.
void registerAllClasses();
}  // namespace simp::mapping
