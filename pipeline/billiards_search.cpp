#include "pipeline/billiards_search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "analysis/compare.hpp"
#include "constructors/registry.hpp"
#include "pipeline/timing.hpp"

namespace tripack::pipeline {

void prepare_scene(const Catalogue& catalogue, Scene& scene, long long expected_n) {
  if (scene.pattern) {
    const auto& req = *scene.pattern;
    const BuildRequest request{req.class_name, static_cast<long>(req.k),
                               req.p ? static_cast<long>(*req.p) : 0, req.variant};
    const Pattern built = build_pattern(catalogue, request);
    if (scene.n && scene.n != static_cast<int>(built.packing.size()))
      throw std::invalid_argument(
          fmt::format("the scene has n = {} but pattern {} k={} has {} disks", scene.n,
                      req.class_name, req.k, built.packing.size()));
    scene.n = static_cast<int>(built.packing.size());
    scene.points = built.packing.points;
    scene.start_d = built.packing.d;
  }
  if (expected_n && scene.n != expected_n)
    throw std::invalid_argument(
        fmt::format("the scene has n = {} but {} was asked for", scene.n, expected_n));
  validate_scene(scene);
}

std::string rank_letters(std::size_t rank) {
  std::string letters;
  for (std::size_t r = rank + 1; r > 0; r = (r - 1) / 26)
    letters.insert(letters.begin(), static_cast<char>('a' + (r - 1) % 26));
  return letters;
}

std::vector<std::size_t> label_order(const std::vector<RankKey>& keys,
                                     const std::vector<std::uint64_t>& tie,
                                     long double d_relative_tolerance) {
  std::vector<std::size_t> order(keys.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  auto d_of = [&](std::size_t i) { return keys[i].d; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return d_of(a) != d_of(b) ? d_of(a) > d_of(b) : tie[a] < tie[b];
  });
  // Packings whose d agree to the labelling tolerance share a rank: order them by bonds (then
  // the tie key), not by d's last bits, which vary from run to run.
  for (std::size_t lo = 0, hi = 0; lo < order.size(); lo = hi) {
    for (hi = lo + 1; hi < order.size() &&
                      std::fabs(d_of(order[hi]) / d_of(order[hi - 1]) - 1) <= d_relative_tolerance;
         ++hi) {
    }
    std::stable_sort(order.begin() + static_cast<long>(lo), order.begin() + static_cast<long>(hi),
                     [&](std::size_t a, std::size_t b) { return keys[a].bonds > keys[b].bonds; });
  }
  return order;
}

std::vector<std::string> paper_labels(long long n, const std::vector<RankKey>& sorted,
                                      long double d_relative_tolerance) {
  auto same_d = [&](std::size_t i, std::size_t j) {
    return std::fabs(sorted[i].d / sorted[j].d - 1) <= d_relative_tolerance;
  };
  std::vector<std::string> labels(sorted.size());
  std::size_t rank = 0;
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    if (i > 0 && !same_d(i, i - 1)) ++rank;
    const bool shared = (i > 0 && same_d(i, i - 1)) || (i + 1 < sorted.size() && same_d(i, i + 1));
    labels[i] = fmt::format("t{}{}{}", n, rank_letters(rank),
                            shared ? std::to_string(sorted[i].bonds) : "");
  }
  std::map<std::string, int> uses, seen;
  for (const auto& label : labels) ++uses[label];
  for (auto& label : labels)
    if (uses[label] > 1) label += fmt::format(".{}", ++seen[label]);
  return labels;
}

namespace {

// d agreeing to this relative tolerance is "the same d" (compare_packings' default).
constexpr long double kSameDTolerance = 1e-12L;

// Every run, in parallel; run r uses seed + r.
std::vector<RunOutcome> run_all(const BilliardsSearch& search) {
  std::vector<RunOutcome> runs(static_cast<std::size_t>(search.runs));
  std::atomic<int> next{0}, done{0};
  std::mutex report;
  auto notify = [&](SearchProgress p) {
    if (!search.progress) return;
    std::lock_guard<std::mutex> lock(report);
    p.runs_done = done.load();
    p.runs = search.runs;
    search.progress(p);
  };
  auto worker = [&] {
    for (int r; (r = next.fetch_add(1)) < search.runs;) {
      if (search.cancel && *search.cancel) break;
      RunOutcome& run = runs[static_cast<std::size_t>(r)];
      run.seed = search.seed + static_cast<std::uint64_t>(r);
      run.ran = true;
      std::mt19937_64 rng(run.seed);
      BilliardsOptions options;
      if (search.progress)
        options.progress = [&, r](const BilliardsProgress& live) {
          SearchProgress p;
          p.run = r;
          p.live = live;
          notify(p);
        };
      try {
        run.sim = run_billiards(search.scene, rng, options);
        if (search.scene.n >= 2 && search.certify)
          run.analysis = analyze_packing(run.sim.packing, {});
      } catch (const std::exception& e) {
        run.error = e.what();
      }
      ++done;
      SearchProgress p;
      p.run = r;
      p.finished_d = run.sim.packing.d;
      p.events_per_second = run.sim.seconds > 0 ? run.sim.events / run.sim.seconds : 0.0;
      notify(p);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, search.threads); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  return runs;
}

// Distinct certified-usable end states (same d and contact graph up to the triangle's symmetries
// are one packing), best first; ties in d broken by more bonds, then by the first seed, so the
// order never depends on thread timing.
std::vector<DistinctPacking> distinct_of(std::vector<RunOutcome>& runs, long long n) {
  std::vector<std::size_t> usable;
  std::vector<Pattern> patterns;
  for (std::size_t r = 0; r < runs.size(); ++r)
    if (runs[r].analysis && runs[r].analysis->identification.polish.converged) {
      usable.push_back(r);
      patterns.push_back(runs[r].analysis->pattern);
    }
  const std::vector<int> group = distinct_packings(patterns);
  std::vector<DistinctPacking> distinct;
  for (std::size_t u = 0; u < usable.size(); ++u) {
    const auto g = static_cast<std::size_t>(group[u]);
    if (distinct.size() <= g) distinct.resize(g + 1);
    auto& x = distinct[g];
    if (x.runs++ == 0) {
      const Analysis& a = *runs[usable[u]].analysis;
      x.pattern = a.pattern;
      x.bonds = a.pattern.bonds.size();
      x.rattlers = a.pattern.rattlers.size();
      x.certified = a.certified();
      x.verdict = a.status();
      x.first_seed = runs[usable[u]].seed;
    }
  }
  std::vector<RankKey> unsorted;
  std::vector<std::uint64_t> seeds;
  for (const auto& x : distinct) {
    unsorted.push_back({x.pattern.packing.d, x.bonds});
    seeds.push_back(x.first_seed);
  }
  const std::vector<std::size_t> order = label_order(unsorted, seeds, kSameDTolerance);
  std::vector<DistinctPacking> sorted;
  std::vector<RankKey> keys;
  for (std::size_t i : order) {
    sorted.push_back(std::move(distinct[i]));
    keys.push_back({sorted.back().pattern.packing.d, sorted.back().bonds});
  }
  const auto labels = paper_labels(n, keys, kSameDTolerance);
  std::vector<std::string> label_of_group(order.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    sorted[i].label = labels[i];
    label_of_group[order[i]] = labels[i];
  }
  for (auto& run : runs) run.label.assign(1, '-');  // (not = "-": GCC 12 -Wrestrict false positive)
  for (std::size_t u = 0; u < usable.size(); ++u)
    runs[usable[u]].label = label_of_group[static_cast<std::size_t>(group[u])];
  return sorted;
}

}  // namespace

BilliardsSearchResult search_billiards(const BilliardsSearch& search) {
  if (search.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  const auto start = Clock::now();
  BilliardsSearchResult result;
  result.scene = search.scene;
  result.runs_asked = search.runs;
  result.runs = run_all(search);
  std::erase_if(result.runs, [](const RunOutcome& run) { return !run.ran; });
  result.packings = distinct_of(result.runs, search.scene.n);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::pipeline
