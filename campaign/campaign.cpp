#include "campaign/campaign.hpp"

#include <fmt/format.h>

#include <chrono>
#include <mutex>
#include <random>
#include <stdexcept>
#include <thread>
#include <utility>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"

namespace tripack::campaign {

namespace {

struct Unit {
  long long n;
  std::uint64_t seed;
};

// One unit: a billiards run from the seeded random start, then the analysis; certified end
// states carry their packing.
store::RunRecord run_unit(const CampaignRequest& request, const Unit& unit) {
  store::RunRecord record;
  record.n = unit.n;
  record.seed = unit.seed;
  record.tool_version = request.tool_version;
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
      const Pattern& p = analysis.pattern;
      store::StoredPacking packing;
      packing.n = unit.n;
      packing.d = format_significant(p.packing.d, 18);
      packing.graph_hash = contact_graph_hash(p);
      packing.points = p.packing.points;
      packing.bonds = p.bonds;
      packing.rattlers = p.rattlers;
      packing.certified = true;
      packing.first_seed = unit.seed;
      packing.tool_version = request.tool_version;
      record.packing = std::move(packing);
    }
  } catch (const std::exception& e) {
    record.outcome = std::string("error: ") + e.what();
  }
  return record;
}

void check(const CampaignRequest& request) {
  if (std::max(request.n_first, 2LL) > request.n_last)
    throw std::invalid_argument(
        fmt::format("campaign range {}..{} has no n >= 2", request.n_first, request.n_last));
  if (request.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  if (request.threads < 1) throw std::invalid_argument("--threads must be at least 1");
  if (request.scene && !request.scene->points.empty())
    throw std::invalid_argument("a campaign scene cannot have initial points (n varies)");
}

}  // namespace

CampaignResult run_campaign(const CampaignRequest& request, const std::atomic<bool>* cancel,
                            const std::function<void(const CampaignProgress&)>& progress) {
  check(request);
  const auto start = std::chrono::steady_clock::now();
  store::ResultsDb db = store::ResultsDb::open(request.db);
  CampaignResult result;
  std::vector<Unit> pending;
  for (long long n = std::max(request.n_first, 2LL); n <= request.n_last; ++n)
    for (int r = 0; r < request.runs; ++r) {
      const Unit unit{n, request.seed + static_cast<std::uint64_t>(r)};
      ++result.units;
      if (db.has_run(unit.n, unit.seed))
        ++result.skipped;
      else
        pending.push_back(unit);
    }
  std::mutex writer;  // one connection, one writer: units are recorded one at a time
  std::size_t next = 0;
  std::string failure;  // a database error stops the campaign (what was recorded stays)
  auto worker = [&] {
    for (;;) {
      Unit unit{};
      {
        std::lock_guard<std::mutex> lock(writer);
        if (next == pending.size() || !failure.empty() || (cancel && *cancel)) return;
        unit = pending[next++];
      }
      const store::RunRecord record = run_unit(request, unit);
      std::lock_guard<std::mutex> lock(writer);
      try {
        db.record(record);
      } catch (const std::exception& e) {
        failure = e.what();
        return;
      }
      ++result.recorded;
      result.certified += record.packing.has_value();
      result.errors += record.outcome.rfind("error: ", 0) == 0;
      if (progress) {
        CampaignProgress p;
        p.done = result.recorded;
        p.total = static_cast<long long>(pending.size());
        p.skipped = result.skipped;
        p.n = unit.n;
        p.d = record.packing ? std::stold(record.packing->d) : 0.0L;
        p.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress(p);
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < request.threads; ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (!failure.empty()) throw store::StoreError(failure);
  result.cancelled = result.recorded < static_cast<long long>(pending.size());
  for (auto& best : db.best_per_n())
    if (best.n >= request.n_first && best.n <= request.n_last) result.best.push_back(best);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace tripack::campaign
