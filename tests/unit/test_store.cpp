// store/: the campaign results database: records, deduplication, resumption, refusal
// of foreign files, locks, what a killed writer leaves behind, the version-1 migration, imported
// packings and the duplicate counts of `db check`.
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

#include "scratch.hpp"
#include "store/results_db.hpp"

namespace tripack::store {
namespace {

// A fresh database path in the test's temporary directory.
std::string fresh_path(const std::string& name) {
  return testing_scratch::fresh_db("store", name);
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

// A run of n = 3 by `method` (empty: RunRecord's default) that ended in the packing "h3".
RunRecord run_to_h3(std::uint64_t seed, const std::string& method = "") {
  RunRecord r = run(3, seed, packing(3, "0.5", "h3"));
  if (!method.empty()) r.method = method;
  return r;
}

// Threads and MPI ranks finish units in any order; the stored packing must not depend on it: a
// packing found by several runs keeps the smallest seed and that run's coordinates and d.
TEST(Store, APackingKeepsItsSmallestSeedWhateverOrderTheUnitsFinishIn) {
  auto found_by = [](std::uint64_t seed) {
    StoredPacking p = packing(3, "1.0000000000000" + std::to_string(seed), "h3");
    p.points[2].x += static_cast<long double>(seed) * 1e-15L;  // each run's own rounding
    return p;
  };
  std::vector<std::vector<StoredPacking>> stored;
  for (const std::vector<std::uint64_t>& order :
       {std::vector<std::uint64_t>{2, 5, 9}, std::vector<std::uint64_t>{9, 5, 2},
        std::vector<std::uint64_t>{5, 9, 2}}) {
    const std::string path = fresh_path("order.db");
    ResultsDb db = ResultsDb::open(path);
    for (const auto seed : order) EXPECT_TRUE(db.record(run(3, seed, found_by(seed))));
    stored.push_back(db.packings(3));
  }
  for (const auto& packings : stored) {
    ASSERT_EQ(packings.size(), 1u);
    EXPECT_EQ(packings[0].first_seed, 2u);
    EXPECT_EQ(packings[0].runs, 3);
    EXPECT_EQ(packings[0].d, found_by(2).d);
    EXPECT_EQ(packings[0].points[2].x, stored[0][0].points[2].x);
    EXPECT_NEAR(static_cast<double>(packings[0].points[2].x - found_by(2).points[2].x), 0, 1e-20);
  }
}

// A new database appears whole: written beside `path` and linked into place, so a process killed
// while creating it never leaves a tableless file (the soak test caught one at 173 ms under load)
// and nothing is left beside it.
TEST(Store, ANewDatabaseAppearsWholeWithNothingLeftBeside) {
  const std::string path = fresh_path("whole.db");
  {
    ResultsDb db = ResultsDb::open(path);
    EXPECT_EQ(db.run_count(), 0);
  }
  const auto dir = std::filesystem::path(path).parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find("whole.db.creating"), std::string::npos)
        << entry.path();
  // Read as a database of this version by a command that never creates one.
  OpenOptions read;
  read.create = false;
  EXPECT_EQ(ResultsDb::open(path, read).statistics().integrity, "ok");
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
  {
    ResultsDb db = ResultsDb::open(path);
    db.record(run(5, 1, packing(5, "0.5", "h5")));
  }
  sqlite3* other = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &other), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(other, "BEGIN EXCLUSIVE", nullptr, nullptr, nullptr), SQLITE_OK);
  {
    // A database at the current version opens without a write lock (WAL: reading goes on while
    // another process writes); writing is refused after the busy timeout, with one line.
    ResultsDb db = ResultsDb::open(path, {.busy_timeout_ms = 100});
    EXPECT_EQ(db.packings(5).size(), 1u);
    for (int attempt = 0; attempt < 2; ++attempt) {
      try {
        if (attempt == 0)
          db.record(run(5, 2, packing(5, "0.5", "h5")));
        else
          db.add_packings({packing(5, "0.25", "other")});
        ADD_FAILURE() << "wrote through an exclusive lock";
      } catch (const StoreError& e) {
        EXPECT_NE(std::string(e.what()).find("is locked by another process"), std::string::npos)
            << e.what();
      }
    }
  }
  sqlite3_exec(other, "COMMIT", nullptr, nullptr, nullptr);
  sqlite3_close(other);
  ResultsDb db = ResultsDb::open(path);
  EXPECT_EQ(db.run_count(), 1);  // nothing of the refused writes
  EXPECT_EQ(db.packings(5).size(), 1u);
  EXPECT_TRUE(db.record(run(5, 2, packing(5, "0.5", "h5"))));  // the lock gone, it works
  EXPECT_EQ(db.integrity_check(), "ok");
}

TEST(Store, ReadingNeverCreatesAFileAndRefusesForeignOnes) {
  OpenOptions read;
  read.create = false;
  const std::string missing = fresh_path("missing.db");
  try {
    ResultsDb::open(missing, read);
    ADD_FAILURE() << "opened a missing file";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("no database"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(missing));
  const std::string empty = fresh_path("empty.db");
  std::ofstream{empty};
  try {
    ResultsDb::open(empty, read);
    ADD_FAILURE() << "read an empty file";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is empty"), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::filesystem::file_size(empty), 0u);
  // An SQLite file of something else: refused, not given tripack's tables.
  const std::string foreign = fresh_path("foreign.db");
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(foreign.c_str(), &raw), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(raw, "CREATE TABLE photos(id INTEGER)", nullptr, nullptr, nullptr),
            SQLITE_OK);
  sqlite3_close(raw);
  for (const bool create : {false, true}) {
    try {
      ResultsDb::open(foreign, {.busy_timeout_ms = 100, .create = create});
      ADD_FAILURE() << "opened a foreign SQLite file";
    } catch (const StoreError& e) {
      EXPECT_NE(std::string(e.what()).find("not a tripack database"), std::string::npos)
          << e.what();
    }
  }
  ASSERT_EQ(sqlite3_open(foreign.c_str(), &raw), SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(raw, "SELECT COUNT(*) FROM sqlite_master", -1, &s, nullptr);
  ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
  EXPECT_EQ(sqlite3_column_int(s, 0), 1);  // still only its own table
  sqlite3_finalize(s);
  sqlite3_close(raw);
}

// The schema tripack 0.1 wrote before packings had an origin (version 1), with one run and its
// packing.
void write_version_1(const std::string& path) {
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  const char* sql = R"sql(
PRAGMA journal_mode=WAL;
CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE packings(id INTEGER PRIMARY KEY, n INTEGER NOT NULL, d TEXT NOT NULL,
  d_key TEXT NOT NULL, d_value REAL NOT NULL, graph_hash TEXT NOT NULL, points TEXT NOT NULL,
  bonds TEXT NOT NULL, rattlers TEXT NOT NULL, certified INTEGER NOT NULL,
  first_seed INTEGER NOT NULL, runs INTEGER NOT NULL, tool_version TEXT NOT NULL,
  UNIQUE(n, graph_hash, d_key));
CREATE TABLE runs(n INTEGER NOT NULL, seed INTEGER NOT NULL, outcome TEXT NOT NULL,
  events INTEGER NOT NULL, seconds REAL NOT NULL, packing_id INTEGER REFERENCES packings(id),
  tool_version TEXT NOT NULL, PRIMARY KEY(n, seed));
INSERT INTO meta VALUES('schema_version', '1');
INSERT INTO packings VALUES(1, 3, '0.5', '0.5', 0.5, 'h3', '0 0
1 0
0.5 0.8
', '0 1
', '2', 1, 7, 1, 'tripack 0.1');
INSERT INTO runs VALUES(3, 7, 'certified', 10, 0.25, 1, 'tripack 0.1');
)sql";
  ASSERT_EQ(sqlite3_exec(raw, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(raw);
  sqlite3_close(raw);
}

// Versions 1 and 2 migrate in place to the current version (3: runs have a method).
TEST(Store, MigratesAVersion1FileInPlace) {
  const std::string path = fresh_path("version1.db");
  write_version_1(path);
  {
    ResultsDb db = ResultsDb::open(path);
    const auto three = db.packings(3);
    ASSERT_EQ(three.size(), 1u);
    EXPECT_EQ(three[0].d, "0.5");
    EXPECT_EQ(three[0].origin, "campaign");
    EXPECT_TRUE(three[0].has_seed);
    EXPECT_EQ(three[0].first_seed, 7u);
    EXPECT_EQ(three[0].runs, 1);
    EXPECT_EQ(three[0].rattlers, std::vector<int>{2});
    EXPECT_TRUE(db.has_run(3, 7));
    // The runs still point at their packing: a new run of the same packing is counted there.
    EXPECT_TRUE(db.record(run(3, 8, packing(3, "0.5", "h3"))));
    EXPECT_EQ(db.packings(3)[0].runs, 2);
    EXPECT_EQ(db.statistics().integrity, "ok");
  }
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  sqlite3_stmt* s = nullptr;
  sqlite3_prepare_v2(raw, "SELECT value FROM meta WHERE key = 'schema_version'", -1, &s, nullptr);
  ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)), "3");
  sqlite3_finalize(s);
  // The old run became a billiards run.
  sqlite3_prepare_v2(raw, "SELECT method FROM runs WHERE n = 3 AND seed = 7", -1, &s, nullptr);
  ASSERT_EQ(sqlite3_step(s), SQLITE_ROW);
  EXPECT_STREQ(reinterpret_cast<const char*>(sqlite3_column_text(s, 0)), "billiards");
  sqlite3_finalize(s);
  sqlite3_prepare_v2(raw, "PRAGMA foreign_key_check", -1, &s, nullptr);
  EXPECT_EQ(sqlite3_step(s), SQLITE_DONE);  // every run's packing_id names a packing
  sqlite3_finalize(s);
  sqlite3_close(raw);
  // Opening again does nothing more.
  EXPECT_EQ(ResultsDb::open(path).run_count(), 2);
}

// A unit is (n, seed, method): a search chain of seed 7 is not the billiards run of seed 7, and
// each is recorded once.
TEST(Store, ASearchChainAndABilliardsRunOfOneSeedAreTwoUnits) {
  ResultsDb db = ResultsDb::open(fresh_path("methods.db"));
  EXPECT_TRUE(db.record(run_to_h3(7)));
  const RunRecord chain = run_to_h3(7, "search 30 s");
  EXPECT_FALSE(db.has_run(3, 7, chain.method));
  EXPECT_TRUE(db.record(chain));
  EXPECT_FALSE(db.record(chain));  // recorded once
  EXPECT_TRUE(db.has_run(3, 7, chain.method));
  EXPECT_EQ(db.finished_seeds(3), std::vector<std::uint64_t>{7});
  EXPECT_EQ(db.finished_seeds(3, chain.method), std::vector<std::uint64_t>{7});
  EXPECT_EQ(db.run_count(), 2);
  EXPECT_EQ(db.packings(3).at(0).runs, 2);  // both ended in it
  EXPECT_EQ(db.statistics().duplicate_runs, 0);
}

// Confirmations: every unit that started from nothing stored counts, a search
// continued from stored packings does not; the count survives into the packing record and
// into the best-per-n query (which reads the runs table through a derived table).
TEST(Store, ContinuedSearchesDoNotConfirmAPacking) {
  ResultsDb db = ResultsDb::open(fresh_path("confirm.db"));
  EXPECT_TRUE(db.record(run_to_h3(1)));
  EXPECT_TRUE(db.record(run_to_h3(2, "search 30 s")));
  EXPECT_TRUE(db.record(run_to_h3(3, "search 30 s, continued")));
  const StoredPacking stored = db.packings(3).at(0);
  EXPECT_EQ(stored.runs, 3);
  EXPECT_EQ(stored.independent_runs, 2);
  EXPECT_EQ(db.best_per_n().at(0).independent_runs, 2);
  PackingRecord record = record_of(stored);
  EXPECT_EQ(record.confirmations(), 2);
  // A builder giving the same packing counts once more, however many builders name it.
  record.sources.push_back({PackingSource::Kind::Builder, "hexagonal k=2"});
  record.sources.push_back({PackingSource::Kind::Builder, "matrix k=2 p=1"});
  EXPECT_EQ(record.confirmations(), 3);
}

TEST(Store, ImportedPackingsHaveNoSeedUntilARunFindsThem) {
  const std::string path = fresh_path("imported.db");
  ResultsDb db = ResultsDb::open(path);
  StoredPacking imported = packing(3, "0.75", "h3");
  imported.has_seed = false;
  imported.runs = 0;
  imported.origin = "import";
  imported.source = "t3a.txt";
  const auto first = db.add_packings({imported, packing(3, "0.5", "other")});
  ASSERT_EQ(first.size(), 2u);
  EXPECT_TRUE(first[0].added);
  EXPECT_TRUE(first[1].added);
  // The same packing again (d equal to 12 digits): recognised, nothing changed.
  imported.d = "0.750000000000000001";
  const auto again = db.add_packings({imported});
  ASSERT_EQ(again.size(), 1u);
  EXPECT_FALSE(again[0].added);
  EXPECT_EQ(again[0].id, first[0].id);
  auto three = db.packings(3);
  ASSERT_EQ(three.size(), 2u);
  EXPECT_EQ(three[0].d, "0.75");
  EXPECT_FALSE(three[0].has_seed);
  EXPECT_EQ(three[0].runs, 0);
  EXPECT_EQ(three[0].origin, "import");
  EXPECT_EQ(three[0].source, "t3a.txt");
  EXPECT_EQ(three[0].id, first[0].id);
  // A campaign run that ends in it counts there and gives it its first seed.
  EXPECT_TRUE(db.record(run(3, 9, packing(3, "0.75", "h3"))));
  three = db.packings(3);
  EXPECT_EQ(three[0].runs, 1);
  EXPECT_TRUE(three[0].has_seed);
  EXPECT_EQ(three[0].first_seed, 9u);
  EXPECT_EQ(three[0].origin, "import");
  const DbStatistics st = db.statistics();
  EXPECT_EQ(st.runs, 1);
  EXPECT_EQ(st.packings, 2);
  EXPECT_EQ(st.imported, 1);
  EXPECT_EQ(st.n_values, 1);
  EXPECT_EQ(st.duplicate_runs, 0);
  EXPECT_EQ(st.duplicate_packings, 0);
}

TEST(Store, StatisticsCountDuplicatesTheConstraintsWouldHaveStopped) {
  const std::string path = fresh_path("duplicates.db");
  {
    ResultsDb db = ResultsDb::open(path);
    db.record(run(4, 1, packing(4, "0.6", "h4")));
    db.record(run(4, 2, packing(4, "0.6", "h4")));
    db.record(run(5, 1, std::nullopt));
    const DbStatistics st = db.statistics();
    EXPECT_EQ(st.integrity, "ok");
    EXPECT_EQ(st.runs, 3);
    EXPECT_EQ(st.packings, 1);
    EXPECT_EQ(st.n_values, 2);
    EXPECT_EQ(st.duplicate_runs + st.duplicate_packings, 0);
  }
  // Tables rebuilt without their unique constraints, as a damaged or hand-edited file might be,
  // then a run and a packing recorded twice: the counts see them (GROUP BY, not the constraints).
  sqlite3* raw = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &raw), SQLITE_OK);
  const char* sql = R"sql(
CREATE TABLE runs_loose AS SELECT * FROM runs;
DROP TABLE runs;
ALTER TABLE runs_loose RENAME TO runs;
INSERT INTO runs SELECT * FROM runs WHERE n = 4 AND seed = 2;
CREATE TABLE packings_loose AS SELECT * FROM packings;
DROP TABLE packings;
ALTER TABLE packings_loose RENAME TO packings;
INSERT INTO packings SELECT id + 1, n, '0.6000000000001', d_key || 'x', d_value, graph_hash, points,
  bonds, rattlers, certified, first_seed, runs, origin, source, tool_version FROM packings;
)sql";
  ASSERT_EQ(sqlite3_exec(raw, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(raw);
  sqlite3_close(raw);
  const DbStatistics st = ResultsDb::open(path).statistics();
  EXPECT_EQ(st.runs, 4);
  EXPECT_EQ(st.duplicate_runs, 1);
  EXPECT_EQ(st.packings, 2);
  EXPECT_EQ(st.duplicate_packings, 1);  // d equal to 12 digits though its d_key was changed
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
