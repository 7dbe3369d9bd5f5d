// The billiards engine's input inside sim/: the start state (Setup) and what the effects see of
// the run being set up (RunStart). Separate from sim/engine.hpp so that the effects' headers can
// make their per-run state without including the engine template, which only sim/billiards.cpp
// instantiates.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::sim_detail {

// The start state in container units and engine numbering; the effects bring the rest.
struct Setup {
  std::vector<Vec2> x, v;
  double diam0 = 0, diam_cap = 0;
  StopRules stop;
};

// A run being set up, as the effects' for_run and after_run see it.
struct RunStart {
  const Scene& scene;
  // order[k]: the scene index of the disk the engine calls k (a Z-order numbering).
  std::vector<int> order;
  double diam_cap = 0;  // the largest diameter possible (Oler's bound)
  std::mt19937_64& rng;
  const BilliardsOptions& options;

  // Per-disk values from engine to scene numbering.
  template <class T>
  std::vector<T> to_scene_numbering(const std::vector<T>& v) const {
    std::vector<T> out(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[std::size_t(order[k])] = v[k];
    return out;
  }
};

}  // namespace tripack::sim_detail
