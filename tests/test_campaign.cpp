// campaign/: work units over threads into the results database (issue 11).
#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <string>

#include "campaign/campaign.hpp"
#include "pipeline/billiards_search.hpp"

namespace tripack::campaign {
namespace {

std::string fresh_db(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tripack_campaign_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  return path;
}

TEST(Campaign, RecordsEveryUnitOnceAndAgreesWithTheBilliardsSearch) {
  CampaignRequest request;
  request.n_first = 10;
  request.n_last = 13;
  request.runs = 4;
  request.threads = 2;
  request.db = fresh_db("agree.db");
  const CampaignResult first = run_campaign(request, nullptr, {});
  EXPECT_EQ(first.units, 16);
  EXPECT_EQ(first.skipped, 0);
  EXPECT_EQ(first.recorded, 16);
  EXPECT_FALSE(first.cancelled);
  ASSERT_EQ(first.best.size(), 4u);
  // The same seeds through `tripack billiards`' search: the same best d for every n.
  for (const auto& best : first.best) {
    pipeline::BilliardsSearch search;
    search.scene = default_scene(static_cast<int>(best.n));
    search.runs = 4;
    search.seed = 1;
    const auto found = pipeline::search_billiards(search);
    ASSERT_FALSE(found.packings.empty());
    EXPECT_LT(std::fabs(std::stold(best.d) / found.packings.front().pattern.packing.d - 1), 1e-12L)
        << "n = " << best.n;
  }
  // Rerun: nothing to do, nothing counted twice.
  const CampaignResult again = run_campaign(request, nullptr, {});
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
  std::atomic<bool> cancel{false};
  const CampaignResult part = run_campaign(request, &cancel, [&](const CampaignProgress& p) {
    if (p.done == 3) cancel = true;  // as Ctrl-C would, after the third unit
  });
  EXPECT_TRUE(part.cancelled);
  EXPECT_EQ(part.recorded, 3);
  const CampaignResult rest = run_campaign(request, nullptr, {});
  EXPECT_EQ(rest.skipped, 3);
  EXPECT_EQ(rest.recorded, 7);
  const auto db = store::ResultsDb::open(request.db);
  EXPECT_EQ(db.run_count(), 10);
  EXPECT_EQ(db.finished_seeds(8), (std::vector<std::uint64_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(db.integrity_check(), "ok");
}

TEST(Campaign, RefusesARangeWithoutValidN) {
  CampaignRequest request;
  request.n_first = 0;
  request.n_last = 1;
  request.db = fresh_db("never.db");
  EXPECT_THROW(run_campaign(request, nullptr, {}), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(request.db));  // checked before the database is made
}

}  // namespace
}  // namespace tripack::campaign
