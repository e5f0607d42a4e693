#pragma once
/// \file YamlText.h
/// The text of a floor-plan YAML file (map_server's floorplan.yaml, the authors' Map.yaml), checked
/// before MRPT's YAML reader (libfyaml) sees it: libfyaml 0.7.12 (Debian 12) loops forever on a `%`
/// directive that holds a byte which is not UTF-8 (found by fuzz_floorplan, doc/fuzzing.md). A
/// map_server file is a few flat `key: value` lines, so the checks cost nothing to real files.

#include <cstddef>
#include <string>

namespace simp::world {

/// Largest floor-plan YAML file (bytes); real ones are under 1 KB.
constexpr std::size_t kMaxYamlBytes = 1 << 20;

/// The file's text when it is at most kMaxYamlBytes, valid UTF-8, free of control characters other
/// than tab, line feed and carriage return (YAML's printable set), and holds no `%` directive line.
/// \throw std::runtime_error "PATH: line L: ..." naming what is wrong.
std::string readYamlText(const std::string& path);

}  // namespace simp::world
