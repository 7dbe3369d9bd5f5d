// Reading scene YAML with one-line errors ("scene: ..."): shared by sim/scene.cpp and the
// effects' parse functions (sim/effects/*.hpp), so every effect reports bad input alike.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>

namespace tripack::sim_detail {

[[noreturn]] inline void scene_error(const std::string& what) {
  throw std::runtime_error("scene: " + what);
}

// `node` is a map whose keys are all in `allowed`.
inline void check_keys(const YAML::Node& node, const std::set<std::string>& allowed,
                       const std::string& where) {
  if (!node.IsMap()) scene_error(where + " must be a map");
  for (const auto& kv : node) {
    const auto key = kv.first.as<std::string>();
    if (!allowed.count(key)) scene_error("unknown key '" + key + "' in " + where);
  }
}

// An effect's options: a bare `name:` (null) keeps every default, else a map of `allowed` keys.
// True when there are options to read.
inline bool has_options(const YAML::Node& node, const std::set<std::string>& allowed,
                        const std::string& where) {
  if (node.IsNull()) return false;
  check_keys(node, allowed, where);
  return true;
}

template <class T>
T scalar(const YAML::Node& node, const std::string& name) {
  if (!node.IsScalar()) scene_error(name + " must be a number");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    scene_error("bad value '" + node.Scalar() + "' for " + name);
  }
}

// A non-negative integer, also written as 1e9.
inline std::uint64_t count(const YAML::Node& node, const std::string& name) {
  const double v = scalar<double>(node, name);
  if (!(v >= 0) || v > 1.8e19 || v != std::floor(v))
    scene_error(name + " must be a non-negative integer");
  return static_cast<std::uint64_t>(v);
}

}  // namespace tripack::sim_detail
