// The billiards engine's interface inside sim/: its input (Setup) and the entry point that picks
// the engine compiled for a run's effects. Separate from sim/engine.hpp so that the code around
// the engine (sim/billiards.cpp, sim/effects.cpp) can start runs without including the engine
// template, which only the dispatcher's translation unit instantiates.
#pragma once

#include <cstdint>
#include <vector>

#include "sim/billiards.hpp"

namespace tripack::sim_detail {

// Everything the engine needs, already in container units.
struct Setup {
  std::vector<Vec2> x, v;
  std::vector<char> pinned;
  double diam0 = 0, rate = 0, diam_cap = 0;
  std::vector<GrowthStep> schedule;  // by decreasing gap
  std::uint64_t thermostat_every = 0;
  StopRules stop;
};

// A run of the engine compiled for exactly the effects it needs: growth (G), thermostat (T),
// pinned disks (P), or shaking (the shaking engine never grows). Defined in sim/billiards.cpp.
BilliardsResult run_engine_for(bool G, bool T, bool P, bool shaking, Setup s,
                               const BilliardsOptions& o);

}  // namespace tripack::sim_detail
