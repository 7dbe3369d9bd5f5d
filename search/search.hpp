// `tripack search`: a search for the densest packing of n disks that learns from what
// it finds, with a time budget. Monotonic basin hopping on a small population (docs/search.md):
// half the steps perturb a member (shrink and regrow by billiards, or move its loosest disk to
// the largest hole) and keep the result when it is not worse; the other half are fresh starts
// (probes: a random compression, or the triangular lattice with its vacancies on a rough
// lattice line, the structure of most best packings above n ~ 50) that replace the least dense
// member when denser. States at least as dense as the best so far are analysed (relaxed,
// polished, certified); every new lattice start is, since only the relax finds the slip of rows
// that makes it denser. Ties are rationed, and a contact graph is analysed once.
// The baseline it is measured against, independent default runs, is the same loop with method
// Restarts.
//
// One chain per thread, chain c seeded by (seed, c): one thread and a step budget give the same
// result every time; a wall-time budget gives the same steps in the same order, so the same
// result whenever the same number of steps fit.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/option_values.hpp"
#include "core/options.hpp"
#include "core/packing.hpp"
#include "core/progress.hpp"
#include "core/record.hpp"

namespace tripack {
class Catalogue;
}

namespace tripack::search {

enum class SearchMethod {
  BasinHopping,  // the search
  Restarts,      // independent runs of the default billiards scene (the baseline)
};
std::string method_name(SearchMethod method);  // "basin-hopping", "restarts"

struct SearchRequest {
  long long n = 0;
  double seconds = 10;  // wall-time budget of each chain (checked between steps)
  long long steps = 0;  // > 0: also stop after this many steps per chain (reproducible budget)
  std::uint64_t seed = 1;
  int threads = 1;  // independent chains, one per thread
  SearchMethod method = SearchMethod::BasinHopping;
  // Half the fresh starts are the triangular lattice with random vacancies. They found what
  // random starts miss above n ~ 60; below, they can trap a chain (t34b: docs/search.md).
  bool lattice_starts = true;
  // Stop a chain once a certified packing with d >= target (relative 1e-12) is found.
  std::optional<long double> target;
  // Packings to continue from (a database's best): they join the population before any random
  // start. Empty: the search starts from nothing stored.
  std::vector<Packing> starts;
  // Set: before the chains, `build --n N` (pipeline::build_best_for_n, on `threads` threads).
  // Its certified packing is every chain's best to beat and its best candidates join every
  // chain's population, so the search never returns less than the builder and its own moves go
  // on from there. The builder's time counts in every chain's budget and CPU seconds (time to
  // target included). Chains so started confirm nothing independently ("from builders").
  // `tripack search` sets it unless --no-builder-starts; campaigns never do (their chains are
  // the atlas's independent confirmations).
  const Catalogue* builders = nullptr;
  bool builder_starts = true;  // the command's switch: whether it sets `builders`

  void declare(OptionList& o) {
    o.option("N", n, "number of disks").required().range(2, 100000);
    o.option("--seconds", seconds, "wall-time budget of each chain").range(1e-3, 1e7);
    o.option("--steps", steps,
             "also stop each chain after this many steps (0: no limit); a step budget on one "
             "thread is exactly reproducible")
        .range(0, 1e9);
    o.option("--seed", seed, "seed of chain 0 (chain c uses seed + c)");
    o.option("--threads", threads, "independent chains, one per thread").range(1, 256);
    o.choice("--method", method,
             {{"basin-hopping", SearchMethod::BasinHopping}, {"restarts", SearchMethod::Restarts}},
             "the search, or independent default billiards runs (the baseline)");
    o.parsed(
        "--target", [this](const std::string& s) { target = positive_decimal(s, "--target"); },
        "none", "stop a chain once a certified d >= this is found");
    o.flag("!--no-builder-starts", builder_starts,
           "start from nothing built (by default every chain starts from build --n N's best "
           "candidates, and the builder's time counts in the budget)");
    o.flag("!--no-lattice-starts", lattice_starts,
           "every fresh start from random (by default half are the triangular lattice with "
           "random vacancies)");
  }
};

struct SearchChain {
  std::uint64_t seed = 0;  // the chain's index among the request's chains
  long long steps = 0;
  long long analyses = 0;           // states analysed (none less dense than the best so far)
  double analysis_cpu_seconds = 0;  // of cpu_seconds, those spent analysing (the rest: billiards)
  double seconds = 0, cpu_seconds = 0;
  std::string best_d;  // the chain's best certified d ("" if none)
  // When the chain first held its best packing (wall and thread CPU seconds since its start).
  double seconds_to_best = 0, cpu_seconds_to_best = 0;
  bool target_reached = false;
  double seconds_to_target = 0, cpu_seconds_to_target = 0;  // when target_reached
  std::optional<PackingRecord> best;                        // the chain's best certified packing
  // Where n is an inflation (patterns/inflation.hpp): the base n searched alongside, the steps of
  // `steps` that went to it, and its best certified d ("" if none). base_n 0: none.
  long long base_n = 0, base_steps = 0;
  std::string base_best_d;
};

// What the chains started from when `builders` was set.
struct BuilderStart {
  std::string member;  // "vacancy-segment k=4 p=28"; empty when no class contains n
  std::string d;       // its d ("" when none)
  bool certified = false;
  int candidates = 0;  // of its candidates, how many joined every chain's population
  double seconds = 0, cpu_seconds = 0;  // the build's wall and process CPU seconds
  std::string error;                    // why there is none (no class contains n, ...)
};

struct SearchResult {
  SearchRequest request;  // what was asked (no callbacks, no catalogue)
  std::optional<BuilderStart> builder;
  // Distinct certified packings the chains found, ranked and labelled (core/ranking.hpp), best
  // first; each with the chain seeds that reached it as billiards sources.
  std::vector<PackingRecord> packings;
  std::vector<SearchChain> chains;
  double seconds = 0;              // wall time of the whole search
  double seconds_to_best = 0;      // first time any chain held the best packing (wall)
  double cpu_seconds_to_best = 0;  // that chain's CPU seconds then
  bool cancelled = false;
  long long steps() const;
};

// The method a search chain is recorded under (jobs/stored.hpp): "search S s" (S the budget),
// "search S s, continued" when it started from stored packings.
// "search S s, from builders" when its chains started from the builder's candidates.
std::string search_method(const SearchRequest& request);
std::string search_method(const SearchResult& result);
// Throws std::invalid_argument for n < 2, a budget that is not positive, threads < 1, or a start
// that is not a packing of n disks.
// Progress: stage "search", one report per step that changed the best, and one per finished
// chain. Cancelled: the chains stop after their current step.
SearchResult run_search(const SearchRequest& request, const JobContext& job = {});

}  // namespace tripack::search
