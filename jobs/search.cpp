#include "jobs/search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "core/ranking.hpp"
#include "core/timing.hpp"
#include "jobs/runner.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::jobs {

std::string method_name(SearchMethod method) {
  return method == SearchMethod::Restarts ? "restarts" : "basin-hopping";
}

long long SearchResult::steps() const {
  long long total = 0;
  for (const auto& chain : chains) total += chain.steps;
  return total;
}

namespace {

// The basin-hopping constants (docs/search.md says how they were chosen).
struct HoppingSettings {
  int population = 3;
  double shrink_min = 1e-3, shrink_max = 3e-2;  // log-uniform relative shrink before a regrow
  double relocate_probability = 0.3;            // else shrink and regrow
  double growth_rate = kDefaultGrowthRate;      // of every regrow and random start
  double trial_gap = 1e-10;                     // billiards stop: estimated relative gap
  // A restart is, this often, the triangular lattice of the smallest k with Delta(k) >= n
  // missing Delta(k) - n random sites (shrunk and regrown), else a random compression.
  double lattice_probability = 0.5;
  int stale_limit = 12;       // steps without improving before a member restarts from random
  double same_d = 1e-9;       // relative: two billiards d this close count as one packing here
  double duplicate_d = 1e-9;  // two members this close: the one not holding the best restarts
};

// Relative d tolerance of "the target is reached": a polished d is good to ~1e-17, and two
// distinct certified packings of one n never came closer than 1e-12 (kSameDTolerance).
constexpr long double kTargetTolerance = kSameDTolerance;

struct Member {
  Packing packing;  // billiards end state
  int stale = 0;
};

// Disks touching (within rel) another disk or a side, per disk (Packing convention: centres in
// the unit triangle, a centre on a side touches that side).
std::vector<int> contact_counts(const Packing& p, double rel) {
  const std::size_t n = p.size();
  std::vector<int> count(n, 0);
  const long double reach = p.d * (1 + rel), side_reach = p.d * rel;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2L a = p.points[i];
    const long double sides[3] = {a.y, (kSqrt3 * a.x - a.y) / 2, (kSqrt3 * (1 - a.x) - a.y) / 2};
    for (long double s : sides) count[i] += s < side_reach;
    for (std::size_t j = i + 1; j < n; ++j) {
      const long double dx = a.x - p.points[j].x, dy = a.y - p.points[j].y;
      if (dx * dx + dy * dy < reach * reach) ++count[i], ++count[j];
    }
  }
  return count;
}

Vec2L random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<long double> u01(0, 1);
  long double a = u01(rng), b = u01(rng);
  if (a + b > 1) a = 1 - a, b = 1 - b;
  return {a + b / 2, b * kSqrt3 / 2};
}

// Distance from q to the nearest centre other than `skip`.
long double clearance(const Packing& p, Vec2L q, std::size_t skip) {
  long double best = std::numeric_limits<long double>::max();
  for (std::size_t j = 0; j < p.size(); ++j)
    if (j != skip) {
      const long double dx = q.x - p.points[j].x, dy = q.y - p.points[j].y;
      best = std::min(best, dx * dx + dy * dy);
    }
  return std::sqrt(best);
}

class Chain {
 public:
  Chain(const SearchRequest& request, std::uint64_t seed, Clock::time_point start,
        const ProgressFn& progress)
      : request_(request), rng_(seed), start_(start), progress_(progress) {
    summary_.seed = seed;
  }

  void run() {
    cpu_start_ = thread_cpu_seconds();
    for (const Packing& p : request_.starts)
      if (members_.size() < std::size_t(settings_.population)) add_member(p);
    while (!done()) {
      step();
      ++summary_.steps;
    }
    if (!summary_.target_reached && request_.method == SearchMethod::BasinHopping)
      for (const Member& m : members_) analyse(m.packing, true);
    summary_.seconds = seconds_since(start_);
    summary_.cpu_seconds = thread_cpu_seconds() - cpu_start_;
  }

  SearchChain summary() const { return summary_; }
  std::vector<PackingRecord> records() const { return records_; }

 private:
  bool done() const {
    if (summary_.target_reached || cancelled(request_.cancel)) return true;
    if (request_.steps > 0 && summary_.steps >= request_.steps) return true;
    return seconds_since(start_) >= request_.seconds;
  }

  void step() {
    if (request_.method == SearchMethod::Restarts) {
      Scene scene = default_scene(int(request_.n));
      consider(run_billiards(scene, rng_).packing);
      return;
    }
    if (members_.size() < std::size_t(settings_.population)) {
      add_member(random_start());
      return;
    }
    const std::size_t i = next_++ % members_.size();
    Member& member = members_[i];
    std::uniform_real_distribution<double> u01(0, 1);
    const Packing trial = u01(rng_) < settings_.relocate_probability ? relocate(member.packing)
                                                                     : shrink(member.packing);
    consider(trial);
    if (trial.d >= member.packing.d * (1 - settings_.same_d)) {
      member.stale = trial.d > member.packing.d * (1 + settings_.same_d) ? 0 : member.stale + 1;
      member.packing = trial;
    } else {
      ++member.stale;
    }
    if (member.stale > settings_.stale_limit || duplicates_another(i)) {
      if (!holds_best(i))
        member = Member{random_start(), 0};
      else
        member.stale = 0;
    }
  }

  void add_member(const Packing& p) {
    consider(p);
    members_.push_back({p, 0});
  }

  bool duplicates_another(std::size_t i) const {
    for (std::size_t j = 0; j < members_.size(); ++j)
      if (j != i && std::abs(members_[j].packing.d - members_[i].packing.d) <
                        settings_.duplicate_d * members_[i].packing.d)
        return true;
    return false;
  }
  bool holds_best(std::size_t i) const {
    for (std::size_t j = 0; j < members_.size(); ++j)
      if (members_[j].packing.d > members_[i].packing.d) return false;
    return true;
  }

  Scene growth_scene(const Packing& from, long double start_d) const {
    Scene scene;
    scene.n = int(request_.n);
    if (!from.points.empty()) {
      scene.points = from.points;
      scene.start_d = start_d;
    }
    scene.growth = GrowthEffect{settings_.growth_rate, {}};
    scene.thermostat = ThermostatEffect{};
    scene.stop.relative_gap = settings_.trial_gap;
    return scene;
  }

  Packing random_start() {
    std::uniform_real_distribution<double> u01(0, 1);
    if (request_.lattice_starts && u01(rng_) < settings_.lattice_probability)
      return lattice_start();
    return run_billiards(growth_scene({}, 0), rng_).packing;
  }

  // The structure the near-triangular optima share (GL1995: Delta(k) minus a few disks, shifted
  // rows): the k-row lattice with random vacancies, shrunk and regrown so that rows can slide.
  Packing lattice_start() {
    const long long n = request_.n;
    long long k = 1;
    while (k * (k + 1) / 2 < n) ++k;
    if (k < 2) return run_billiards(growth_scene({}, 0), rng_).packing;
    const long double spacing = 1.0L / (k - 1);
    std::vector<Vec2L> sites;
    for (long long j = 0; j < k; ++j)
      for (long long i = 0; i + j < k; ++i)
        sites.push_back({(i + j / 2.0L) * spacing, j * spacing * kSqrt3 / 2});
    std::shuffle(sites.begin(), sites.end(), rng_);
    sites.resize(static_cast<std::size_t>(n));
    Packing start;
    start.points = std::move(sites);
    start.d = spacing;
    return run_billiards(growth_scene(start, shrunk_d(spacing)), rng_).packing;
  }

  // d shrunk by a relative amount drawn log-uniformly in [shrink_min, shrink_max].
  long double shrunk_d(long double d) {
    std::uniform_real_distribution<double> u(std::log(settings_.shrink_min),
                                             std::log(settings_.shrink_max));
    return d * (1 - std::exp(u(rng_)));
  }

  Packing shrink(const Packing& p) {
    return run_billiards(growth_scene(p, shrunk_d(p.d)), rng_).packing;
  }

  // The loosest disk (fewest contacts; ties at random) or, half the time, any disk, moved to the
  // largest hole of the others (best of 30 n random points); the disks shrunk as in `shrink`, or
  // more if the hole needs it, and regrown.
  Packing relocate(const Packing& p) {
    const std::size_t n = p.size();
    std::uniform_int_distribution<std::size_t> any(0, n - 1);
    std::size_t moved = any(rng_);
    std::uniform_real_distribution<double> u01(0, 1);
    if (u01(rng_) < 0.5) {
      const std::vector<int> count = contact_counts(p, 1e-7);
      const int fewest = *std::min_element(count.begin(), count.end());
      std::vector<std::size_t> loosest;
      for (std::size_t i = 0; i < n; ++i)
        if (count[i] == fewest) loosest.push_back(i);
      moved = loosest[std::uniform_int_distribution<std::size_t>(0, loosest.size() - 1)(rng_)];
    }
    Vec2L hole = p.points[moved];
    long double room = 0;
    for (std::size_t k = 0; k < 30 * n; ++k) {
      const Vec2L q = random_point(rng_);
      const long double c = clearance(p, q, moved);
      if (c > room) room = c, hole = q;
    }
    Packing start = p;
    start.points[moved] = hole;
    const long double start_d = std::min(shrunk_d(p.d), room * (1 - 1e-9L));
    return run_billiards(growth_scene(start, start_d), rng_).packing;
  }

  // A state denser than the chain's best billiards state so far is analysed; a certified one
  // denser than the chain's best certified packing becomes its best.
  void consider(const Packing& p) {
    if (p.d <= best_billiards_d_ * (1 - settings_.same_d)) return;
    best_billiards_d_ = std::max(best_billiards_d_, p.d);
    analyse(p, false);
  }

  void analyse(const Packing& p, bool final_member) {
    ++summary_.analyses;
    const double cpu_before = thread_cpu_seconds();
    pipeline::Analysis analysis;
    try {
      analysis = pipeline::analyze_packing(p, {});
    } catch (const std::exception&) {
      summary_.analysis_cpu_seconds += thread_cpu_seconds() - cpu_before;
      return;  // not usable: the search goes on
    }
    summary_.analysis_cpu_seconds += thread_cpu_seconds() - cpu_before;
    if (!analysis.certified()) return;
    PackingRecord record = pipeline::record_of(analysis);
    // A chain continued from stored packings is not an independent confirmation of them.
    record.sources.push_back(
        {PackingSource::Kind::Billiards, "", summary_.seed, 1, request_.starts.empty() ? 1 : 0});
    const long double d = record.d.value();
    records_.push_back(record);
    if (final_member || d <= best_d_ * (1 + kTargetTolerance)) return;
    best_d_ = d;
    summary_.best = record;
    summary_.best_d = record.d.str(kLongDoubleDigits);
    summary_.seconds_to_best = seconds_since(start_);
    summary_.cpu_seconds_to_best = thread_cpu_seconds() - cpu_start_;
    if (request_.target && d >= *request_.target * (1 - kTargetTolerance)) {
      summary_.target_reached = true;
      summary_.seconds_to_target = summary_.seconds_to_best;
      summary_.cpu_seconds_to_target = summary_.cpu_seconds_to_best;
    }
    if (progress_) {
      Progress report;
      report.stage = "search";
      report.item =
          fmt::format("chain {} step {}: d = {}", summary_.seed, summary_.steps, summary_.best_d);
      report.elapsed = summary_.seconds_to_best;
      report.fraction = std::min(1.0, report.elapsed / request_.seconds);
      report.d = d;
      progress_(report);
    }
  }

  const SearchRequest& request_;
  HoppingSettings settings_;
  std::mt19937_64 rng_;
  Clock::time_point start_;
  const ProgressFn& progress_;
  double cpu_start_ = 0;
  std::vector<Member> members_;
  std::size_t next_ = 0;
  long double best_billiards_d_ = 0, best_d_ = 0;
  std::vector<PackingRecord> records_;
  SearchChain summary_;
};

void check(const SearchRequest& request) {
  if (request.n < 2) throw std::invalid_argument("search needs n >= 2");
  if (!(request.seconds > 0) || !std::isfinite(request.seconds))
    throw std::invalid_argument("--seconds must be positive");
  if (request.steps < 0) throw std::invalid_argument("--steps must be at least 0");
  if (request.threads < 1) throw std::invalid_argument("--threads must be at least 1");
  for (const Packing& p : request.starts)
    if (static_cast<long long>(p.size()) != request.n)
      throw std::invalid_argument(fmt::format(
          "a start packing has {} disks, the search is for n = {}", p.size(), request.n));
}

}  // namespace

std::string search_method(const SearchRequest& request) {
  return fmt::format("search {:g} s{}", request.seconds,
                     request.starts.empty() ? "" : ", continued");
}

store::RunRecord run_record_of(const SearchResult& result, std::size_t chain,
                               const std::string& tool_version) {
  const SearchChain& c = result.chains.at(chain);
  store::RunRecord run;
  run.n = result.request.n;
  run.seed = c.seed;
  run.method = search_method(result.request);
  run.events = c.steps;
  run.seconds = c.seconds;
  run.tool_version = tool_version;
  run.outcome = c.best ? "certified" : "no certified packing";
  if (c.best) run.packing = store::stored_of(*c.best, tool_version);
  return run;
}

std::vector<Packing> stored_starts(const store::ResultsDb& db, long long n, std::size_t count) {
  std::vector<Packing> starts;
  for (const store::StoredPacking& stored : db.packings(n)) {
    if (starts.size() == count) break;
    Packing p;
    p.d = std::stold(stored.d);
    p.points = stored.points;
    starts.push_back(std::move(p));
  }
  return starts;
}

SearchResult run_search(const SearchRequest& request) {
  check(request);
  SearchResult result;
  result.request = request;
  result.request.progress = {};
  result.request.cancel = nullptr;
  const auto start = Clock::now();
  const ProgressFn progress = serialised(request.progress);
  std::vector<SearchChain> chains(static_cast<std::size_t>(request.threads));
  std::vector<std::vector<PackingRecord>> found(chains.size());
  JobItems items;
  items.count = chains.size();
  items.run = [&](std::size_t c) {
    Chain chain(request, request.seed + c, start, progress);
    chain.run();
    chains[c] = chain.summary();
    found[c] = chain.records();
    return std::string();
  };
  items.finished = [](std::size_t, const std::string&) {};
  ThreadExecutor(request.threads).run_items(items, nullptr);
  result.cancelled = cancelled(request.cancel);
  result.chains = chains;
  std::vector<PackingRecord> all;
  for (auto& records : found) all.insert(all.end(), records.begin(), records.end());
  result.packings = merge_same_packings(std::move(all));
  rank_records(request.n, result.packings);
  if (!result.packings.empty()) {
    const long double best = result.packings.front().d.value();
    bool first = true;
    for (const SearchChain& chain : chains)
      if (!chain.best_d.empty() && std::stold(chain.best_d) >= best * (1 - kTargetTolerance) &&
          (first || chain.seconds_to_best < result.seconds_to_best)) {
        result.seconds_to_best = chain.seconds_to_best;
        result.cpu_seconds_to_best = chain.cpu_seconds_to_best;
        first = false;
      }
  }
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
