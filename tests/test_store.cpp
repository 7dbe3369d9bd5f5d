// store/: the campaign results database (issue 11): records, deduplication, resumption, refusal
// of foreign files, locks, and what a killed writer leaves behind.
#include <gtest/gtest.h>
#include <signal.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "store/results_db.hpp"

namespace tripack::store {
namespace {

// A fresh database path in the test's temporary directory.
std::string fresh_path(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tripack_store_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto path = dir / name;
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path.string() + suffix);
  return path.string();
}

StoredPacking packing(long long n, const std::string& d, const std::string& hash) {
  StoredPacking p;
  p.n = n;
  p.d = d;
  p.graph_hash = hash;
  p.points = {{0.0L, 0.0L}, {1.0L, 0.0L}, {0.5L, 0.866025403784438646763723170752936183L}};
  p.bonds = {Bond::pair(0, 1), Bond::wall(0, Side::Bottom)};
  p.rattlers = {2};
  p.certified = true;
  return p;
}

RunRecord run(long long n, std::uint64_t seed, std::optional<StoredPacking> p) {
  RunRecord r;
  r.n = n;
  r.seed = seed;
  r.outcome = p ? "certified" : "error: test";
  r.events = 1000 + static_cast<long long>(seed);
  r.seconds = 0.5;
  r.packing = std::move(p);
  r.tool_version = "test";
  return r;
}

TEST(Store, RecordsUnitsOnceAndDeduplicatesPackings) {
  const std::string path = fresh_path("records.db");
  {
    ResultsDb db = ResultsDb::open(path);
    EXPECT_TRUE(db.record(run(3, 1, packing(3, "1.00000000000000000000", "h3"))));
    EXPECT_TRUE(db.record(run(3, 2, packing(3, "1.000000000000000001", "h3"))));  // same one
    EXPECT_TRUE(db.record(run(3, 3, packing(3, "0.9", "other"))));
    EXPECT_TRUE(db.record(run(4, 1, std::nullopt)));
    EXPECT_FALSE(db.record(run(3, 2, packing(3, "1", "h3"))));  // already recorded: unchanged
    EXPECT_EQ(db.run_count(), 4);
  }
  const ResultsDb db = ResultsDb::open(path);  // reopened: all of it is there
  EXPECT_TRUE(db.has_run(3, 2));
  EXPECT_FALSE(db.has_run(3, 4));
  EXPECT_EQ(db.finished_seeds(3), (std::vector<std::uint64_t>{1, 2, 3}));
  const auto three = db.packings(3);
  ASSERT_EQ(three.size(), 2u);
  EXPECT_EQ(three[0].d, "1.00000000000000000000");  // the first d, with every digit given
  EXPECT_EQ(three[0].runs, 2);
  EXPECT_EQ(three[0].first_seed, 1u);
  EXPECT_EQ(three[0].bonds, packing(3, "1", "h3").bonds);
  EXPECT_EQ(three[0].rattlers, std::vector<int>{2});
  ASSERT_EQ(three[0].points.size(), 3u);
  // 21 significant digits: the point comes back to long double within 1e-20.
  EXPECT_NEAR(static_cast<double>(three[0].points[2].y - packing(3, "1", "h3").points[2].y), 0,
              1e-20);
  EXPECT_EQ(three[1].d, "0.9");
  const auto best = db.best_per_n();
  ASSERT_EQ(best.size(), 1u);  // n = 4 has a run but no packing
  EXPECT_EQ(best[0].n, 3);
  EXPECT_EQ(db.integrity_check(), "ok");
}

TEST(Store, RefusesAnotherSchemaVersionAndForeignFiles) {
  const std::string path = fresh_path("version.db");
  { ResultsDb::open(path); }
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(raw, "UPDATE meta SET value = '99' WHERE key = 'schema_version'", nullptr,
                         nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(raw);
  try {
    ResultsDb::open(path);
    ADD_FAILURE() << "opened a version 99 database";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("schema version 99"), std::string::npos) << e.what();
  }
  const std::string text = fresh_path("text.db");
  std::ofstream(text) << "x y\n0.1 0.2\n0.3 0.1\nthese are points, not a database\n";
  try {
    ResultsDb::open(text);
    ADD_FAILURE() << "opened a text file";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("not a tripack database"), std::string::npos) << e.what();
  }
  // The refused file is left as it was.
  std::ifstream in(text);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "x y");
}

TEST(Store, ALockedDatabaseIsReportedNotCorrupted) {
  const std::string path = fresh_path("locked.db");
  { ResultsDb::open(path); }
  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &other), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(other, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
  // Opening checks the schema in a write transaction, so it is refused (after the busy
  // timeout) with one line.
  try {
    ResultsDb::open(path, {.busy_timeout_ms = 100});
    ADD_FAILURE() << "opened through an exclusive lock";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is locked by another process"), std::string::npos)
        << e.what();
  }
  sqlite3_exec(other, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(other);
  ResultsDb db = ResultsDb::open(path);
  EXPECT_TRUE(db.record(run(5, 1, packing(5, "0.5", "h5"))));  // the lock gone, it works
  EXPECT_EQ(db.integrity_check(), "ok");
}

TEST(Store, AKilledWriterLosesNothingCommitted) {
  // A child records units 0, 1, 2, ... as fast as it can and is killed with SIGKILL: the
  // database must pass the integrity check and hold exactly the seeds 0..k-1 for some k >= 1
  // (every unit committed before the kill, none half-written), and a rerun continues from k.
  const std::string path = fresh_path("killed.db");
  { ResultsDb::open(path); }
  for (int attempt = 0; attempt < 3; ++attempt) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      ResultsDb db = ResultsDb::open(path);
      for (std::uint64_t seed = db.finished_seeds(7).size();; ++seed)
        db.record(run(7, seed, packing(7, "0." + std::to_string(100000 + seed), "h")));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(150 + 100 * attempt));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status));
    ResultsDb db = ResultsDb::open(path);
    EXPECT_EQ(db.integrity_check(), "ok");
    const auto seeds = db.finished_seeds(7);
    ASSERT_FALSE(seeds.empty());
    for (std::size_t i = 0; i < seeds.size(); ++i) ASSERT_EQ(seeds[i], i);
    EXPECT_EQ(db.packings(7).size(), seeds.size());  // every run's packing with it
  }
}

}  // namespace
}  // namespace tripack::store
