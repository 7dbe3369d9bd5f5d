// Lubachevsky–Stillinger billiards of growing disks in the equilateral triangle
// (docs/billiards.md).
//
// Event-driven: disk–disk and disk–wall collisions of disks whose diameter grows as
// diam(t) = diam0 + rate t, predicted exactly (cancellation-free quadratic roots), a cell list with
// cell-crossing events and a binary heap with lazy invalidation. Only the effects the scene names
// are compiled into the engine that runs it (growth, thermostat, pinned disks).
//
// Coordinates: the engine works in the unit triangle as the CONTAINER (disks inside it). The
// result's Packing is in the Packing convention (docs/conventions.md): centres mapped from the
// centres' triangle (the container inset by diam / 2) onto the unit triangle, d = diam / (1 - sqrt3
// diam). (For n = 1 that triangle shrinks to a point: use `diameter`, which tends to 1/sqrt3.)
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "core/packing.hpp"
#include "core/progress.hpp"
#include "sim/scene.hpp"

namespace tripack {

// One processed collision (for tests and diagnostics).
struct BilliardsEvent {
  double time = 0;  // simulation time since the start
  int i = -1;
  int partner = -1;             // disk index, or -1 - side for a wall
  Vec2 position_i, velocity_i;  // disk i just after the collision (container units)
};

struct BilliardsOptions {
  // Check every pair for overlap after every event (slow; tests). The largest relative overlap
  // seen is reported in BilliardsResult::max_overlap either way (at the end otherwise).
  bool check_every_event = false;
  // Record every collision here when non-null.
  std::vector<BilliardsEvent>* trace = nullptr;
  // Compile every effect's code into the engine even when the scene does not use it (benchmark of
  // the cost of an absent effect).
  bool all_policies = false;
  // Called about every `progress_seconds` of wall time (checked every 4096 events, where the
  // wall-time stop rule is checked anyway); empty: never called.
  // Stage "billiards": events, elapsed (wall seconds), d (of the current diameter), relative_gap.
  ProgressFn progress;
  double progress_seconds = 0.5;
  // Set: the run throws Abandoned once the token is abandoned (checked every 4096 events).
  const CancelToken* cancel = nullptr;
};

struct BilliardsResult {
  Packing packing;           // Packing convention (see above)
  long double diameter = 0;  // final disk diameter in the container
  std::uint64_t events = 0;  // processed events: collisions and cell crossings
  std::uint64_t collisions = 0;
  double seconds = 0;   // wall time
  double time = 0;      // simulated time
  bool jammed = false;  // stopped because growth stalled (gap reached or precision limit)
  std::string stop_reason;
  double relative_gap = 1;  // last estimate of 1 - diam / diam_jammed (growth runs)
  double max_overlap = 0;   // largest overlap seen, relative to the diameter
  double kinetic_energy_start = 0, kinetic_energy_end = 0;  // sum v^2 / 2
  std::vector<Vec2> positions, velocities;                  // final state, container units
  double growth_rate = 0;  // at the end (a growth schedule changes it)
  // Shaking (scene effect `shake`; empty otherwise), per disk: its collisions during the shake,
  // its path extent relative to the diameter, and the rattlers: the disks that collide more than
  // rattler_factor times less often than the median disk. The positions above are the state
  // before shaking.
  std::vector<std::uint64_t> shake_hits;
  std::vector<double> excursion;
  std::vector<int> shake_rattlers;
  std::uint64_t shake_collisions = 0;
  double shake_seconds = 0;
};

BilliardsResult run_billiards(const Scene& scene, std::mt19937_64& rng,
                              const BilliardsOptions& options = {});

// Container diameter <-> Packing d.
inline long double d_from_diameter(long double diam) {
  return diam / (1 - kSqrt3 * diam);
}
inline long double diameter_from_d(long double d) {
  return d / (1 + kSqrt3 * d);
}

}  // namespace tripack
