// Billiards scenes (docs/billiards.md): the container, the number of disks, the initial state and
// the effects a run needs. A scene is plain data; sim/billiards.hpp runs it.
//
// YAML form (every key but n optional):
//   container: triangle
//   n: 22
//   initial: random                 # or a file path, or {file: PATH, d: D}, or {points: [[x, y],
//   ...], d: D} effects:
//     growth:                       # disk diameter grows by `rate` per unit time (speeds ~1)
//       rate: 0.01
//       schedule:                   # optional: a new rate once the reduced pressure p exceeds
//         - {pressure: 1e4, rate: 0.005}  # a threshold (or the gap estimate 2/p falls below
//         - {gap: 1e-8, rate: 0.001}      # `gap`); checked every 20 n events
//     thermostat: {every: 220}      # rescale the kinetic energy every `every` collisions
//     shake: {per_disk: 200}        # then (or, without growth, only) shake at fixed size for
//                                   # per_disk * n collisions: each disk's excursion; rattlers
//     pinned: [0, 5]                # these disks never move
//     stop: {relative_gap: 1e-12, pressure: 1e9, max_events: 1e9, max_seconds: 600}
// `initial: {pattern: CLASS, k: K, p: P, variant: V}` names a built pattern; sim/ cannot build
// it (constructors/ sits above), so the scene keeps the request and the caller fills the points
// (app/: resolve_pattern) before validate_scene.
// Points of a file or of `points` follow the Packing convention: centres in the unit triangle with
// minimum distance d (the default d is the points' own minimum distance, so they may touch).
// Each effect's data is a field of Scene below; its policy (sim/effects/*.hpp, listed in
// sim/effect_list.hpp) reads, checks and describes it and hooks it into the engine.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

// A change of growth rate once the estimated relative gap to jamming (2 / reduced pressure)
// falls below `gap`.
struct GrowthStep {
  double gap = 0;
  double rate = 0;
};
struct GrowthEffect {
  double rate = 0.01;                // diameter per unit time, in the unit (container) triangle
  std::vector<GrowthStep> schedule;  // by decreasing gap
};
// Shaking at fixed size: an elastic run of per_disk * n collisions from the end state (fresh
// random unit velocities), counting each disk's collisions and path extent. A disk that collides
// more than rattler_factor times less often than the median disk is a rattler: a jammed disk
// bounces across the remaining gap, a rattler across its cage (for a cage c and a gap g, at
// cage-to-gap ratio c / g; a cage no wider than rattler_factor gaps is not told apart).
struct ShakeEffect {
  std::uint64_t per_disk = 200;
  double rattler_factor = 20;
};
// A built pattern as the start; filled in by the caller (see above).
struct PatternRequest {
  std::string class_name;
  long long k = 0;
  std::optional<long long> p;
  std::string variant;
};
struct ThermostatEffect {
  std::uint64_t every = 0;  // collisions between rescalings; 0: 10 n
};
struct StopRules {
  double relative_gap = 1e-12;  // estimated 1 - diam / diam_jammed (growth runs only)
  double pressure = 0;  // also stop once the reduced pressure exceeds this (0: no such rule;
                        // the estimate is the same: relative gap = 2 / pressure)
  std::uint64_t max_events = 1'000'000'000;
  std::uint64_t max_collisions = 0;  // 0: no limit
  double max_seconds = 600;
};

struct Scene {
  int n = 0;
  // Empty: random positions (diameter 0). Otherwise n points in the Packing convention with start
  // distance `start_d` (the disks then have diameter d / (1 + sqrt3 d) in the container).
  std::vector<Vec2L> points;
  long double start_d = 0;
  // Optional initial velocities (container units); empty: random unit speeds.
  std::vector<Vec2> velocities;
  std::optional<PatternRequest> pattern;  // points still to be built (see above)
  std::optional<GrowthEffect> growth;
  std::optional<ThermostatEffect> thermostat;
  std::optional<ShakeEffect> shake;
  std::vector<int> pinned;
  StopRules stop;
};

// Built-in scene: n random disks, thermostat every 10 n collisions, stop at a gap of 1e-12, growth
// at rate 0.01, slowed to default_window_rate(n) while the estimated gap is in [0.01, 0.1) when
// n > 40 (the hit-rate table of docs/performance.md: at n = 254 constant 0.01 reached
// t254a in 0 of 64 runs, this default in 19 of 32). For n <= 40 it is constant 0.01.
Scene default_scene(int n);
inline constexpr double kDefaultGrowthRate = 0.01;
inline constexpr int kDefaultFastUpTo = 40;               // constant kDefaultGrowthRate up to here
inline constexpr double kDefaultWindow[2] = {0.1, 0.01};  // slow while gap in [0.01, 0.1)
inline constexpr double kDefaultSlowestRate = 3e-5;
// The default's rate inside the window: (2.5 / n)^2 within [3e-5, 0.01] for n > 40, else 0.01.
double default_window_rate(int n);

// Parse and validate; relative file paths are taken from `base_dir`. Any problem throws a
// one-line std::runtime_error.
Scene parse_scene(const std::string& yaml_text, const std::string& base_dir = ".");
Scene load_scene(const std::string& path);

// Checks n, indices, stop rules, the start points (inside the triangle, no pair closer than
// start_d beyond 1e-12 relative). Throws a one-line std::runtime_error.
void validate_scene(const Scene& scene);

// One line per effect the scene uses, as each effect describes itself (for reports).
std::vector<std::string> describe_effects(const Scene& scene);

// A Packing as a scene start: its points at its own d. Without `growth_rate` the scene names no
// effect (an elastic gas that never jams); with it, growth at that rate plus the thermostat.
Scene scene_from_packing(const Packing& packing, std::optional<double> growth_rate = std::nullopt);

}  // namespace tripack
