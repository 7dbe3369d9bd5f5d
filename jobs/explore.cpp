#include "jobs/explore.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "core/timing.hpp"
#include "jobs/billiards_runs.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "runner/runner.hpp"
#include "search/search.hpp"

namespace tripack::jobs {

namespace {

// Cost of the work items in seconds on 2 cores, fitted to an explore --max-n 250 run on this
// project's machines (docs/performance.md "Explorer"): a build + certificate ~2.3e-5 n^1.5 s
// (n = 25: 3 ms, 225: 72 ms, 1012: 0.85 s); a billiards run + analysis ~1.5e-3 n s at growth
// rate 0.01, growing as rate^-0.75 (n = 254 at rate 1e-4: ~11 s a run).
double build_cost(long long n) {
  return 2.3e-5 * std::pow(static_cast<double>(n), 1.5);
}
double billiards_cost(long long n, int runs, int threads, double rate) {
  const double per_run = 1.5e-3 * static_cast<double>(n) * std::pow(0.01 / rate, 0.75);
  return per_run * runs / std::max(1, threads);
}
// A basin-hopping step (a regrow from a shrunk or moved state, analyses of improvements): about
// 2.5e-4 n s (n = 26: 6 ms, 53: 12 ms); the chains run side by side.
double hopping_cost(long long n, long long steps) {
  return 2.5e-4 * static_cast<double>(n) * static_cast<double>(steps);
}

// The accuracy study with its hard cases: ~50 s on 2 cores with the default settings (2026-11-28:
// four billiards runs of 500 disks take 27 s of it, the catalogue's best packing of 500 10 s).
constexpr double kAccuracyCost = 50;

bool proven_optimal(long long n) {
  if (n <= 15) return true;  // GL1995 Sec.1: optimal packings known (proved) for n <= 15
  const auto k = static_cast<long long>(std::llround((std::sqrt(8.0 * n + 1) - 1) / 2));
  return triangular(k) == n;  // Delta(k): Oler's bound is attained (Oler 1961)
}

struct Plan {
  std::vector<BuildRequest> builds;
  std::vector<long long> searches;  // n, increasing
  double cost = 0;
};

Plan plan_for(const Catalogue& catalogue, const ExploreSettings& s) {
  Plan plan;
  plan.builds = pipeline::class_members_up_to(catalogue, s.max_n);
  std::erase_if(plan.builds, [&](const BuildRequest& b) {
    const auto& c = catalogue.find(b.class_id);
    return c.claim_status == "discovered" && catalogue.n_of(c, b.k, b.p) > s.discovered_max_n;
  });
  std::set<long long> search_n;
  for (long long n = 2; n <= std::min(s.billiards_max_n, s.max_n); ++n) search_n.insert(n);
  for (const auto& b : plan.builds) {
    const long long n = catalogue.n_of(catalogue.find(b.class_id), b.k, b.p);
    plan.cost += build_cost(n);
    if (n <= std::min(s.class_billiards_max_n, s.max_n) && n >= 2) search_n.insert(n);
  }
  for (long long n : s.stress_set)
    if (n <= s.max_n) search_n.insert(n);
  for (const auto& b : s.large_terms) {
    plan.builds.push_back(b);
    plan.cost += build_cost(catalogue.n_of(catalogue.find(b.class_id), b.k, b.p));
  }
  plan.searches.assign(search_n.begin(), search_n.end());
  if (s.accuracy) plan.cost += kAccuracyCost;
  for (long long n : plan.searches) {
    const Scene scene = default_scene(static_cast<int>(n));
    const double rate = scene.growth ? scene.growth->rate : 0.01;
    plan.cost += n > s.billiards_max_n && n > s.class_billiards_max_n
                     ? billiards_cost(n, s.large_runs, s.threads, rate)
                     : hopping_cost(n, s.search_steps);
  }
  return plan;
}

PackingRecord packing_of_build(const pipeline::BuildResult& b, double seconds) {
  PackingRecord row = b.record;
  row.label = pipeline::member_name(row.pattern.provenance);
  row.rank = 0;
  row.seconds = seconds;
  row.proven_optimal = proven_optimal(row.n());
  return row;
}

PackingRecord packing_of_search(const PackingRecord& x, double seconds) {
  PackingRecord row = x;
  row.seconds = seconds;
  row.proven_optimal = proven_optimal(row.n());
  return row;
}

// The best builder row for each n (largest d).
std::map<long long, const PackingRecord*> best_builder_by_n(
    const std::vector<PackingRecord>& rows) {
  std::map<long long, const PackingRecord*> best;
  for (const auto& r : rows)
    if (r.from_builder() &&
        (!best.count(r.n()) || r.pattern.packing.d > best[r.n()]->pattern.packing.d))
      best[r.n()] = &r;
  return best;
}

// `found`: a search's distinct packings of n, ranked.
void compare_with_builders(ExploreResult& result, long long n,
                           const std::vector<PackingRecord>& found) {
  if (found.empty()) return;
  // Every builder row of this n learns its billiards label when the search found it.
  for (auto& row : result.packings) {
    if (!row.from_builder() || row.n() != n) continue;
    for (std::size_t i = 0; i < found.size(); ++i)
      if (same_packing(row, found[i])) {
        row.rank = i + 1;
        row.label = found[i].label;
        break;
      }
  }
  const auto best = best_builder_by_n(result.packings);
  const auto it = best.find(n);
  if (it == best.end()) return;
  const PackingRecord& b = *it->second;
  const PackingRecord& x = found.front();
  const Comparison c = compare_packings(b.pattern, x.pattern);
  ExploreComparison row;
  row.n = n;
  row.builder = pipeline::member_name(b.pattern.provenance);
  row.billiards_label = x.label;
  row.d_builder = b.pattern.packing.d;
  row.d_billiards = x.pattern.packing.d;
  row.d_relative_difference = (row.d_billiards - row.d_builder) / row.d_builder;
  row.bonds_builder = b.pattern.bonds.size();
  row.bonds_billiards = x.bonds();
  row.rattlers_builder = b.pattern.rattlers.size();
  row.rattlers_billiards = x.rattlers();
  row.same_contact_graph = c.isomorphic;
  row.same_packing = c.same;
  row.symmetry = c.symmetry ? std::string(symmetry_name(*c.symmetry)) : "";
  row.reason = c.reason;
  result.comparisons.push_back(row);
}

// L(n(k)+1) - L(n(k)) for every class member whose n + 1 has a value here.
std::vector<ClassGap> class_gaps_of(const Catalogue& catalogue,
                                    const std::vector<PackingRecord>& rows) {
  std::map<long long, const PackingRecord*> best;  // best d for each n, any source
  for (const auto& r : rows)
    if (!best.count(r.n()) || r.pattern.packing.d > best[r.n()]->pattern.packing.d)
      best[r.n()] = &r;
  std::vector<ClassGap> gaps;
  std::set<std::tuple<std::string, long, long>> seen;
  for (const auto& r : rows) {
    if (!r.from_builder() || !seen.insert({r.pattern.provenance.class_id, r.pattern.provenance.k,
                                           r.pattern.provenance.p})
                                  .second)
      continue;
    const auto next = best.find(r.n() + 1);
    if (next == best.end()) continue;
    ClassGap g;
    g.class_id = r.pattern.provenance.class_id;
    g.k = r.pattern.provenance.k;
    g.p = r.pattern.provenance.p;
    g.n = r.n();
    g.L_n = 1 / r.pattern.packing.d;
    g.L_next = 1 / next->second->pattern.packing.d;
    g.next_source = next->second->from_builder()
                        ? "builder: " + pipeline::member_name(next->second->pattern.provenance)
                        : "billiards: " + next->second->label;
    g.claim_tight = catalogue.find(r.pattern.provenance.class_id).claim_tight;
    gaps.push_back(g);
  }
  return gaps;
}

// A class member built and certified; when the certificate's LP fails (near-degenerate members,
// README "Known limits") the polished build is kept, marked not certified, with the reason.
PackingRecord build_row(const Catalogue& catalogue, const BuildRequest& request) {
  const auto start = Clock::now();
  try {
    return packing_of_build(
        pipeline::build_and_certify(catalogue, request, pipeline::BuildSettings{}),
        seconds_since(start));
  } catch (const std::exception& certify_error) {
    pipeline::BuildSettings polish_only;
    polish_only.certify = false;
    PackingRecord row = packing_of_build(
        pipeline::build_and_certify(catalogue, request, polish_only), seconds_since(start));
    row.verdict = std::string("not certified: ") + certify_error.what();
    return row;
  }
}

}  // namespace

double estimated_explore_seconds(const Catalogue& catalogue, const ExploreSettings& settings) {
  return plan_for(catalogue, settings).cost;
}

ExploreResult explore(const Catalogue& catalogue, const ExploreSettings& settings,
                      const JobContext& job) {
  const CancelToken never;
  const CancelToken& cancel = job.cancel ? *job.cancel : never;
  const auto start = Clock::now();
  ExploreResult result;
  result.settings = settings;
  const Plan plan = plan_for(catalogue, settings);
  double done = 0;  // estimated seconds of the items finished
  std::mutex report_lock;
  auto report = [&](const std::string& stage, const std::string& item, double cost_done = 0) {
    std::lock_guard<std::mutex> lock(report_lock);
    done += cost_done;
    if (!job.progress) return;
    Progress p;
    p.stage = stage;
    p.item = item;
    p.fraction = plan.cost > 0 ? std::min(1.0, done / plan.cost) : 1.0;
    p.elapsed = seconds_since(start);
    p.item_finished = cost_done > 0;
    job.progress(p);
  };

  // Builds on the runner's threads, in catalogue order in the result.
  std::vector<std::optional<PackingRecord>> built(plan.builds.size());
  std::vector<std::string> build_errors(plan.builds.size());
  JobItems builds;
  builds.count = plan.builds.size();
  builds.run = [&](std::size_t i) {
    const BuildRequest& request = plan.builds[i];
    const std::string name =
        pipeline::member_name({request.class_id, request.k, request.p, request.variant});
    try {
      built[i] = build_row(catalogue, request);
    } catch (const std::exception& e) {
      build_errors[i] = fmt::format("build {}: {}", name, e.what());
    }
    return std::string();
  };
  builds.finished = [&](std::size_t i, const std::string&) {
    const BuildRequest& request = plan.builds[i];
    const long long n = catalogue.n_of(catalogue.find(request.class_id), request.k, request.p);
    report("building",
           fmt::format(
               "{} (n = {})",
               pipeline::member_name({request.class_id, request.k, request.p, request.variant}), n),
           build_cost(n));
  };
  ThreadExecutor(settings.threads).run_items(builds, &cancel);
  for (std::size_t i = 0; i < built.size(); ++i) {
    if (built[i]) result.packings.push_back(std::move(*built[i]));
    if (!build_errors[i].empty()) result.errors.push_back(build_errors[i]);
  }
  if (!cancel.cancelled()) result.stages_done.push_back("build");

  // Searches one n at a time, each on the runner's threads: basin hopping (one chain per
  // thread) up to the small-n limits, billiards runs for the stress set. Each n's packings are
  // compared with its builders once every search is done (a stage of its own in the log).
  std::vector<std::pair<long long, std::vector<PackingRecord>>> found_by_n;
  for (long long n : plan.searches) {
    if (cancel.cancelled()) break;
    const bool large = n > settings.billiards_max_n && n > settings.class_billiards_max_n;
    if (!large) {
      search::SearchRequest search;
      search.n = n;
      search.steps = settings.search_steps;
      search.seconds = 3600;  // the step budget decides; this only bounds a pathological step
      search.seed = settings.seed;
      search.threads = settings.threads;
      // Random starts only: at n <= 60 they reach the best (19 of 19 n = 16..34 at 100 steps),
      // where lattice starts led both chains of seed 1 to t34b.
      search.lattice_starts = false;
      const std::string item = fmt::format("n = {}, {} steps", n, settings.search_steps);
      report("search", item);
      try {
        const search::SearchResult found = search::run_search(search, {&cancel, {}, {}});
        for (const auto& x : found.packings)
          result.packings.push_back(packing_of_search(x, found.seconds));
        found_by_n.emplace_back(n, found.packings);
      } catch (const std::exception& e) {
        result.errors.push_back(fmt::format("search n = {}: {}", n, e.what()));
      }
      report("search", item, hopping_cost(n, settings.search_steps));
      continue;
    }
    BilliardsRunsRequest runs;
    runs.scene = default_scene(static_cast<int>(n));
    runs.runs = settings.large_runs;
    runs.seed = settings.seed;
    runs.threads = settings.threads;
    const double cost = billiards_cost(n, runs.runs, settings.threads,
                                       runs.scene.growth ? runs.scene.growth->rate : 0.01);
    report("billiards", fmt::format("n = {}, {} runs", n, runs.runs));
    const auto t0 = Clock::now();
    try {
      const BilliardsRunsResult found = billiards_runs(runs, {&cancel, {}, {}});
      const double seconds = seconds_since(t0);
      for (std::size_t i = 0; i < found.packings.size(); ++i)
        result.packings.push_back(packing_of_search(found.packings[i], seconds));
      found_by_n.emplace_back(n, found.packings);
    } catch (const std::exception& e) {
      result.errors.push_back(fmt::format("billiards n = {}: {}", n, e.what()));
    }
    report("billiards", fmt::format("n = {}, {} runs", n, runs.runs), cost);
  }
  if (!cancel.cancelled()) result.stages_done.push_back("billiards");
  if (!found_by_n.empty()) {
    report("compare", fmt::format("{} n against their builders", found_by_n.size()));
    for (const auto& [n, found] : found_by_n) compare_with_builders(result, n, found);
  }
  if (settings.accuracy && !cancel.cancelled()) {
    try {
      AccuracySettings accuracy;
      accuracy.seed = settings.seed;
      const auto accuracy_progress = [&](const Progress& p) {
        report("accuracy", p.item, p.item_finished ? kAccuracyCost / std::max(1LL, p.total) : 0);
      };
      result.accuracy =
          measure_accuracy(catalogue, accuracy, {&cancel, accuracy_progress, job.tool_version});
      if (!result.accuracy->cancelled) result.stages_done.push_back("accuracy");
    } catch (const std::exception& e) {
      result.errors.push_back(std::string("accuracy: ") + e.what());
    }
  }
  std::stable_sort(result.packings.begin(), result.packings.end(),
                   [](const PackingRecord& a, const PackingRecord& b) {
                     if (a.n() != b.n()) return a.n() < b.n();
                     return a.from_builder() && !b.from_builder();
                   });
  // A proven optimum is the best packing of its n: a worse local optimum there (sparse-corner
  // at 13, below sparse-rows' t13a) is no proven optimum.
  std::map<long long, long double> best_d;
  for (const auto& r : result.packings)
    best_d[r.n()] = std::max(best_d[r.n()], r.pattern.packing.d);
  for (auto& r : result.packings)
    r.proven_optimal = r.proven_optimal && r.pattern.packing.d >= best_d[r.n()] * (1 - 1e-12L);
  result.class_gaps = class_gaps_of(catalogue, result.packings);
  result.cancelled = cancel.cancelled();
  result.seconds = seconds_since(start);
  report("done", "");
  return result;
}

}  // namespace tripack::jobs
