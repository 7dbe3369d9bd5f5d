// Many billiards runs of one scene in parallel threads, each end state relaxed, polished and
// certified, then the distinct packings ranked by d and labelled like the paper (t22a, t22b, ...).
// Returns results; progress goes to a callback.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/record.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::pipeline {

struct SearchProgress {
  int runs_done = 0, runs = 0;
  int run = -1;                           // the run this snapshot is from
  std::optional<BilliardsProgress> live;  // a running run's state
  std::optional<long double> finished_d;  // a run just finished with this billiards d
  double events_per_second = 0;
};

struct BilliardsSearch {
  Scene scene;  // validated, points filled (see prepare_scene)
  int runs = 10;
  std::uint64_t seed = 1;  // run r uses seed + r, so every run is reproducible on its own
  int threads = 1;
  bool certify = true;  // relax, bonds, rigidity, stress of every end state
  std::function<void(const SearchProgress&)> progress;  // from any worker thread, serialised
  // When set, no new run starts (runs under way finish); the result holds the runs done.
  const std::atomic<bool>* cancel = nullptr;
};

struct RunOutcome {
  std::uint64_t seed = 0;
  BilliardsResult sim;
  std::optional<Analysis> analysis;
  std::string error;  // the run failed with this message (the others go on)
  std::string label;  // of its distinct packing; "-" when not certified usable
  bool ran = false;   // false: cancelled before it started
};

struct BilliardsSearchResult {
  Scene scene;
  int runs_asked = 0;
  std::vector<RunOutcome> runs;           // in seed order
  // The distinct packings the runs ended in (core/record.hpp: one per packing, each with its
  // billiards source: first seed and runs), ranked and labelled, best first.
  std::vector<PackingRecord> packings;
  double seconds = 0;                     // wall time of the whole search
};

// A scene naming a built pattern gets its points from the builder (sim/ cannot build); n is
// checked against `expected_n` (0: any). Then the scene is validated. Throws one-line errors.
void prepare_scene(const Catalogue& catalogue, Scene& scene, long long expected_n);

BilliardsSearchResult search_billiards(const BilliardsSearch& search);

}  // namespace tripack::pipeline
