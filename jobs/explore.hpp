// The explorer (`tripack explore`): every class member up to max_n built and certified,
// billiards runs for small n, class members and the matrix stress set, the two compared, and
// the class gaps L(n(k)+1) - L(n(k)). Returns the data; report/explore_report.hpp writes the
// report directory. Every stage runs on the job runner (runner/runner.hpp) and stops between items
// when its job is cancelled; the result says so.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/options.hpp"
#include "core/progress.hpp"
#include "core/record.hpp"
#include "jobs/accuracy.hpp"
#include "jobs/compare.hpp"
#include "pipeline/build.hpp"

namespace tripack::jobs {

struct ExploreSettings {
  long long max_n = 300;                 // class members built and certified up to this n
  long long billiards_max_n = 40;        // billiards for every n = 2 .. this
  long long class_billiards_max_n = 60;  // and for every class member up to this
  // Members of the discovered classes (classes.yaml, claim "discovered") are built only up to
  // this n: every n is one of their members, and each enumerates its lattice's vacancy segments
  // (~K^2/4 relaxes), so all of them up to 300 would take hours (docs/classes.md §9).
  long long discovered_max_n = 60;
  std::vector<long long> stress_set{254, 255, 256, 258, 260};  // matrix stress set, when <= max_n
  // A few large class members, built and certified (4Delta(22): n = 1012; Delta(40): n = 820).
  std::vector<BuildRequest> large_terms{{"four-delta", 22, 0, ""}, {"hexagonal", 40, 0, ""}};
  // The search (search/search.hpp) per n up to billiards_max_n and class members <= 60: one chain
  // per thread, each this many steps (a step budget, so the report does not depend on the
  // machine's speed). 100 steps on 2 threads from seed 1 reach the paper's best at every
  // n = 16..34 (docs/search.md).
  long long search_steps = 100;
  int large_runs = 8;  // per n of the stress set (slower growth: ~1 s a run at n = 254)
  int threads = 2;
  std::uint64_t seed = 1;
  bool accuracy = true;  // the accuracy-against-time study and the hard cases (docs/accuracy.md)

  void declare(OptionList& o) {
    o.option(
         "--max-n", max_n,
         "class members up to this n (an exploration estimated above 5 minutes is warned about)")
        .range(2, 100000);
    o.option("--discovered-max-n", discovered_max_n,
             "members of the discovered classes (vacancy-segment, inflated-segment, jogged-line) "
             "up to this n: each enumerates vacancy sets, seconds per member above 100 disks")
        .range(2, 100000);
    o.option("--search-steps", search_steps,
             "basin-hopping steps per chain for each searched n (a step budget: the report does "
             "not depend on the machine's speed)")
        .range(1, 1e8);
    o.option("--billiards-max-n", billiards_max_n,
             "search every n = 2 .. this (class members up to 60 disks are searched too)")
        .range(2, 100000);
    o.option("--threads", threads, "parallel runs").range(1, 256);
    o.option("--seed", seed, "seed of run 0 (run r uses seed + r)");
    o.flag("!--no-accuracy", accuracy, "skip the accuracy-against-time study (~50 s)");
  }
};

// One row of compare.csv.
struct ExploreComparison {
  long long n = 0;
  std::string builder, billiards_label;
  long double d_builder = 0, d_billiards = 0;
  long double d_relative_difference = 0;  // (billiards - builder) / builder
  std::size_t bonds_builder = 0, bonds_billiards = 0, rattlers_builder = 0, rattlers_billiards = 0;
  bool same_contact_graph = false, same_packing = false;
  std::string symmetry, reason;
};

// One row of classes.csv: the paper's tight/loose measure L(n(k)+1) - L(n(k)).
struct ClassGap {
  std::string class_id;
  long k = 0, p = 0;
  long long n = 0;
  long double L_n = 0, L_next = 0;  // L(n) and L(n+1) (the best known here)
  std::string next_source;          // "builder: class k=.." or "billiards"
  std::string claim_tight;          // the paper's conjecture from classes.yaml
};

struct ExploreResult {
  ExploreSettings settings;
  // One record per row of packings.csv: by n, builder rows first (label: the billiards label of
  // the same packing, else "class-k[-p][-variant]"; rank: that packing's billiards rank, 0 when
  // billiards did not find it), then the billiards packings by rank.
  std::vector<PackingRecord> packings;
  std::vector<ExploreComparison> comparisons;
  std::vector<ClassGap> class_gaps;
  std::optional<AccuracyStudy> accuracy;
  std::vector<std::string> stages_done;
  std::vector<std::string> errors;  // one line each: an item that failed (the rest went on)
  bool cancelled = false;
  double seconds = 0;
};

// Estimated seconds of an exploration on 2 cores (measured per stage on this project's machines;
// docs/performance.md), to warn before a run far beyond the 5-minute budget.
double estimated_explore_seconds(const Catalogue& catalogue, const ExploreSettings& settings);

// Progress: stage "build", "billiards", "accuracy" or "done", the item in words, and the fraction
// of the whole exploration's estimated cost (Progress::fraction).
ExploreResult explore(const Catalogue& catalogue, const ExploreSettings& settings,
                      const JobContext& job = {});

}  // namespace tripack::jobs
