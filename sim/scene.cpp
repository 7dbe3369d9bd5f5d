#include "sim/scene.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "core/neighbours.hpp"
#include "formats/formats.hpp"
#include "sim/effect_list.hpp"
#include "sim/scene_yaml.hpp"

namespace tripack {
namespace {

using sim_detail::check_keys;
using sim_detail::count;
using sim_detail::EffectList;
using sim_detail::scalar;
using sim_detail::SceneEffects;
[[noreturn]] void fail(const std::string& what) {
  sim_detail::scene_error(what);
}

// The effects' parts of a scene, each handled by its policy (sim/effect_list.hpp).
template <class... Policies>
void parse_effects(EffectList<Policies...>, const YAML::Node& node, Scene& s) {
  check_keys(node, {Policies::kKey..., "stop"}, "effects");
  const auto parse = [&]<class P>() {
    if (const auto fx = node[P::kKey]) P::parse(fx, s);
  };
  (parse.template operator()<Policies>(), ...);
}
template <class... Policies>
void validate_effects(EffectList<Policies...>, const Scene& s) {
  (Policies::validate(s), ...);
}
template <class... Policies>
void check_effects_after_parse(EffectList<Policies...>, const Scene& s) {
  const auto check = [&]<class P>() {
    if constexpr (requires { P::after_parse(s); }) P::after_parse(s);
  };
  (check.template operator()<Policies>(), ...);
}
template <class... Policies>
bool grows(EffectList<Policies...>, const Scene& s) {
  return (false || ... || (Policies::kGrows && Policies::active(s)));
}
template <class... Policies>
std::vector<std::string> describe(EffectList<Policies...>, const Scene& s) {
  std::vector<std::string> lines;
  const auto add = [&]<class P>() {
    if (P::active(s)) lines.push_back(P::describe(s));
  };
  (add.template operator()<Policies>(), ...);
  return lines;
}

void parse_stop(const YAML::Node& st, StopRules& stop) {
  check_keys(st, {"relative_gap", "pressure", "max_events", "max_collisions", "max_seconds"},
             "effects.stop");
  if (st["relative_gap"])
    stop.relative_gap = scalar<double>(st["relative_gap"], "stop.relative_gap");
  if (st["pressure"]) stop.pressure = scalar<double>(st["pressure"], "stop.pressure");
  if (st["max_events"]) stop.max_events = count(st["max_events"], "stop.max_events");
  if (st["max_collisions"])
    stop.max_collisions = count(st["max_collisions"], "stop.max_collisions");
  if (st["max_seconds"]) stop.max_seconds = scalar<double>(st["max_seconds"], "stop.max_seconds");
}

// Smallest distance among points in the unit triangle: no packing of n >= 2 beats Oler's bound
// d <= 1 / t(n) (and no two points are farther apart than 1), so pairs beyond it are not looked at.
long double min_distance(const std::vector<Vec2L>& p) {
  const long double t = oler_bound(static_cast<long long>(p.size()));
  const long double reach = (t > 1 ? 1 / t : 1.0L) * (1 + 1e-9L) + 1e-30L;
  long double best = INFINITY;
  for_each_pair_within(p, reach, [&](int, int, long double r) { best = std::min(best, r); });
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
    if (node["pattern"]) {  // a built pattern: resolved by the caller
      check_keys(node, {"pattern", "k", "p", "variant"}, "initial");
      PatternRequest req;
      req.class_name = node["pattern"].as<std::string>();
      if (!node["k"]) fail("initial.pattern needs k");
      req.k = scalar<long long>(node["k"], "initial.k");
      if (node["p"]) req.p = scalar<long long>(node["p"], "initial.p");
      if (node["variant"]) req.variant = node["variant"].as<std::string>();
      s.pattern = req;
      return;
    }
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
        // (.nan and .inf are valid YAML numbers; found by fuzzing, they reached the
        // neighbour grid's integer cast.)
        if (!std::isfinite(s.points.back().x) || !std::isfinite(s.points.back().y))
          fail("initial.points must be finite numbers");
      }
    } else if (file.empty()) {
      fail("initial needs file or points");
    }
    if (node["d"]) d = scalar<long double>(node["d"], "initial.d");
    if (d && !std::isfinite(*d)) fail("initial.d must be a finite number");
  }
  if (!file.empty()) {
    std::filesystem::path path(file);
    if (path.is_relative()) path = std::filesystem::path(base_dir) / path;
    try {
      s.points = read_packing_file(path.string()).points;
    } catch (const std::exception& e) {
      fail(std::string("initial file: ") + e.what());
    }
  }
  if (s.points.empty()) fail("initial state has no points");
  s.start_d = d ? *d : (s.points.size() > 1 ? min_distance(s.points) : 0.0L);
}

}  // namespace

// The default growth protocol against n, chosen from the hit-rate table of docs/performance.md
// ("Billiards defaults against n", bench/hit_rates.sh): the fraction of runs from random
// starts that jam in the best known packing, and the CPU time per hit. Constant 0.01 is good at
// small n (t22a in 27% of runs, 0.04 s per hit) but fails at large n (t254a in 0 of 64 runs;
// slower constant rates hit it at 6.5 s per hit). What matters is the rate while the estimated
// gap 2/p is between 0.1 and 0.01 (where the disks order): slow there alone, fast before and after
// (each decade of gap below costs about as many events: constant 1e-4 costs 13x the events of the
// 1e-4 window at n = 254 for the same hit fraction).
// Best rates in that window, per hit: 1e-3 at n = 79 (t79a in 66% of runs; 1.8e-3: 38%),
// 1e-3..3e-4 at 121, 1e-4 at 254 (t254a in 44% of runs, 2.1 s per hit). The window rate
// (2.5 / n)^2 runs through those (1.0e-3, 4.3e-4, 9.7e-5; as measured: t79a in 62% of runs,
// t254a in 59%, 1.5 s per hit, against 5% and 0 for constant 0.01). Up to n = 40 the default is
// exactly the old constant 0.01, no window: explorers run many small n with many runs each, and the
// window would double the cost of a run there (at n = 22 it raises the hits from 27% to 53% at
// about the same cost per hit). The rate is not taken below 3e-5, the slowest rate measured
// (from n = 457 on).
double default_window_rate(int n) {
  if (n <= kDefaultFastUpTo) return kDefaultGrowthRate;
  const double r = std::pow(2.5 / n, 2);
  return std::clamp(r, kDefaultSlowestRate, kDefaultGrowthRate);
}

Scene default_scene(int n) {
  Scene s;
  s.n = n;
  s.growth = GrowthEffect{};
  s.growth->rate = kDefaultGrowthRate;
  if (n > kDefaultFastUpTo)
    s.growth->schedule = {{kDefaultWindow[0], default_window_rate(n)},
                          {kDefaultWindow[1], kDefaultGrowthRate}};
  s.thermostat = ThermostatEffect{};
  return s;
}

Scene scene_from_packing(const Packing& packing, std::optional<double> growth_rate) {
  Scene s;
  s.n = static_cast<int>(packing.size());
  s.points = packing.points;
  s.start_d = packing.d;
  if (growth_rate) {
    s.growth = GrowthEffect{*growth_rate, {}};
    s.thermostat = ThermostatEffect{};
  }
  return s;
}

void validate_scene(const Scene& s) {
  if (s.pattern && s.points.empty())
    fail("initial pattern " + s.pattern->class_name + " has not been built");
  if (s.n < 1) fail("n must be at least 1 (got " + std::to_string(s.n) + ")");
  if (!s.points.empty() && static_cast<int>(s.points.size()) != s.n)
    fail("n = " + std::to_string(s.n) + " but the initial state has " +
         std::to_string(s.points.size()) + " points");
  if (!s.velocities.empty() && static_cast<int>(s.velocities.size()) != s.n)
    fail("velocities must have n entries");
  validate_effects(SceneEffects{}, s);
  const auto& st = s.stop;
  if (!(st.relative_gap > 0 && st.relative_gap < 1)) fail("stop.relative_gap must be in (0, 1)");
  if (st.pressure != 0 && !(st.pressure > 2 && std::isfinite(st.pressure)))
    fail("stop.pressure must be > 2 (the reduced pressure of a gas is about 2)");
  if (!(st.max_seconds > 0)) fail("stop.max_seconds must be > 0");
  if (st.max_events == 0) fail("stop.max_events must be > 0");
  // Random points start at diameter 0: without growth nothing would ever happen until max_seconds.
  if (s.points.empty() && !grows(SceneEffects{}, s))
    fail("a random start has disks of diameter 0: it needs growth with a rate > 0");
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
    else if (!s.pattern)
      fail("n is missing");
    if (const auto fx = root["effects"]; fx && !fx.IsNull()) {
      parse_effects(SceneEffects{}, fx, s);
      if (const auto st = fx["stop"]) parse_stop(st, s.stop);
    }
  } catch (const YAML::Exception& e) {
    fail("bad scene at line " + std::to_string(e.mark.line + 1));
  }
  if (!s.pattern) validate_scene(s);  // else once the caller has built the points
  check_effects_after_parse(SceneEffects{}, s);
  return s;
}

std::vector<std::string> describe_effects(const Scene& scene) {
  return describe(SceneEffects{}, scene);
}

Scene load_scene(const std::string& path) {
  std::ifstream in(path);
  if (!in) fail("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return parse_scene(ss.str(), std::filesystem::path(path).parent_path().string());
}

}  // namespace tripack
