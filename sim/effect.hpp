// What a billiards effect is: one policy struct that reads its part of a scene and hooks into
// the engine (sim/engine.hpp). The effects a scene may name are listed once, in
// sim/effect_list.hpp; scene parsing, validation, reports and the engine's instantiations all go
// through that list, so a new effect is its policy header, its scene data (sim/scene.hpp) and a
// line in the list (docs/extending.md).
//
// Scene side, static, required:
//   kKey                               its key under `effects:` in scene YAML
//   parse(const YAML::Node&, Scene&)   read that node into the scene (one-line scene_error)
//   validate(const Scene&)             check its data (called whether or not the scene names it)
//   active(const Scene&)               whether the scene uses it
//   describe(const Scene&)             one line for reports, when active
// Optional: after_parse(const Scene&), rules for YAML scenes only (code may build scenes that
// YAML refuses).
//
// Engine side, optional: `static P for_run(const RunStart&)` makes the per-run state (the neutral
// one when the scene does not use the effect) and puts the effect into the main phase's engine,
// Engine<Effects...>, compiled for the active effects only. The state inherits EffectHooks and
// hides the hooks it needs; the ones it leaves are empty inline functions, so they cost nothing.
// An effect that runs a phase of its own after the main one (shaking) has
// `template <template <class...> class Engine> static void after_run(BilliardsResult&, const
// RunStart&)` and, if it can stand in for the main phase, `replaces_main_phase(const Scene&)`.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>

#include "core/geometry.hpp"
#include "sim/billiards.hpp"

namespace tripack::sim_detail {

template <class... Policies>
struct EffectList {};

// Why a run ends, when an effect ends it.
struct Stop {
  const char* why = "";
  bool jammed = false;
};

// The collision statistics of the engine's current block (since the last block end), for the
// pressure.
struct BlockStatistics {
  double virial = 0;        // sum of D |dp| over its collisions
  double time = 0;          // its length in simulated time
  double energy_start = 0;  // sum v^2 at its start (-1 until measured)
};

// The engine hooks, all empty. `E` is the engine: the public part of Engine (sim/engine.hpp)
// is what hooks may use. Events on the hot path (on_disk_at, on_collision, sync_due, is_pinned)
// must stay cheap; the others run once per block, sync or run.
struct EffectHooks {
  // Grows the disks: rate() is the engine's growth rate (at most one effect per engine). Without
  // one the rate is 0 at compile time and collisions also correct their energy rounding.
  static constexpr bool kGrows = false;
  // Bounds the run's time: before each event the engine asks horizon() (engine clock) and ends
  // the run there, with kHorizonStop, when the event comes later.
  static constexpr bool kHasHorizon = false;
  static constexpr Stop kHorizonStop{};
  double horizon() const { return std::numeric_limits<double>::infinity(); }

  // Run start, after the engine is built and before the first prediction.
  template <class E>
  void on_start(E&) {}
  // Whether disk i (engine numbering) never moves.
  bool is_pinned(int) const { return false; }
  // Disk i is at x at an event (collision or neighbourhood update); paths are straight between.
  void on_disk_at(int, Vec2) {}
  // After a collision of disk i with disk j (j >= 0) or a wall (j = -1 - side).
  void on_collision(int, int) {}
  // True: the engine should sync (restart its clock) after this event.
  bool sync_due() const { return false; }
  // Every sync (the positions brought to the present) restarts the clock, elapsed time ago.
  void on_clock_restart(double) {}
  // Block end (every 20 n events, just synced): a Stop ends the run.
  template <class E>
  std::optional<Stop> at_block_end(E&) {
    return std::nullopt;
  }
  // The growth rate changed (E::rate_changed()).
  template <class E>
  void on_rate_change(E&) {}
  // After every sync and block end; true when it changed velocities (predictions are redone).
  template <class E>
  bool at_sync(E&) {
    return false;
  }
  // Run end, the result filled in (engine numbering).
  template <class E>
  void at_end(const E&, BilliardsResult&) const {}
};

}  // namespace tripack::sim_detail
