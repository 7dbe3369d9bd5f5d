// campaign/import and campaign/stored: `tripack db import` and `db export`. Export and
// import are inverse (same d to the 18 stored digits, same contact-graph hash, no duplicate
// row); every format and convention reads back through the file reader; built class members
// certify on import with their closed-form d; overlapping, malformed and uncertified files are
// refused with the database untouched.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/io.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"
#include "jobs/campaign.hpp"
#include "jobs/import.hpp"
#include "jobs/stored.hpp"
#include "pipeline/build.hpp"

namespace tripack::jobs {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const auto dir = fs::temp_directory_path() / ("tripack_import_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir;
}

std::string fresh_db(const std::string& name) {
  const std::string path = (scratch() / name).string();
  for (const char* suffix : {"", "-wal", "-shm"}) fs::remove(path + suffix);
  return path;
}

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

// A class member as built (polished with its builder's bonds), written as a unit-triangle file.
std::string built_file(const std::string& class_id, long k, const std::string& name) {
  const auto built = pipeline::build_and_certify(catalogue(), {class_id, k, 0, ""}, {});
  const std::string path = (scratch() / name).string();
  std::ofstream(path) << [&] {
    std::ostringstream s;
    write_text(s, built.pattern);
    return s.str();
  }();
  return path;
}

ImportResult import_files(const std::vector<std::string>& files, const std::string& db) {
  ImportRequest request;
  request.files = files;
  request.db = db;
  return import_packings(request, {nullptr, {}, "test"});
}

// Every row of both tables in a fixed order, as one string: equal strings, equal databases.
std::string rows_of(const std::string& db) {
  sqlite3* raw = nullptr;
  EXPECT_EQ(sqlite3_open(db.c_str(), &raw), SQLITE_OK);
  std::string all;
  for (const char* sql :
       {"SELECT * FROM packings ORDER BY id", "SELECT * FROM runs ORDER BY n, seed",
        "SELECT * FROM meta ORDER BY key"}) {
    sqlite3_stmt* s = nullptr;
    EXPECT_EQ(sqlite3_prepare_v2(raw, sql, -1, &s, nullptr), SQLITE_OK);
    while (sqlite3_step(s) == SQLITE_ROW) {
      for (int c = 0; c < sqlite3_column_count(s); ++c) {
        const auto* text = sqlite3_column_text(s, c);
        all += text ? reinterpret_cast<const char*>(text) : "NULL";
        all += '|';
      }
      all += '\n';
    }
    sqlite3_finalize(s);
  }
  sqlite3_close(raw);
  return all;
}

// A small campaign's database: billiards-found packings of n = 10..12, with rattlers and shared
// ranks, as `tripack campaign` records them.
std::string campaign_db(const std::string& name) {
  CampaignRequest request;
  request.n_first = 10;
  request.n_last = 12;
  request.runs = 4;
  request.threads = 2;
  request.db = fresh_db(name);
  run_campaign(request, ThreadExecutor(request.threads), {});
  return request.db;
}

// `tripack db export N --rank R --format F --convention C -o FILE`.
std::string exported(const std::string& db, long long n, long long rank, const std::string& format,
                     const std::string& convention) {
  jobs::DbExport o;
  o.db = db;
  o.n = n;
  o.rank = rank;
  o.format = format;
  o.convention = convention;
  const std::string ext = format == "records" ? "pck" : format;
  o.output = (scratch() / fmt::format("t{}.{}.{}.{}", n, rank, convention, ext)).string();
  std::ostringstream paths;
  jobs::export_packings(o, paths);
  return o.output;
}

TEST(Import, ExportThenImportIsTheSamePacking) {
  const std::string db = campaign_db("roundtrip.db");
  const std::string copy = fresh_db("roundtrip-copy.db");
  int checked = 0;
  for (long long n = 10; n <= 12; ++n) {
    std::vector<long long> ids;
    const auto ranked = ranked_packings(store::ResultsDb::open(db), n, &ids);
    ASSERT_FALSE(ranked.empty());
    for (const auto& r : ranked) {
      for (const std::string format : {"txt", "records"}) {
        const std::string file =
            exported(db, n, static_cast<long long>(r.rank), format, "unit-triangle");
        // Into a fresh database: the same d to the 18 stored digits, the same contact graph.
        const auto fresh = import_files({file}, copy);
        ASSERT_EQ(fresh.packings.size(), 1u);
        const auto& x = fresh.packings[0];
        EXPECT_EQ(x.d, r.d.str(kLongDoubleDigits)) << file;
        EXPECT_EQ(x.graph_hash, r.graph_hash) << file;
        EXPECT_EQ(x.n, n);
        // Into the database it came from: recognised, no new row, nothing changed.
        const std::string before = rows_of(db);
        const auto again = import_files({file}, db);
        EXPECT_FALSE(again.packings[0].added) << file;
        EXPECT_EQ(again.packings[0].id, ids[static_cast<std::size_t>(r.rank - 1)]) << file;
        EXPECT_EQ(again.packings[0].label, r.label) << file;
        EXPECT_EQ(rows_of(db), before) << file;
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 6);
  // The copy holds each packing once, labelled as in the original.
  const store::ResultsDb original = store::ResultsDb::open(db),
                         imported = store::ResultsDb::open(copy);
  for (long long n = 10; n <= 12; ++n) {
    const auto a = ranked_packings(original, n), b = ranked_packings(imported, n);
    ASSERT_EQ(a.size(), b.size()) << "n = " << n;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].label, b[i].label);
      EXPECT_EQ(b[i].origin(), "import");
      EXPECT_FALSE(b[i].has_seed());
      EXPECT_EQ(b[i].sources.front().name.rfind(fmt::format("t{}.", n), 0), 0u);  // the file
    }
  }
  const auto stats = imported.statistics();
  EXPECT_EQ(stats.duplicate_packings, 0);
  EXPECT_EQ(stats.runs, 0);
}

TEST(Import, EveryFormatAndConventionReadsBackToTheSamePoints) {
  const std::string db = campaign_db("conventions.db");
  const auto best = ranked_packings(store::ResultsDb::open(db), 12).front();
  const auto& want = best.pattern.packing.points;
  for (const std::string format : {"txt", "csv", "json", "records"})
    for (const std::string convention : {"unit-triangle", "radius", "unit-disk-side"}) {
      const std::string file = exported(db, 12, 1, format, convention);
      // The file's own convention line is enough; naming it explicitly gives the same.
      for (const bool explicitly : {false, true}) {
        const auto c = explicitly ? parse_convention(convention) : std::nullopt;
        const PointsReading reading = packing_from_points(read_packing_file(file), c, 12);
        EXPECT_EQ(reading.convention, *parse_convention(convention)) << file;
        ASSERT_EQ(reading.packing.points.size(), want.size()) << file;
        long double worst = 0;
        for (std::size_t i = 0; i < want.size(); ++i)
          worst = std::max(worst, norm(reading.packing.points[i] - want[i]));
        // Lengths relative to the unit triangle's side.
        EXPECT_LT(worst, 1e-15L) << file << ": " << static_cast<double>(worst);
        EXPECT_LT(std::fabs(reading.packing.d / best.d.value() - 1), 1e-15L) << file;
      }
    }
}

TEST(Import, BuiltClassMembersCertifyWithTheirClosedFormD) {
  const std::string db = fresh_db("built.db");
  // Oler 1961 (classes.yaml, hexagonal): d(Delta(k)) = 1/(k-1); Delta(6) = 21, Delta(10) = 55.
  // docs/classes.md (classes.yaml, even-ripple k = 3): d(22) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11).
  const long double sqrt3 = std::sqrt(3.0L);
  struct Case {
    std::string class_id;
    long k;
    long long n;
    long double d;
  };
  for (const Case& c :
       {Case{"hexagonal", 6, 21, 1.0L / 5}, Case{"hexagonal", 10, 55, 1.0L / 9},
        Case{"even-ripple", 3, 22, 5 * sqrt3 / (20 * sqrt3 + 7 + 2 * std::sqrt(11.0L))}}) {
    const std::string file = built_file(c.class_id, c.k, c.class_id + std::to_string(c.k) + ".txt");
    const auto result = import_files({file}, db);
    ASSERT_EQ(result.packings.size(), 1u);
    const auto& x = result.packings[0];
    EXPECT_TRUE(x.added);
    EXPECT_EQ(x.n, c.n);
    EXPECT_LT(std::fabs(std::stold(x.d) / c.d - 1), 1e-17L)
        << c.class_id << " k=" << c.k << ": " << x.d;
    EXPECT_EQ(x.label, "t" + std::to_string(c.n) + "a");
    EXPECT_NE(x.verdict.find("certified"), std::string::npos);
  }
  const auto t22 = ranked_packings(store::ResultsDb::open(db), 22);
  ASSERT_EQ(t22.size(), 1u);
  EXPECT_EQ(t22[0].bonds(), 47u);  // GL1995 Fig.t22: 47 bonds, 2 rattlers
  EXPECT_EQ(t22[0].rattlers(), 2u);
  EXPECT_EQ(t22[0].sources.front().name, "even-ripple3.txt");
}

// Delta(6) with disk `moved` shifted by `shift` (in units of d) towards disk `towards`; the
// header keeps d = 0.2.
std::string hexagon_with_moved_disk(const std::string& name, double shift) {
  const auto built = pipeline::build_and_certify(catalogue(), {"hexagonal", 6, 0, ""}, {});
  Pattern p = built.pattern;
  // The closest pair to disk 10 (an interior disk of Delta(6)) gives the direction.
  std::size_t moved = 10, towards = 0;
  long double closest = 10;
  for (std::size_t j = 0; j < p.packing.size(); ++j)
    if (j != moved && norm(p.packing.points[j] - p.packing.points[moved]) < closest) {
      closest = norm(p.packing.points[j] - p.packing.points[moved]);
      towards = j;
    }
  const Vec2L dir = (p.packing.points[towards] - p.packing.points[moved]) / closest;
  p.packing.points[moved] += dir * (static_cast<long double>(shift) * p.packing.d);
  const std::string path = (scratch() / name).string();
  std::ofstream(path) << [&] {
    std::ostringstream s;
    write_text(s, p);
    return s.str();
  }();
  return path;
}

TEST(Import, AnOverlappingFileIsRefusedAndTheDatabaseUnchanged) {
  const std::string db = campaign_db("overlap.db");
  const std::string before = rows_of(db);
  const std::string good = built_file("hexagonal", 6, "t21.txt");
  // A disk moved 30% of d towards its neighbour: the header's d = 0.2 is not the points' d.
  const std::string moved = hexagon_with_moved_disk("t21-overlap.txt", 0.3);
  // A header claiming more than the points have (the same points as the good file).
  const std::string claimed = (scratch() / "t21-claims.txt").string();
  {
    std::ifstream in(good);
    std::ofstream out(claimed);
    for (std::string line; std::getline(in, line);)
      out << (line.rfind("# d:", 0) == 0 ? "# d: 0.2000001" : line) << "\n";
  }
  // Circles of radius r whose centres are closer than 2r.
  const std::string circles = (scratch() / "t21-circles.txt").string();
  {
    const auto built = pipeline::build_and_certify(catalogue(), {"hexagonal", 6, 0, ""}, {});
    std::ofstream out(circles);
    for (const auto& q : built.pattern.packing.points)
      out << format_significant(q.x, 21) << ' ' << format_significant(q.y, 21) << " 0.11\n";
  }
  for (const auto& bad : {moved, claimed, circles}) {
    try {
      import_files({good, bad}, db);  // the good file first: it must not be stored either
      ADD_FAILURE() << "imported " << bad;
    } catch (const ImportError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("overlapping disks"), std::string::npos) << message;
      EXPECT_NE(message.find(bad), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(rows_of(db), before) << bad;
  }
  // The moved disk without the header's claim is a start like any other: relaxed and certified
  // as `analyze` does it, stored with the certified d (Delta(6) again: d = 1/5, Oler 1961).
  const std::string unclaimed = (scratch() / "t21-unclaimed.txt").string();
  {
    std::ifstream in(moved);
    std::ofstream out(unclaimed);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("# d:", 0) != 0) out << line << "\n";
  }
  const auto relaxed = import_files({unclaimed}, db);
  ASSERT_EQ(relaxed.packings.size(), 1u);
  EXPECT_TRUE(relaxed.packings[0].added);
  EXPECT_LT(std::stold(relaxed.packings[0].d_file), 0.2L * 0.75L);
  EXPECT_LT(std::fabs(std::stold(relaxed.packings[0].d) / 0.2L - 1), 1e-17L);
}

TEST(Import, MalformedUncertifiedAndMissingFilesAreRefusedWithOneLine) {
  const std::string db = campaign_db("refused.db");
  const std::string before = rows_of(db);
  const std::string malformed = (scratch() / "malformed.txt").string();
  std::ofstream(malformed) << "0.1 0.1\n0.5 abc\n0.9 0.05\n";
  const std::string coincide = (scratch() / "coincide.txt").string();
  std::ofstream(coincide) << "0.1 0.1\n0.1 0.1\n0.9 0.05\n";
  // sparse-rows k = 9 (n = 64): its smallest contact force is below what the LPs resolve, so it
  // is reported not certified (README, known limits).
  const std::string uncertified = built_file("sparse-rows", 9, "sparse-rows9.txt");
  struct Case {
    std::string file, needle;
  };
  for (const Case& c : {Case{malformed, "line 2: 'abc' is not a number"},
                        Case{coincide, "coincide"}, Case{uncertified, "not certified"},
                        Case{(scratch() / "nonexistent.txt").string(), "cannot read"}}) {
    try {
      import_files({c.file}, db);
      ADD_FAILURE() << "imported " << c.file;
    } catch (const ImportError& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find(c.needle), std::string::npos) << message;
      EXPECT_NE(message.find(c.file), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
    EXPECT_EQ(rows_of(db), before) << c.file;
  }
  // Nothing is created for a refused import into a database that did not exist.
  const std::string none = fresh_db("never.db");
  EXPECT_THROW(import_files({malformed}, none), ImportError);
  EXPECT_FALSE(fs::exists(none));
}

TEST(Import, ExportSelectsByRankAndRefusesWhatIsNotThere) {
  const std::string db = campaign_db("select.db");
  const auto all = select_packings(db, 12, 1, true);
  ASSERT_GE(all.size(), 2u);
  EXPECT_EQ(all[0].label, "t12a");
  for (std::size_t i = 0; i < all.size(); ++i) {
    EXPECT_EQ(all[i].rank, i + 1);
    const auto one = select_packings(db, 12, static_cast<long long>(i + 1), false);
    ASSERT_EQ(one.size(), 1u);
    EXPECT_EQ(one[0].pattern.packing.points, all[i].pattern.packing.points);
    EXPECT_EQ(one[0].graph_hash, all[i].graph_hash);
    if (i > 0) {
      EXPECT_GE(all[i - 1].d.value(), all[i].d.value());
    }
  }
  EXPECT_THROW(select_packings(db, 12, static_cast<long long>(all.size()) + 1, false),
               std::invalid_argument);
  EXPECT_THROW(select_packings(db, 0, 1, false), std::invalid_argument);
  EXPECT_THROW(select_packings(db, 40, 1, false), std::invalid_argument);
  const std::string missing = fresh_db("missing.db");
  EXPECT_THROW(select_packings(missing, 12, 1, false), store::StoreError);
  EXPECT_FALSE(fs::exists(missing));
  // The labels are the billiards runs': the best of n is tNa; check sees no duplicates.
  const auto table = best_table(db, 10, 12);
  ASSERT_EQ(table.rows.size(), 3u);
  for (const auto& r : table.rows) EXPECT_EQ(r.label, "t" + std::to_string(r.n()) + "a");
  const auto check = check_database(db);
  EXPECT_TRUE(check.ok());
  EXPECT_EQ(check.stats.runs, 12);
  EXPECT_EQ(check.stats.n_values, 3);
}

}  // namespace
}  // namespace tripack::jobs
