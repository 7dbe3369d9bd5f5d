#include "jobs/campaign.hpp"

#include <fmt/format.h>

#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>

#include "core/io.hpp"
#include "core/precision.hpp"
#include "core/timing.hpp"
#include "jobs/stored.hpp"
#include "jobs/work_unit.hpp"
#include "pipeline/analyze.hpp"
#include "runner/ranks.hpp"
#include "search/search.hpp"
#include "sim/billiards.hpp"

namespace tripack::jobs {

namespace {

search::SearchRequest search_of(const CampaignRequest& request, long long n, std::uint64_t seed) {
  search::SearchRequest search;
  search.n = n;
  search.seed = seed;
  search.seconds = request.search_seconds.value_or(1);
  return search;
}

// A search unit: one chain from random starts, recorded with its best certified packing.
store::RunRecord search_unit(const CampaignRequest& request, const WorkUnit& unit,
                             const std::string& tool_version) {
  const search::SearchRequest search = search_of(request, unit.n, unit.seed);
  try {
    return run_record_of(search::run_search(search), 0, tool_version);
  } catch (const std::exception& e) {
    store::RunRecord record;
    record.n = unit.n;
    record.seed = unit.seed;
    record.method = search::search_method(search);
    record.tool_version = tool_version;
    record.outcome = std::string("error: ") + e.what();
    return record;
  }
}

// One unit: a billiards run from the seeded random start, then the analysis; certified end
// states carry their packing.
store::RunRecord run_unit(const CampaignRequest& request, const WorkUnit& unit,
                          const std::string& tool_version) {
  if (request.search_seconds) return search_unit(request, unit, tool_version);
  store::RunRecord record;
  record.n = unit.n;
  record.seed = unit.seed;
  record.tool_version = tool_version;
  try {
    Scene scene = request.scene ? *request.scene : default_scene(static_cast<int>(unit.n));
    scene.n = static_cast<int>(unit.n);
    std::mt19937_64 rng(unit.seed);
    const BilliardsResult sim = run_billiards(scene, rng);
    const pipeline::Analysis analysis = pipeline::analyze_packing(sim.packing, {});
    record.events = static_cast<long long>(sim.events);
    record.seconds = sim.seconds + analysis.times.total();
    record.outcome = analysis.certified() ? "certified" : "not certified: " + analysis.status();
    if (analysis.certified()) {
      PackingRecord found = pipeline::record_of(analysis);
      found.sources.push_back({PackingSource::Kind::Billiards, "", unit.seed, 1, 1});
      record.packing = store::stored_of(found, tool_version);
    }
  } catch (const std::exception& e) {
    record.outcome = std::string("error: ") + e.what();
  }
  return record;
}

void check(const CampaignRequest& request, int ranks) {
  if (std::max(request.n_first, 2LL) > request.n_last)
    throw std::invalid_argument(
        fmt::format("campaign range {}..{} has no n >= 2", request.n_first, request.n_last));
  if (request.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  if (request.threads < (ranks > 1 ? 0 : 1))
    throw std::invalid_argument(ranks > 1 ? "--threads must be at least 0 under mpirun"
                                          : "--threads must be at least 1");
  if (request.search_seconds && !(*request.search_seconds > 0))
    throw std::invalid_argument("--search-seconds must be positive");
  if (request.search_seconds && request.scene)
    throw std::invalid_argument("a search campaign has no scene (--scene is for billiards runs)");
  if (request.scene && !request.scene->points.empty())
    throw std::invalid_argument("a campaign scene cannot have initial points (n varies)");
}

// The units of the request, in order: every process of an MPI launch computes the same list.
std::vector<WorkUnit> units_of(const CampaignRequest& request) {
  std::vector<WorkUnit> units;
  for (long long n = std::max(request.n_first, 2LL); n <= request.n_last; ++n)
    for (int r = 0; r < request.runs; ++r)
      units.push_back({n, request.seed + static_cast<std::uint64_t>(r)});
  return units;
}

std::string recorded_line(const store::RunRecord& run) {
  return fmt::format(
      "recorded n = {} seed = {}: {}", run.n, run.seed,
      run.packing ? "d = " + format_significant(std::stold(run.packing->d), 15) : "not certified");
}

}  // namespace

CampaignResult run_campaign(const CampaignRequest& request, const Executor& executor,
                            const JobContext& job) {
  const int ranks = launched_ranks();
  check(request, ranks);
  const std::vector<WorkUnit> units = units_of(request);
  JobItems items;
  items.count = units.size();
  items.run = [&](std::size_t i) {
    return encode_run(run_unit(request, units[i], job.tool_version));
  };
  if (executor.rank() != 0) {
    CampaignResult result;
    const JobOutcome outcome = executor.run_items(items, job.cancel);
    result.ranks = outcome.ranks;
    result.rank = outcome.rank;
    return result;
  }
  const auto start = Clock::now();
  CampaignResult result;
  std::optional<store::ResultsDb> db;
  try {
    db.emplace(store::ResultsDb::open(request.db));
  } catch (...) {
    executor.run_items(JobItems{0, std::vector<std::size_t>{}, items.run, {}},
                       job.cancel);  // stop every rank
    throw;
  }
  // Resumed: the units the database already holds a run of (same n, seed and method) are done.
  const std::string method = request.search_seconds
                                 ? search::search_method(search_of(request, 0, 0))
                                 : store::RunRecord{}.method;
  const auto key = [](long long n, std::uint64_t seed) { return fmt::format("{}:{}", n, seed); };
  std::set<std::string> done;
  for (long long n = std::max(request.n_first, 2LL); n <= request.n_last; ++n)
    for (std::uint64_t seed : db->finished_seeds(n, method)) done.insert(key(n, seed));
  result.units = static_cast<long long>(units.size());
  result.skipped = skip_done(
      items, [&](std::size_t i) { return key(units[i].n, units[i].seed); }, done);
  ProgressCounter counter("campaign", result.units - result.skipped);
  items.finished = [&](std::size_t i, const std::string& encoded) {
    const store::RunRecord run = decode_run(encoded);
    if (run.n != units[i].n || run.seed != units[i].seed)
      throw std::runtime_error(
          fmt::format("a worker sent a run (n = {}, seed = {}) for unit n = {}, seed = {}", run.n,
                      run.seed, units[i].n, units[i].seed));
    db->record(run);
    ++result.recorded;
    result.certified += run.packing.has_value();
    result.errors += run.outcome.rfind("error: ", 0) == 0;
    Progress p =
        counter.finished(recorded_line(run), run.packing ? std::stold(run.packing->d) : 0.0L);
    p.skipped = result.skipped;
    job.report(p);
  };
  const JobOutcome outcome = executor.run_items(items, job.cancel);
  result.cancelled = outcome.cancelled;
  result.ranks = outcome.ranks;
  for (auto& best : db->best_per_n())
    if (best.n >= request.n_first && best.n <= request.n_last) result.best.push_back(best);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
