#include "search/search.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <unordered_set>

#include "core/ranking.hpp"
#include "core/timing.hpp"
#include "patterns/inflation.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "runner/runner.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::search {

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
  // A fresh start is, this often, the triangular lattice of the smallest k with Delta(k) >= n
  // missing Delta(k) - n sites (shrunk and regrown), else a random compression.
  double lattice_probability = 0.5;
  // Of the lattice starts, this many have their vacancies on a rough lattice line (the rest
  // uniformly at random).
  double vacancy_path_probability = 0.75;
  double path_straight = 0.85;  // a path's step goes straight on (else turns 2:1 over jogs)
  double path_from_side = 0.5;  // a path starts on a side (else anywhere)
  int stale_limit = 12;         // steps without improving before a member restarts from random
  double same_d = 1e-9;         // relative: two billiards d this close count as one packing here
  double duplicate_d = 1e-9;    // two members this close: the one not holding the best restarts
  long long tie_interval = 4;   // at most one tie analysed per this many steps
  // A step is, this often, a fresh start (probe) that replaces the least dense member if denser.
  double probe_probability = 0.5;
  // Where n is the Delta(2)-inflation of a smaller n (patterns/inflation.hpp), the share of the
  // chain's work (estimated as steps times n^1.5) given to a search of that base n while it
  // still improves, and after it has gone as many steps again without improving.
  double base_share = 0.8, stale_base_share = 0.2;
};

// Relative d tolerance of "the target is reached": a polished d is good to ~1e-17, and two
// distinct certified packings of one n never came closer than 1e-12 (kSameDTolerance).
constexpr long double kTargetTolerance = kSameDTolerance;

struct Member {
  Packing packing;  // billiards end state
  int stale = 0;
};

// Who touches whom (within rel of d): for each disk, the other disks and, as n + s, the sides s
// it touches (Packing convention: centres in the unit triangle, a centre on a side touches it).
std::vector<std::vector<std::size_t>> contacts(const Packing& p, long double rel) {
  const std::size_t n = p.size();
  std::vector<std::vector<std::size_t>> adjacent(n);  // other disks, or n + side for a side
  const long double reach = p.d * (1 + rel), side_reach = p.d * rel;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2L a = p.points[i];
    const long double sides[3] = {a.y, (kSqrt3 * a.x - a.y) / 2, (kSqrt3 * (1 - a.x) - a.y) / 2};
    for (std::size_t s = 0; s < 3; ++s)
      if (sides[s] < side_reach) adjacent[i].push_back(n + s);
    for (std::size_t j = i + 1; j < n; ++j) {
      const long double dx = a.x - p.points[j].x, dy = a.y - p.points[j].y;
      if (dx * dx + dy * dy < reach * reach) adjacent[i].push_back(j), adjacent[j].push_back(i);
    }
  }
  return adjacent;
}

// How many contacts each disk has.
std::vector<int> contact_counts(const Packing& p, double rel) {
  std::vector<int> count;
  for (const auto& touching : contacts(p, rel)) count.push_back(static_cast<int>(touching.size()));
  return count;
}

// The contact graph of a billiards end state without its rattlers, as a hash of its edge list:
// pairs and disk-side contacts within relative 1e-8 of d, then disks with fewer than 3 contacts
// removed until none is left (a rattler's contacts are different every time a member returns to
// the same packing). None when fewer than half the disks are left: an end state that billiards
// has not jammed to 1e-8 everywhere (often one whose rows have begun to slip: the interesting
// ones) has no graph to tell it by, and every such state would share one key.
std::optional<std::size_t> contact_graph_key(const Packing& p) {
  const std::size_t n = p.size();
  const std::vector<std::vector<std::size_t>> adjacent = contacts(p, 1e-8L);
  std::vector<bool> removed(n, false);
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (removed[i]) continue;
      int live = 0;
      for (std::size_t j : adjacent[i]) live += j >= n || !removed[j];
      if (live < 3) removed[i] = true, changed = true;
    }
  }
  if (2 * static_cast<std::size_t>(std::count(removed.begin(), removed.end(), false)) < n)
    return std::nullopt;
  std::size_t key = n;
  const auto mix = [&key](std::size_t v) {
    key ^= v + 0x9e3779b97f4a7c15ULL + (key << 6) + (key >> 2);
  };
  for (std::size_t i = 0; i < n; ++i)
    if (!removed[i])
      for (std::size_t j : adjacent[i])
        if (j >= n || (j > i && !removed[j])) mix(i * (n + 3) + j);
  return key;
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

// What every chain starts from when the request names builders: the builder's packing and its
// best candidates, and what building them cost.
struct HeadStart {
  // Kept even when its certificate declined (a degenerate maximum, docs/certified.md): a
  // search never returns less than the builder, and the record's flag says what is proven.
  std::optional<PackingRecord> record;
  std::vector<Packing> starts;  // densest first
  double seconds = 0, cpu_seconds = 0;
};

class Chain {
 public:
  Chain(const SearchRequest& request, std::uint64_t seed, Clock::time_point start,
        const JobContext& job, const HeadStart* head = nullptr)
      : request_(request),
        rng_(seed),
        start_(start),
        job_(job),
        base_job_{job.cancel, {}, job.tool_version},
        head_(head),
        independent_(request.starts.empty() && !head) {
    summary_.seed = seed;
    if (const std::optional<long long> base = patterns::inflation_base(request.n);
        base && request.method == SearchMethod::BasinHopping) {
      base_request_ = request;
      base_request_.n = *base;
      base_request_.target.reset();
      base_request_.starts.clear();
      base_ = std::make_unique<Chain>(base_request_, rng_(), start, base_job_);
    }
  }

  void run() {
    // The builder's CPU seconds are every chain's: a chain's clock starts when the search did.
    cpu_start_ = thread_cpu_seconds() - (head_ ? head_->cpu_seconds : 0);
    if (base_) base_->cpu_start_ = cpu_start_;
    if (head_) start_from(*head_);
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
    if (base_) {
      summary_.base_n = base_request_.n;
      summary_.base_steps = base_->summary_.steps;
      summary_.base_best_d = base_->summary_.best_d;
    }
  }

  SearchChain summary() const { return summary_; }
  std::vector<PackingRecord> records() const { return records_; }

 private:
  bool done() const {
    if (summary_.target_reached || job_.cancelled()) return true;
    if (request_.steps > 0 && summary_.steps >= request_.steps) return true;
    return seconds_since(start_) >= request_.seconds;
  }

  void step() {
    if (request_.method == SearchMethod::Restarts) {
      Scene scene = default_scene(int(request_.n));
      consider(run_billiards(scene, rng_).packing);
      return;
    }
    if (base_ && base_turn()) {
      base_step();
      return;
    }
    if (members_.size() < std::size_t(settings_.population)) {
      add_member(random_start());
      return;
    }
    ++own_steps_;
    std::uniform_real_distribution<double> u01(0, 1);
    if (u01(rng_) < settings_.probe_probability) {
      probe();
      return;
    }
    const std::size_t i = next_++ % members_.size();
    Member& member = members_[i];
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

  // A fresh start that takes the place of the least dense member when it is denser (and is not
  // a copy of another member).
  void probe() {
    bool lattice = false;
    const Packing p = random_start(&lattice);
    consider(p, lattice);
    offer(p);
  }

  // p takes the place of the least dense member when it is denser and no copy of a member.
  void offer(const Packing& p) {
    std::size_t worst = 0;
    for (std::size_t j = 1; j < members_.size(); ++j)
      if (members_[j].packing.d < members_[worst].packing.d) worst = j;
    if (p.d <= members_[worst].packing.d) return;
    for (const Member& m : members_)
      if (std::abs(m.packing.d - p.d) < settings_.duplicate_d * p.d) return;
    members_[worst] = Member{p, 0};
  }

  // Whether this step goes to the base search: it is behind its share of the work so far, the
  // cost of a step estimated as n^1.5 (billiards events per step grow ~n, each ~n^0.5 here).
  bool base_turn() const {
    const double base_cost = static_cast<double>(base_->summary_.steps) *
                             std::pow(static_cast<double>(base_request_.n), 1.5);
    const double own_cost =
        static_cast<double>(own_steps_) * std::pow(static_cast<double>(request_.n), 1.5);
    const bool stale = base_->summary_.steps > 2 * base_improved_at_ + 50;
    const double share = stale ? settings_.stale_base_share : settings_.base_share;
    return base_cost <= share * (base_cost + own_cost);
  }

  // A step of the base search; when it found a denser certified packing, its inflation is
  // analysed and offered to the population.
  void base_step() {
    base_->step();
    ++base_->summary_.steps;
    if (!(base_->best_d_ > inflated_base_d_) || !base_->summary_.best) return;
    inflated_base_d_ = base_->best_d_;
    base_improved_at_ = base_->summary_.steps;
    const std::optional<Packing> inflated =
        patterns::inflate_by_two(base_->summary_.best->pattern.packing);
    if (!inflated || static_cast<long long>(inflated->size()) != request_.n) return;
    consider(*inflated, true);
    if (members_.size() < std::size_t(settings_.population))
      members_.push_back({*inflated, 0});
    else
      offer(*inflated);
  }

  void add_member(const Packing& p) {
    consider(p);
    members_.push_back({p, 0});
  }

  // The builder's packing is the best to beat from the first step (already analysed by the
  // build: not again), and its candidates are members.
  void start_from(const HeadStart& head) {
    if (head.record) {
      best_d_ = head.record->d.value();
      summary_.best = *head.record;
      summary_.best_d = head.record->d.str(kLongDoubleDigits);
      summary_.seconds_to_best = head.seconds;
      summary_.cpu_seconds_to_best = head.cpu_seconds;
      if (head.record->certified && request_.target &&
          best_d_ >= *request_.target * (1 - kTargetTolerance)) {
        summary_.target_reached = true;
        summary_.seconds_to_target = head.seconds;
        summary_.cpu_seconds_to_target = head.cpu_seconds;
      }
    }
    for (const Packing& p : head.starts) {
      if (members_.size() >= std::size_t(settings_.population)) break;
      first_time(p);
      best_billiards_d_ = std::max(best_billiards_d_, p.d);
      members_.push_back({p, 0});
    }
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

  Packing random_start(bool* lattice = nullptr) {
    std::uniform_real_distribution<double> u01(0, 1);
    if (request_.lattice_starts && u01(rng_) < settings_.lattice_probability) {
      if (lattice) *lattice = true;
      return lattice_start();
    }
    return run_billiards(growth_scene({}, 0), rng_).packing;
  }

  // The structure the near-triangular optima share (GL1995: Delta(k) minus a few disks, shifted
  // rows): the k-row lattice with random vacancies, shrunk and regrown so that rows can slide.
  Packing lattice_start() {
    const long long n = request_.n;
    long long k = 1;
    while (triangular(k) < n) ++k;
    if (k < 2) return run_billiards(growth_scene({}, 0), rng_).packing;
    const long double spacing = 1.0L / (k - 1);
    const long long vacancies = triangular(k) - n;
    std::vector<bool> vacant(static_cast<std::size_t>(triangular(k)), false);
    std::uniform_real_distribution<double> u01(0, 1);
    if (!(u01(rng_) < settings_.vacancy_path_probability && vacancy_path(k, vacancies, vacant))) {
      std::vector<std::size_t> order(vacant.size());
      for (std::size_t s = 0; s < order.size(); ++s) order[s] = s;
      std::shuffle(order.begin(), order.end(), rng_);
      std::fill(vacant.begin(), vacant.end(), false);
      for (long long v = 0; v < vacancies; ++v) vacant[order[static_cast<std::size_t>(v)]] = true;
    }
    std::vector<Vec2L> sites;
    for (long long j = 0; j < k; ++j)
      for (long long i = 0; i + j < k; ++i)
        if (!vacant[lattice_site(k, i, j)])
          sites.push_back({(i + j / 2.0L) * spacing, j * spacing * kSqrt3 / 2});
    Packing start;
    start.points = std::move(sites);
    start.d = spacing;
    return run_billiards(growth_scene(start, shrunk_d(spacing)), rng_).packing;
  }

  // Vacancies along a rough lattice line: a walk from a random site (path_from_side of the time
  // one on a side) in one of the 6 lattice directions, each step straight on (path_straight),
  // else turned by 60 degrees or, a third of those times, jogged to a second neighbour. Of the
  // 173 atlas bests of n = 20..200 that map onto the lattice Delta(k), 86 have their
  // Delta(k) - n vacancies on one straight segment and 77 on such a path: the line along which
  // the two sides slip (docs/search.md). False: no walk of that length fitted in 20 tries.
  bool vacancy_path(long long k, long long vacancies, std::vector<bool>& vacant) {
    static constexpr long long kDirections[6][2] = {{1, 0},  {0, 1},  {-1, 1},
                                                    {-1, 0}, {0, -1}, {1, -1}};
    if (vacancies < 1) return true;
    std::uniform_int_distribution<long long> coordinate(0, k - 1);
    std::uniform_int_distribution<int> direction(0, 5);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int attempt = 0; attempt < 20; ++attempt) {
      std::fill(vacant.begin(), vacant.end(), false);
      long long i = coordinate(rng_), j = coordinate(rng_);
      if (i + j >= k) i = k - 1 - i, j = k - 1 - j;  // a uniform site of the triangle
      if (u01(rng_) < settings_.path_from_side) {    // or a uniform site on a side
        const int side = std::uniform_int_distribution<int>(0, 2)(rng_);
        const long long along = coordinate(rng_);
        i = side == 0 ? along : side == 1 ? 0 : along;
        j = side == 0 ? 0 : side == 1 ? along : k - 1 - along;
      }
      const int heading = direction(rng_);
      long long placed = 0;
      while (placed < vacancies && i >= 0 && j >= 0 && i + j < k &&
             !vacant[lattice_site(k, i, j)]) {
        vacant[lattice_site(k, i, j)] = true;
        ++placed;
        const double u = u01(rng_);
        const int side = u01(rng_) < 0.5 ? 1 : 5;  // turn left or right
        const auto& straight = kDirections[heading];
        const auto& turned = kDirections[(heading + side) % 6];
        if (u < settings_.path_straight) {
          i += straight[0], j += straight[1];
        } else if (u < settings_.path_straight + (1 - settings_.path_straight) * 2 / 3) {
          i += turned[0], j += turned[1];
        } else {
          i += straight[0] + turned[0], j += straight[1] + turned[1];
        }
      }
      if (placed == vacancies) return true;
    }
    return false;
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
  // A state whose contact graph (disks labelled as in the chain) was analysed before is not
  // analysed again: a member walking a plateau keeps ending in the same packing, and at n ~ 190
  // an analysis costs more than the billiards step that led to it.
  //
  // Ties (states within same_d of the best so far) are analysed at most once every
  // tie_interval steps: above n ~ 130 a chain meets a plateau of ties (Delta(k) with vacancies
  // anywhere has d = 1/(k-1)), each a new contact graph costing more than a step.
  void consider(const Packing& p, bool lattice = false) {
    if (lattice) {
      // The billiards d of a lattice start is that of the lattice: the rows' slip that makes it
      // denser is found by the relax of the analysis, so every new one is analysed.
      best_billiards_d_ = std::max(best_billiards_d_, p.d);
      if (first_time(p)) analyse(p, false);
      return;
    }
    if (p.d <= best_billiards_d_ * (1 - settings_.same_d)) return;
    const bool tie = p.d <= best_billiards_d_ * (1 + settings_.same_d);
    best_billiards_d_ = std::max(best_billiards_d_, p.d);
    // The baseline (independent default runs) analyses every tie, as `tripack billiards` does.
    if (tie && request_.method == SearchMethod::BasinHopping &&
        tie_analyses_ * settings_.tie_interval > summary_.steps)
      return;
    if (!first_time(p)) return;
    tie_analyses_ += tie;
    analyse(p, false);
  }

  // False when a state of the same contact graph was analysed before in this chain.
  bool first_time(const Packing& p) {
    const std::optional<std::size_t> key = contact_graph_key(p);
    return !key || analysed_graphs_.insert(*key).second;
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
        {PackingSource::Kind::Billiards, "", summary_.seed, 1, independent_ ? 1 : 0});
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
    if (job_.progress) {
      Progress report;
      report.stage = "search";
      report.item =
          fmt::format("chain {} step {}: d = {}", summary_.seed, summary_.steps, summary_.best_d);
      report.elapsed = summary_.seconds_to_best;
      report.fraction = std::min(1.0, report.elapsed / request_.seconds);
      report.d = d;
      job_.report(report);
    }
  }

  const SearchRequest& request_;
  HoppingSettings settings_;
  std::mt19937_64 rng_;
  Clock::time_point start_;
  const JobContext& job_;
  JobContext base_job_;  // the base chain's: stops with this one, reports nothing
  const HeadStart* head_;
  bool independent_;  // started from nothing stored or built
  double cpu_start_ = 0;
  std::vector<Member> members_;
  std::size_t next_ = 0;
  long double best_billiards_d_ = 0, best_d_ = 0;
  std::vector<PackingRecord> records_;
  std::unordered_set<std::size_t> analysed_graphs_;
  long long tie_analyses_ = 0;
  SearchChain summary_;
  // The search of the base n when n is an inflation of it (else none).
  SearchRequest base_request_;
  std::unique_ptr<Chain> base_;
  long long own_steps_ = 0, base_improved_at_ = 0;
  long double inflated_base_d_ = 0;
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

namespace {

std::string method_of(const SearchRequest& request, bool from_builders) {
  return fmt::format("search {:g} s{}{}", request.seconds, from_builders ? ", from builders" : "",
                     request.starts.empty() ? "" : ", continued");
}

bool starts_from_builders(const SearchRequest& request) {
  return request.builders && request.builder_starts && request.method == SearchMethod::BasinHopping;
}

// `build --n N` on the request's threads, timed; no head start when no class contains n.
HeadStart build_head_start(const SearchRequest& request, const JobContext& job,
                           BuilderStart& summary) {
  HeadStart head;
  const auto start = Clock::now();
  const double cpu_start = process_cpu_seconds();
  try {
    pipeline::BuildSettings settings;
    settings.threads = request.threads;
    pipeline::BestBuild built =
        pipeline::build_best_for_n(*request.builders, request.n, settings, {job.cancel, {}, {}});
    const PackingRecord& record = built.best.record;
    summary.member = pipeline::member_name(built.best.pattern.provenance);
    summary.d = record.d.str(kLongDoubleDigits);
    summary.certified = record.certified;
    head.record = record;
    head.starts.push_back(built.best.pattern.packing);
    for (Packing& p : built.runners_up) head.starts.push_back(std::move(p));
    summary.candidates = static_cast<int>(head.starts.size());
  } catch (const Cancelled&) {
    summary.error = "interrupted";
  } catch (const std::exception& e) {
    summary.error = e.what();
  }
  head.seconds = summary.seconds = seconds_since(start);
  head.cpu_seconds = summary.cpu_seconds = process_cpu_seconds() - cpu_start;
  return head;
}

}  // namespace

std::string search_method(const SearchRequest& request) {
  return method_of(request, starts_from_builders(request));
}

std::string search_method(const SearchResult& result) {
  return method_of(result.request, result.builder && !result.builder->member.empty());
}

SearchResult run_search(const SearchRequest& request, const JobContext& job) {
  check(request);
  SearchResult result;
  result.request = request;
  result.request.builders = nullptr;
  const auto start = Clock::now();
  const JobContext chains_job{job.cancel, serialised(job.progress), job.tool_version};
  std::optional<HeadStart> head;
  if (starts_from_builders(request)) {
    result.builder.emplace();
    head = build_head_start(request, job, *result.builder);
    if (head->starts.empty()) head.reset();
  }
  std::vector<SearchChain> chains(static_cast<std::size_t>(request.threads));
  std::vector<std::vector<PackingRecord>> found(chains.size());
  JobItems items;
  items.count = chains.size();
  items.run = [&](std::size_t c) {
    Chain chain(request, request.seed + c, start, chains_job, head ? &*head : nullptr);
    chain.run();
    chains[c] = chain.summary();
    found[c] = chain.records();
    return std::string();
  };
  items.finished = [](std::size_t, const std::string&) {};
  ThreadExecutor(request.threads).run_items(items, nullptr);
  result.cancelled = job.cancelled();
  result.chains = chains;
  // A chain meets one packing many times (a member walking a plateau, its final analysis): it
  // counts once per chain, so that a packing's runs are the chains that reached it.
  std::vector<PackingRecord> all;
  if (head && head->record) all.push_back(*head->record);
  for (auto& records : found)
    for (PackingRecord& record : merge_same_packings(std::move(records))) {
      for (PackingSource& source : record.sources)
        if (source.kind == PackingSource::Kind::Billiards)
          source.runs = 1,
          source.independent_runs = std::min<long long>(source.independent_runs, 1);
      all.push_back(std::move(record));
    }
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

}  // namespace tripack::search
