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
      s.points = read_points_file(path.string()).points;
    } catch (const std::exception& e) {
      fail(std::string("initial file: ") + e.what());
    }
  }
  if (s.points.empty()) fail("initial state has no points");
  s.start_d = d ? *d : (s.points.size() > 1 ? min_distance(s.points) : 0.0L);
}

}  // namespace

// The default growth protocol against n, chosen from the hit-rate table of docs/performance.md
// ("Billiards defaults against n (issue 9)", bench/hit_rates.sh): the fraction of runs from random
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
  if (s.growth && !(s.growth->rate >= 0 && std::isfinite(s.growth->rate)))
    fail("growth rate must be finite and >= 0");
  if (s.growth)
    for (const auto& st : s.growth->schedule) {
      if (!(st.gap > 0 && st.gap < 1)) fail("growth.schedule gap must be in (0, 1)");
      if (!(st.rate > 0 && std::isfinite(st.rate)))
        fail("growth.schedule rate must be finite and > 0");
    }
  if (s.shake && s.shake->per_disk == 0) fail("shake.per_disk must be at least 1");
  if (s.shake && !(s.shake->rattler_factor > 1 && std::isfinite(s.shake->rattler_factor)))
    fail("shake.rattler_factor must be finite and > 1");
  const auto& st = s.stop;
  if (!(st.relative_gap > 0 && st.relative_gap < 1)) fail("stop.relative_gap must be in (0, 1)");
  if (st.pressure != 0 && !(st.pressure > 2 && std::isfinite(st.pressure)))
    fail("stop.pressure must be > 2 (the reduced pressure of a gas is about 2)");
  if (!(st.max_seconds > 0)) fail("stop.max_seconds must be > 0");
  if (st.max_events == 0) fail("stop.max_events must be > 0");
  for (int i : s.pinned)
    if (i < 0 || i >= s.n) fail("pinned index " + std::to_string(i) + " out of range");
  // Random points start at diameter 0: without growth nothing would ever happen until max_seconds.
  if (s.points.empty() && !(s.growth && s.growth->rate > 0))
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
      check_keys(fx, {"growth", "thermostat", "shake", "pinned", "stop"}, "effects");
      if (const auto g = fx["growth"]) {
        s.growth = GrowthEffect{};
        if (!g.IsNull()) {
          check_keys(g, {"rate", "schedule"}, "effects.growth");
          if (g["rate"]) s.growth->rate = scalar<double>(g["rate"], "growth.rate");
          if (const auto sch = g["schedule"]) {
            if (!sch.IsSequence()) fail("growth.schedule must be a list of {pressure|gap, rate}");
            for (const auto& step : sch) {
              check_keys(step, {"pressure", "gap", "rate"}, "a growth.schedule step");
              if (!step["rate"] || (!step["pressure"] == !step["gap"]))
                fail("a growth.schedule step needs rate and one of pressure or gap");
              GrowthStep st;
              st.rate = scalar<double>(step["rate"], "growth.schedule rate");
              if (step["gap"]) {
                st.gap = scalar<double>(step["gap"], "growth.schedule gap");
              } else {
                const double p = scalar<double>(step["pressure"], "growth.schedule pressure");
                if (!(p > 2 && std::isfinite(p))) fail("growth.schedule pressure must be > 2");
                st.gap = 2 / p;  // free-volume estimate: 1 - D/D_jam = 2 / p
              }
              s.growth->schedule.push_back(st);
            }
            std::stable_sort(
                s.growth->schedule.begin(), s.growth->schedule.end(),
                [](const GrowthStep& a, const GrowthStep& b) { return a.gap > b.gap; });
          }
        }
      }
      if (const auto sh = fx["shake"]) {
        s.shake = ShakeEffect{};
        if (!sh.IsNull()) {
          check_keys(sh, {"per_disk", "rattler_factor"}, "effects.shake");
          if (sh["per_disk"]) s.shake->per_disk = count(sh["per_disk"], "shake.per_disk");
          if (sh["rattler_factor"])
            s.shake->rattler_factor = scalar<double>(sh["rattler_factor"], "shake.rattler_factor");
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
        check_keys(st, {"relative_gap", "pressure", "max_events", "max_collisions", "max_seconds"},
                   "effects.stop");
        if (st["relative_gap"])
          s.stop.relative_gap = scalar<double>(st["relative_gap"], "stop.relative_gap");
        if (st["pressure"]) s.stop.pressure = scalar<double>(st["pressure"], "stop.pressure");
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
  if (!s.pattern) validate_scene(s);  // else once the caller has built the points
  // Growth without velocity rescaling pumps kinetic energy into every collision: measured at
  // n = 10, 22, 40 and 60, such runs never reach their stop gap (15 M events in 2 s, stuck near
  // jamming) and end only at max_seconds. A YAML scene must name the thermostat with growth.
  if (s.growth && !s.thermostat && s.stop.max_collisions == 0)
    fail(
        "growth needs a thermostat (add `thermostat: {}`): without rescaling the kinetic energy "
        "grows at every collision and the run never reaches its stop gap");
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
