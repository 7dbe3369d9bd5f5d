// Campaigns (docs/campaigns.md): billiards runs over many n as work units (n, seed), run by the job
// runner on threads or, when the program was started by mpirun, on MPI ranks (runner/ranks.hpp),
// each finished unit recorded in the results database at once (store/), so rerunning the same
// request skips every unit already recorded and an interrupted campaign loses at most the units
// under way.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "core/option_values.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"
#include "runner/runner.hpp"
#include "sim/scene.hpp"
#include "store/results_db.hpp"

namespace tripack::jobs {

struct CampaignRequest {
  long long n_first = 0, n_last = 0;  // every n in [n_first, n_last] with n >= 2
  int runs = 20;                      // seeds seed .. seed + runs - 1 for each n
  std::uint64_t seed = 1;
  int threads = 1;  // under mpirun: rank 0's own worker threads (0: it only hands out and writes)
  std::string db = "tripack.db";  // the results database file
  std::optional<Scene> scene;     // effects and stop rule for every n (default_scene(n) if none)
  // Set: every unit is a search chain (search/search.hpp) of this many seconds from random starts
  // instead of one billiards run; its method is "search S s".
  std::optional<double> search_seconds;

  void declare(OptionList& o) {
    o.parsed(
         "--n", [this](const std::string& s) { std::tie(n_first, n_last) = parse_range(s, "--n"); },
         "", "A..B or N")
        .required();
    o.option("--runs", runs, "seeds per n").range(1, 1000000);
    o.option("--seed", seed, "first seed");
    o.option("--threads", threads,
             "parallel units; under mpirun, rank 0's own (0: it only hands out)")
        .range(0, 256);
    o.option("--db", db, "results database");
    o.parsed(
        "--scene", [this](const std::string& s) { scene = load_scene(s); }, "the default scene",
        "scene YAML (effects, stop rule) for every n");
    o.parsed(
        "--search-seconds",
        [this](const std::string& s) { search_seconds = positive_decimal(s, "--search-seconds"); },
        "none",
        "every unit is a search chain of this many seconds from random starts (method 'search S "
        "s'), not one billiards run");
  }
};

struct CampaignResult {
  long long units = 0;     // in the request
  long long skipped = 0;   // already recorded before this call
  long long recorded = 0;  // finished and recorded now
  long long certified = 0;
  long long errors = 0;  // units that ended with an error (recorded with it)
  bool cancelled = false;
  std::vector<store::StoredPacking> best;  // the database's best of every n in the range
  double seconds = 0;
  int ranks = 1;  // MPI ranks of the launch (1: threads only)
  int rank = 0;   // this process's rank: only rank 0's result has counts and the best packings
};

// Runs the units the database does not hold yet on `executor` (executor_for_launch: threads, or
// MPI ranks under mpirun). Progress: stage "campaign", one report per recorded unit (item
// "recorded n = N seed = S: d = ..."). Throws std::invalid_argument for a range without n >= 2,
// runs < 1, threads < 1 (< 0 under mpirun), a scene with initial points; store::StoreError for the
// database (before any run starts, or after the units under way when a write fails: what was
// recorded stays). Rank 0 is the only process that opens the database; the other ranks' result is
// empty.
CampaignResult run_campaign(const CampaignRequest& request, const Executor& executor,
                            const JobContext& job);

}  // namespace tripack::jobs
