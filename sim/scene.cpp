#include "sim/scene.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/io.hpp"
#include "core/neighbours.hpp"

namespace tripack {
namespace {

[[noreturn]] void fail(const std::string& what) {
  throw std::runtime_error("scene: " + what);
}

void check_keys(const YAML::Node& node, const std::set<std::string>& allowed,
                const std::string& where) {
  if (!node.IsMap()) fail(where + " must be a map");
  for (const auto& kv : node) {
    const auto key = kv.first.as<std::string>();
    if (!allowed.count(key)) fail("unknown key '" + key + "' in " + where);
  }
}

template <class T>
T scalar(const YAML::Node& node, const std::string& name) {
  if (!node.IsScalar()) fail(name + " must be a number");
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    fail("bad value '" + node.Scalar() + "' for " + name);
  }
}

std::uint64_t count(const YAML::Node& node, const std::string& name) {
  const double v = scalar<double>(node, name);  // accepts 1e9
  if (!(v >= 0) || v > 1.8e19 || v != std::floor(v)) fail(name + " must be a non-negative integer");
  return static_cast<std::uint64_t>(v);
}

long double min_distance(const std::vector<Vec2L>& p) {
  long double best = INFINITY;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) best = std::min(best, norm(p[i] - p[j]));
  return best;
}

void read_initial(const YAML::Node& node, const std::string& base_dir, Scene& s) {
  std::string file;
  std::optional<long double> d;
  if (node.IsScalar()) {
    const auto v = node.as<std::string>();
    if (v == "random") return;
    file = v;
  } else {
    check_keys(node, {"file", "points", "d"}, "initial");
    if (node["file"] && node["points"]) fail("initial: give either file or points");
    if (node["file"]) file = node["file"].as<std::string>();
    if (node["points"]) {
      const auto& pts = node["points"];
      if (!pts.IsSequence()) fail("initial.points must be a list of [x, y]");
      for (const auto& p : pts) {
        if (!p.IsSequence() || p.size() != 2) fail("initial.points must be a list of [x, y]");
        s.points.push_back({scalar<long double>(p[0], "a point coordinate"),
                            scalar<long double>(p[1], "a point coordinate")});
      }
    } else if (file.empty()) {
      fail("initial needs file or points");
    }
    if (node["d"]) d = scalar<long double>(node["d"], "initial.d");
  }
  if (!file.empty()) {
    std::filesystem::path path(file);
    if (path.is_relative()) path = std::filesystem::path(base_dir) / path;
    try {
      s.points = read_points_file(path.string());
    } catch (const std::exception& e) {
      fail(std::string("initial file: ") + e.what());
    }
  }
  if (s.points.empty()) fail("initial state has no points");
  s.start_d = d ? *d : (s.points.size() > 1 ? min_distance(s.points) : 0.0L);
}

}  // namespace

Scene default_scene(int n) {
  Scene s;
  s.n = n;
  s.growth = GrowthEffect{};
  s.thermostat = ThermostatEffect{};
  return s;
}

Scene scene_from_packing(const Packing& packing, std::optional<double> growth_rate) {
  Scene s;
  s.n = static_cast<int>(packing.size());
  s.points = packing.points;
  s.start_d = packing.d;
  if (growth_rate) {
    s.growth = GrowthEffect{*growth_rate};
    s.thermostat = ThermostatEffect{};
  }
  return s;
}

void validate_scene(const Scene& s) {
  if (s.n < 1) fail("n must be at least 1 (got " + std::to_string(s.n) + ")");
  if (!s.points.empty() && static_cast<int>(s.points.size()) != s.n)
    fail("n = " + std::to_string(s.n) + " but the initial state has " +
         std::to_string(s.points.size()) + " points");
  if (!s.velocities.empty() && static_cast<int>(s.velocities.size()) != s.n)
    fail("velocities must have n entries");
  if (s.growth && !(s.growth->rate >= 0 && std::isfinite(s.growth->rate)))
    fail("growth rate must be finite and >= 0");
  const auto& st = s.stop;
  if (!(st.relative_gap > 0 && st.relative_gap < 1)) fail("stop.relative_gap must be in (0, 1)");
  if (!(st.max_seconds > 0)) fail("stop.max_seconds must be > 0");
  if (st.max_events == 0) fail("stop.max_events must be > 0");
  for (int i : s.pinned)
    if (i < 0 || i >= s.n) fail("pinned index " + std::to_string(i) + " out of range");
  if (s.points.empty()) return;
  if (!(s.start_d >= 0 && std::isfinite(s.start_d))) fail("initial d must be finite and >= 0");
  const long double tol = 1e-12L;
  for (int i = 0; i < s.n; ++i) {
    const auto& p = s.points[static_cast<std::size_t>(i)];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) fail("initial point is not finite");
    for (Side side : kSides)
      if (wall_distance(p, side, 1.0L) < -tol)
        fail("initial disk " + std::to_string(i) + " lies outside the triangle");
  }
  // Overlaps on a cell grid (O(n)); the first pair in index order is named.
  int bad_i = -1, bad_j = -1;
  long double bad_r = 0;
  for_each_pair_within(s.points, s.start_d * (1 - tol), [&](int i, int j, long double r) {
    if (r >= s.start_d * (1 - tol)) return;
    if (bad_i < 0 || std::make_pair(i, j) < std::make_pair(bad_i, bad_j))
      bad_i = i, bad_j = j, bad_r = r;
  });
  if (bad_i >= 0)
    fail("initial disks " + std::to_string(bad_i) + " and " + std::to_string(bad_j) +
         " overlap (distance " + std::to_string(static_cast<double>(bad_r)) + " < d " +
         std::to_string(static_cast<double>(s.start_d)) + ")");
}

Scene parse_scene(const std::string& text, const std::string& base_dir) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    fail("malformed YAML at line " + std::to_string(e.mark.line + 1));
  }
  if (!root.IsMap()) fail("the scene must be a YAML map");
  Scene s;
  try {
    check_keys(root, {"container", "n", "initial", "effects"}, "the scene");
    if (root["container"] && root["container"].as<std::string>() != "triangle")
      fail("unknown container '" + root["container"].as<std::string>() + "' (only triangle)");
    if (root["initial"]) read_initial(root["initial"], base_dir, s);
    if (root["n"])
      s.n = scalar<int>(root["n"], "n");
    else if (!s.points.empty())
      s.n = static_cast<int>(s.points.size());
    else
      fail("n is missing");
    if (const auto fx = root["effects"]; fx && !fx.IsNull()) {
      check_keys(fx, {"growth", "thermostat", "pinned", "stop"}, "effects");
      if (const auto g = fx["growth"]) {
        s.growth = GrowthEffect{};
        if (!g.IsNull()) {
          check_keys(g, {"rate"}, "effects.growth");
          if (g["rate"]) s.growth->rate = scalar<double>(g["rate"], "growth.rate");
        }
      }
      if (const auto t = fx["thermostat"]) {
        s.thermostat = ThermostatEffect{};
        if (!t.IsNull()) {
          check_keys(t, {"every"}, "effects.thermostat");
          if (t["every"]) s.thermostat->every = count(t["every"], "thermostat.every");
        }
      }
      if (const auto p = fx["pinned"]) {
        if (!p.IsSequence()) fail("effects.pinned must be a list of disk indices");
        for (const auto& i : p) s.pinned.push_back(scalar<int>(i, "a pinned index"));
      }
      if (const auto st = fx["stop"]) {
        check_keys(st, {"relative_gap", "max_events", "max_collisions", "max_seconds"},
                   "effects.stop");
        if (st["relative_gap"])
          s.stop.relative_gap = scalar<double>(st["relative_gap"], "stop.relative_gap");
        if (st["max_events"]) s.stop.max_events = count(st["max_events"], "stop.max_events");
        if (st["max_collisions"])
          s.stop.max_collisions = count(st["max_collisions"], "stop.max_collisions");
        if (st["max_seconds"])
          s.stop.max_seconds = scalar<double>(st["max_seconds"], "stop.max_seconds");
      }
    }
  } catch (const YAML::Exception& e) {
    fail("bad scene at line " + std::to_string(e.mark.line + 1));
  }
  validate_scene(s);
  return s;
}

Scene load_scene(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(ss.str(), std::filesystem::path(path).parent_path().string());
}

}  // namespace tripack
