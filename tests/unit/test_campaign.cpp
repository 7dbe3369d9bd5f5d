// campaign/: work units over threads into the results database.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "jobs/billiards_runs.hpp"
#include "jobs/campaign.hpp"
#include "jobs/stored.hpp"
#include "jobs/work_unit.hpp"
#include "scratch.hpp"

namespace tripack::jobs {
namespace {

std::string fresh_db(const std::string& name) {
  return testing_scratch::fresh_db("campaign", name);
}

// Billiards units over n = first..last, `runs` seeds each, on 2 threads, into a fresh database.
CampaignRequest small_campaign(long long first, long long last, int runs, const std::string& db) {
  CampaignRequest request;
  request.n_first = first;
  request.n_last = last;
  request.runs = runs;
  request.threads = 2;
  request.db = fresh_db(db);
  return request;
}

TEST(Campaign, RecordsEveryUnitOnceAndAgreesWithTheBilliardsRuns) {
  CampaignRequest request = small_campaign(10, 13, 4, "agree.db");
  const CampaignResult first = run_campaign(request, ThreadExecutor(request.threads), {});
  EXPECT_EQ(first.units, 16);
  EXPECT_EQ(first.skipped, 0);
  EXPECT_EQ(first.recorded, 16);
  EXPECT_FALSE(first.cancelled);
  ASSERT_EQ(first.best.size(), 4u);
  // The same seeds through `tripack billiards`' search: the same best d for every n.
  for (const auto& best : first.best) {
    jobs::BilliardsRunsRequest runs;
    runs.scene = default_scene(static_cast<int>(best.n));
    runs.runs = 4;
    runs.seed = 1;
    const auto found = jobs::billiards_runs(runs);
    ASSERT_FALSE(found.packings.empty());
    EXPECT_LT(std::fabs(std::stold(best.d) / found.packings.front().pattern.packing.d - 1), 1e-12L)
        << "n = " << best.n;
  }
  // Rerun: nothing to do, nothing counted twice.
  const CampaignResult again = run_campaign(request, ThreadExecutor(request.threads), {});
  EXPECT_EQ(again.skipped, 16);
  EXPECT_EQ(again.recorded, 0);
  EXPECT_EQ(store::ResultsDb::open(request.db).run_count(), 16);
}

TEST(Campaign, AnInterruptedCampaignResumesWithoutRepeats) {
  CampaignRequest request;
  request.n_first = 8;
  request.n_last = 9;
  request.runs = 5;
  request.db = fresh_db("resume.db");
  CancelToken cancel;
  const auto progress = [&](const Progress& p) {
    if (p.done == 3) cancel.cancel();  // as Ctrl-C would, after the third unit
  };
  const CampaignResult part =
      run_campaign(request, ThreadExecutor(request.threads), {&cancel, progress, ""});
  EXPECT_TRUE(part.cancelled);
  EXPECT_EQ(part.recorded, 3);
  const CampaignResult rest = run_campaign(request, ThreadExecutor(request.threads), {});
  EXPECT_EQ(rest.skipped, 3);
  EXPECT_EQ(rest.recorded, 7);
  const auto db = store::ResultsDb::open(request.db);
  EXPECT_EQ(db.run_count(), 10);
  EXPECT_EQ(db.finished_seeds(8), (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(db.integrity_check(), "ok");
}

// A worker rank's run reaches rank 0 digit for digit: the stored packing is the one it found.
TEST(Campaign, ARunRecordCrossesRanksUnchanged) {
  store::RunRecord run;
  run.n = 3;
  run.seed = 18446744073709551615ULL;  // the largest seed survives the trip
  run.outcome = "certified";
  run.events = 1234;
  run.seconds = 0.125;
  run.tool_version = "tripack test";
  store::StoredPacking p;
  p.n = 3;
  p.d = "1";
  p.graph_hash = "0123456789abcdef";
  // Long doubles that a 17-digit double would round: the trip must keep all 64 bits.
  p.points = {Vec2L{0.0L, 0.0L}, Vec2L{1.0L, 0.0L},
              Vec2L{0.5L, 0.866025403784438646763723170752936183L}};
  p.points.push_back(Vec2L{1.0L / 3.0L, std::nextafter(0.1L, 1.0L)});
  p.bonds = {Bond::pair(0, 1), Bond::wall(2, Side::Bottom)};
  p.rattlers = {3};
  p.certified = true;
  p.first_seed = run.seed;
  p.tool_version = run.tool_version;
  run.packing = p;
  const store::RunRecord back = decode_run(encode_run(run));
  EXPECT_EQ(back.n, run.n);
  EXPECT_EQ(back.seed, run.seed);
  EXPECT_EQ(back.outcome, run.outcome);
  EXPECT_EQ(back.events, run.events);
  EXPECT_EQ(back.seconds, run.seconds);
  ASSERT_TRUE(back.packing.has_value());
  ASSERT_EQ(back.packing->points.size(), p.points.size());
  for (std::size_t i = 0; i < p.points.size(); ++i) {
    EXPECT_EQ(back.packing->points[i].x, p.points[i].x) << i;
    EXPECT_EQ(back.packing->points[i].y, p.points[i].y) << i;
  }
  ASSERT_EQ(back.packing->bonds.size(), 2u);
  EXPECT_EQ(back.packing->bonds[1].b, p.bonds[1].b);
  EXPECT_EQ(back.packing->rattlers, p.rattlers);
  EXPECT_EQ(back.packing->graph_hash, p.graph_hash);
  run.packing.reset();
  EXPECT_FALSE(decode_run(encode_run(run)).packing.has_value());
  EXPECT_THROW(decode_run("{\"n\": 3}"), std::runtime_error);
  EXPECT_THROW(decode_run("not json"), std::runtime_error);
}

TEST(Campaign, RefusesARangeWithoutValidN) {
  CampaignRequest request;
  request.n_first = 0;
  request.n_last = 1;
  request.db = fresh_db("never.db");
  EXPECT_THROW(run_campaign(request, ThreadExecutor(request.threads), {}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(request.db));  // checked before the database is made
}

// db prune keeps exactly the best K of each n in its range, in ranked_packings' order, leaves
// every run and the other n alone, and a rerun of the campaign still skips every unit.
TEST(Campaign, PruneKeepsTheBestKOfEachNAndEveryRun) {
  CampaignRequest request = small_campaign(14, 17, 12, "prune.db");
  run_campaign(request, ThreadExecutor(request.threads), {});
  std::map<long long, std::vector<PackingRecord>> before;
  std::map<long long, std::vector<long long>> before_ids;
  {
    const auto db = store::ResultsDb::open(request.db);
    for (long long n = 14; n <= 17; ++n) before[n] = ranked_packings(db, n, &before_ids[n]);
  }
  ASSERT_GT(before[16].size(), 2u);  // something to prune (16 has several local optima)
  const PruneResult pruned = prune_database(request.db, 2, 15, 16);
  EXPECT_EQ(pruned.n_values, 2);
  const auto db = store::ResultsDb::open(request.db);
  EXPECT_EQ(db.run_count(), 48);
  long long removed = 0;
  for (long long n = 14; n <= 17; ++n) {
    std::vector<long long> after_ids;
    const auto after = ranked_packings(db, n, &after_ids);
    const bool in_range = n == 15 || n == 16;
    const std::size_t expected =
        in_range ? std::min<std::size_t>(2, before[n].size()) : before[n].size();
    ASSERT_EQ(after.size(), expected) << "n = " << n;
    removed += static_cast<long long>(before[n].size() - after.size());
    for (std::size_t r = 0; r < after.size(); ++r) {
      EXPECT_EQ(after_ids[r], before_ids[n][r]) << "n = " << n;
      EXPECT_EQ(after[r].pattern.packing.points, before[n][r].pattern.packing.points);
    }
  }
  EXPECT_EQ(pruned.removed, removed);
  EXPECT_EQ(db.statistics().integrity, "ok");
  const CampaignResult again = run_campaign(request, ThreadExecutor(request.threads), {});
  EXPECT_EQ(again.skipped, 48);
  EXPECT_EQ(again.recorded, 0);
  EXPECT_THROW(prune_database(request.db, 0, 2, 100), std::invalid_argument);
}

}  // namespace
}  // namespace tripack::jobs
