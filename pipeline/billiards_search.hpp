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

// One distinct packing found: d, its contact graph and rank.
struct DistinctPacking {
  std::string label;
  Pattern pattern;  // polished, with bonds and rattlers
  std::size_t bonds = 0, rattlers = 0;
  bool certified = false;
  std::string verdict;
  int runs = 0;  // how many runs ended in it
  std::uint64_t first_seed = 0;
};

struct BilliardsSearchResult {
  Scene scene;
  int runs_asked = 0;
  std::vector<RunOutcome> runs;           // in seed order
  std::vector<DistinctPacking> packings;  // best first
  double seconds = 0;                     // wall time of the whole search
};

// A scene naming a built pattern gets its points from the builder (sim/ cannot build); n is
// checked against `expected_n` (0: any). Then the scene is validated. Throws one-line errors.
void prepare_scene(const Catalogue& catalogue, Scene& scene, long long expected_n);

BilliardsSearchResult search_billiards(const BilliardsSearch& search);

// The rank letters of the paper extended past z: 0 -> a, 25 -> z, 26 -> aa, 27 -> ab, ... (a
// bijective base-26 numeral, so every rank has a label and labels sort by length then letters).
std::string rank_letters(std::size_t rank);

// Labels for packings sorted by decreasing d: tN + rank letters, where packings whose d agree to
// `d_relative_tolerance` share a rank and get their bond count appended (t17a40), and those that
// share the bond count too get .1, .2, ... (t31a81.1).
struct RankKey {
  long double d = 0;
  std::size_t bonds = 0;
};
std::vector<std::string> paper_labels(long long n, const std::vector<RankKey>& sorted,
                                      long double d_relative_tolerance = 1e-12L);
// The order packings are labelled in (indices into `keys`): d decreasing; where d agree to the
// tolerance, more bonds first, then the smaller `tie` (the first seed: the billiards search and
// `tripack db` rank alike), then the given order.
std::vector<std::size_t> label_order(const std::vector<RankKey>& keys,
                                     const std::vector<std::uint64_t>& tie,
                                     long double d_relative_tolerance = 1e-12L);

}  // namespace tripack::pipeline
