// Many billiards runs of one scene on the job runner's threads, each end state relaxed, polished
// and certified, then the distinct packings ranked by d and labelled like the paper (t22a, t22b,
// ...). Returns results; progress goes to a callback.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"
#include "core/record.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::jobs {

struct BilliardsRunsRequest {
  Scene scene;  // validated, points filled (see prepare_scene)
  int runs = 10;
  std::uint64_t seed = 1;  // run r uses seed + r, so every run is reproducible on its own
  int threads = 1;
  bool certify = true;  // relax, bonds, rigidity, stress of every end state

  // The runs (the scene comes from N or --scene: the commands' BilliardsScene).
  void declare(OptionList& o) {
    o.option("--runs", runs, "number of runs").range(1, 1000000);
    o.option("--seed", seed, "seed of run 0 (run r uses seed + r)");
    o.option("--threads", threads, "parallel runs").range(1, 256);
  }
};

struct RunOutcome {
  std::uint64_t seed = 0;
  BilliardsResult sim;
  std::optional<pipeline::Analysis> analysis;
  std::string error;  // the run failed with this message (the others go on)
  std::string label;  // of its distinct packing; "-" when not certified usable
  bool ran = false;   // false: cancelled before it started
};

struct BilliardsRunsResult {
  Scene scene;
  int runs_asked = 0;
  std::vector<RunOutcome> runs;  // in seed order
  bool cancelled = false;        // stopped before every run ran: `runs` holds those that did
  // The distinct packings the runs ended in (core/record.hpp: one per packing, each with its
  // billiards source: first seed and runs), ranked and labelled, best first.
  std::vector<PackingRecord> packings;
  double seconds = 0;  // wall time of all the runs
};

// A scene naming a built pattern gets its points from the builder (sim/ cannot build); n is
// checked against `expected_n` (0: any). Then the scene is validated. Throws one-line errors.
void prepare_scene(const Catalogue& catalogue, Scene& scene, long long expected_n);

// Progress: stage "billiards", a live snapshot of a run under way (item "run R") about every
// 0.5 s, and one report per finished run (d: its billiards d), one at a time. Cancelled: no new
// run starts (runs under way finish).
BilliardsRunsResult billiards_runs(const BilliardsRunsRequest& request, const JobContext& job = {});

}  // namespace tripack::jobs
