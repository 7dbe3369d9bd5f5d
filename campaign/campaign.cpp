#include "campaign/campaign.hpp"

#include <fmt/format.h>

#include <chrono>
#include <map>
#include <mutex>
#include <optional>
#include <random>
#include <stdexcept>
#include <thread>
#include <utility>

#include "analysis/compare.hpp"
#include "campaign/ranks.hpp"
#include "campaign/work_unit.hpp"
#include "core/io.hpp"
#include "core/timing.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"

namespace tripack::campaign {

namespace {

// One unit: a billiards run from the seeded random start, then the analysis; certified end
// states carry their packing.
store::RunRecord run_unit(const CampaignRequest& request, const WorkUnit& unit) {
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
      PackingRecord found = pipeline::record_of(analysis);
      found.sources.push_back({PackingSource::Kind::Billiards, "", unit.seed, 1});
      record.packing = store::stored_of(found, request.tool_version);
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
  if (request.scene && !request.scene->points.empty())
    throw std::invalid_argument("a campaign scene cannot have initial points (n varies)");
}



// The one writer's bookkeeping: the units still to run, the database, the counts. Units are
// handed out and recorded under one mutex (threads of this process and, through rank 0's main
// thread, the other MPI ranks), so the database has one connection and one writer.
class Ledger {
 public:
  Ledger(const CampaignRequest& request, const std::atomic<bool>* cancel,
         const std::function<void(const CampaignProgress&)>& progress)
      : db_(store::ResultsDb::open(request.db)), cancel_(cancel), progress_(progress) {
    for (long long n = std::max(request.n_first, 2LL); n <= request.n_last; ++n)
      for (int r = 0; r < request.runs; ++r) {
        const WorkUnit unit{n, request.seed + static_cast<std::uint64_t>(r)};
        ++result_.units;
        if (db_.has_run(unit.n, unit.seed))
          ++result_.skipped;
        else
          pending_.push_back(unit);
      }
  }

  // The next unit to run; none when every unit is handed out, after a database error, or when
  // cancelled.
  std::optional<WorkUnit> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (next_ == pending_.size() || !failure_.empty() || (cancel_ && *cancel_)) return std::nullopt;
    return pending_[next_++];
  }

  void finish(const store::RunRecord& record) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!failure_.empty()) return;
    try {
      db_.record(record);
    } catch (const std::exception& e) {
      failure_ = e.what();
      return;
    }
    ++result_.recorded;
    result_.certified += record.packing.has_value();
    result_.errors += record.outcome.rfind("error: ", 0) == 0;
    if (progress_) {
      CampaignProgress p;
      p.done = result_.recorded;
      p.total = static_cast<long long>(pending_.size());
      p.skipped = result_.skipped;
      p.n = record.n;
      p.seed = record.seed;
      p.d = record.packing ? std::stold(record.packing->d) : 0.0L;
      p.elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
      progress_(p);
    }
  }

  void fail(const std::string& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (failure_.empty()) failure_ = message;
  }

  // After every worker has stopped: the result, or the database error that stopped the run.
  CampaignResult close(const CampaignRequest& request) {
    if (!failure_.empty()) throw store::StoreError(failure_);
    result_.cancelled = result_.recorded < static_cast<long long>(pending_.size());
    for (auto& best : db_.best_per_n())
      if (best.n >= request.n_first && best.n <= request.n_last) result_.best.push_back(best);
    result_.seconds = std::chrono::duration<double>(Clock::now() - start_).count();
    return result_;
  }

 private:
  store::ResultsDb db_;
  const std::atomic<bool>* cancel_;
  std::function<void(const CampaignProgress&)> progress_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
  std::vector<WorkUnit> pending_;
  std::size_t next_ = 0;
  std::string failure_;
  CampaignResult result_;
};

void run_units(const CampaignRequest& request, Ledger& ledger) {
  while (const auto unit = ledger.take()) ledger.finish(run_unit(request, *unit));
}

// Rank 0's main thread: answer every worker rank's report with a unit or, when none is left,
// stop; return once every worker has stopped. A worker's run that does not match the unit it
// was given stops the campaign (nothing of it is recorded).
void serve_ranks(RankLink& link, Ledger* ledger) {
  std::map<int, WorkUnit> given;
  int working = link.size() - 1;
  while (working > 0) {
    const auto report = link.poll_report();
    if (!report) {
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      continue;
    }
    if (ledger && !report->run.empty()) {
      try {
        const store::RunRecord run = decode_run(report->run);
        const auto it = given.find(report->from);
        if (it == given.end() || it->second.n != run.n || it->second.seed != run.seed)
          throw std::runtime_error(
              fmt::format("rank {} sent a run (n = {}, seed = {}) it was not given", report->from,
                          run.n, run.seed));
        ledger->finish(run);
      } catch (const std::exception& e) {
        ledger->fail(e.what());
      }
    }
    given.erase(report->from);
    const auto unit = ledger ? ledger->take() : std::nullopt;
    if (unit) {
      given[report->from] = *unit;
      link.send_unit(report->from, *unit);
    } else {
      link.send_stop(report->from);
      --working;
    }
  }
}

CampaignResult run_on_ranks(const CampaignRequest& request, const std::atomic<bool>* cancel,
                            const std::function<void(const CampaignProgress&)>& progress) {
  RankLink link;
  CampaignResult result;
  result.ranks = link.size();
  result.rank = link.rank();
  if (link.rank() != 0) {
    std::string last;
    while (const auto unit = link.report_and_wait(last))
      last = encode_run(run_unit(request, *unit));
    return result;
  }
  std::optional<Ledger> ledger;
  try {
    ledger.emplace(request, cancel, progress);
  } catch (...) {
    serve_ranks(link, nullptr);  // stop every worker, then say why
    throw;
  }
  std::vector<std::thread> pool;
  for (int t = 0; t < request.threads; ++t) pool.emplace_back([&] { run_units(request, *ledger); });
  serve_ranks(link, &*ledger);
  for (auto& t : pool) t.join();
  result = ledger->close(request);
  result.ranks = link.size();
  return result;
}

}  // namespace

CampaignResult run_campaign(const CampaignRequest& request, const std::atomic<bool>* cancel,
                            const std::function<void(const CampaignProgress&)>& progress) {
  const int ranks = launched_ranks();
  check(request, ranks);
  if (ranks > 1) return run_on_ranks(request, cancel, progress);
  Ledger ledger(request, cancel, progress);
  std::vector<std::thread> pool;
  for (int t = 1; t < request.threads; ++t) pool.emplace_back([&] { run_units(request, ledger); });
  run_units(request, ledger);
  for (auto& t : pool) t.join();
  return ledger.close(request);
}

}  // namespace tripack::campaign
