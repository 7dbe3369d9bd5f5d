// The explorer's data: the values behind the delta(n) plot against closed forms, and
// every written packing file re-analysed passes the certificate its row claims.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"
#include "jobs/explore.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/explore_report.hpp"

namespace tripack {
namespace {

namespace fs = std::filesystem;

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

// A small exploration (seconds): class members up to 60, billiards up to n = 12.
const jobs::ExploreResult& small_exploration() {
  static const jobs::ExploreResult result = [] {
    jobs::ExploreSettings s;
    s.max_n = 60;
    s.billiards_max_n = 12;
    s.class_billiards_max_n = 16;
    s.stress_set.clear();
    s.large_terms.clear();
    s.search_steps = 6;
    s.accuracy = false;  // tests/unit/test_accuracy.cpp covers it
    return jobs::explore(catalogue(), s);
  }();
  return result;
}

double delta_of(const PackingRecord& r) {
  return static_cast<double>(oler_delta(r.n(), 1 / r.pattern.packing.d));
}

TEST(Explore, DeltaOfTriangularNumbersIsZero) {
  // Oler 1961: d(Delta(k)) = 1/(k-1), so L = k - 1 = t(Delta(k)) and delta = 0.
  int seen = 0;
  for (const auto& r : small_exploration().packings)
    if (r.from_builder() && r.pattern.provenance.class_id == "hexagonal") {
      EXPECT_NEAR(delta_of(r), 0.0, 1e-13) << r.n();  // ~100 ulps of L <= 10
      EXPECT_TRUE(r.proven_optimal);
      ++seen;
    }
  EXPECT_GE(seen, 9);  // Delta(2..10) <= 60
}

// n <= 15 are proven optima (GL1995 sec. 1), but only the best packing of such an n is one: at
// n = 13 the sparse-corner member (k = 3) is a local optimum below sparse-rows' t13a.
TEST(Explore, OnlyTheBestPackingOfAProvenNIsMarkedProven) {
  int at13 = 0;
  for (const auto& r : small_exploration().packings)
    if (r.n() == 13 && r.from_builder()) {
      // vacancy-segment k=3 p=2 (Delta(5) minus a divacancy, relaxed) is t13a too.
      EXPECT_EQ(r.proven_optimal, r.pattern.provenance.class_id == "sparse-rows" ||
                                      r.pattern.provenance.class_id == "vacancy-segment")
          << r.pattern.provenance.class_id;
      ++at13;
    }
  EXPECT_GE(at13, 2);
}

TEST(Explore, DeltaOfFourDeltaDecreasesToSqrt3MinusThreeHalvesAsOneOverK) {
  // GL1995: L(4Delta(k)) = 2k - 2 + sqrt3; with t(2k(k+1)) = (-3 + sqrt(16k^2 + 16k + 1)) / 2,
  // delta - (sqrt3 - 3/2) = 2k + 1/2 - sqrt(16k^2+16k+1)/2 = 3 / (2 (4k + 2 + sqrt(16k^2+16k+1))),
  // which lies between 3/(16k + 8) and 3/(16k + 4): decreasing, O(1/k).
  const double limit = std::sqrt(3.0) - 1.5;
  std::map<long, double> delta_by_k;
  for (const auto& r : small_exploration().packings)
    if (r.from_builder() && r.pattern.provenance.class_id == "four-delta")
      delta_by_k[r.pattern.provenance.k] = delta_of(r);
  ASSERT_GE(delta_by_k.size(), 5u);  // 4Delta(k) <= 60: k = 1..5
  double previous = 1e9;
  for (const auto& [k, delta] : delta_by_k) {
    const double excess = delta - limit;
    EXPECT_GT(excess, 3.0 / (16 * k + 8) - 1e-13) << k;
    EXPECT_LT(excess, 3.0 / (16 * k + 4) + 1e-13) << k;
    EXPECT_LT(delta, previous) << k;
    previous = delta;
  }
}

TEST(Explore, EveryWrittenPackingPassesTheCertificateItsRowClaims) {
  const auto& result = small_exploration();
  const fs::path dir = fs::temp_directory_path() / "tripack_explore_test";
  fs::remove_all(dir);
  report::write_explore_report(result, dir, {false, false});
  // packings.csv: one row per packing, the file column names a file that exists.
  std::ifstream csv(dir / "packings.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "n,rank,label,class,p,k,variant,d,L,delta,bonds,rattlers,certified,source,"
            "seconds,file");
  std::size_t rows = 0, certified = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    ASSERT_EQ(f.size(), 16u) << line;
    const auto& row = result.packings[rows++];
    const PointsFile file = read_packing_file((dir / f[15]).string());
    const Packing start = packing_from_points(file, std::nullopt, std::stoll(f[0])).packing;
    const pipeline::Analysis a = pipeline::analyze_packing(start, {});
    // d is printed with 17 digits; the re-analysis polishes again from 21-digit coordinates.
    EXPECT_NEAR(static_cast<double>(a.pattern.packing.d / std::stold(f[7]) - 1), 0.0, 1e-14)
        << line;
    if (f[12] == "true") {
      ++certified;
      EXPECT_TRUE(a.certified()) << line;
      EXPECT_EQ(a.pattern.bonds.size(), std::stoul(f[10])) << line;
      EXPECT_EQ(a.pattern.rattlers.size(), std::stoul(f[11])) << line;
    }
    EXPECT_EQ(f[13], row.origin());
  }
  EXPECT_EQ(rows, result.packings.size());
  EXPECT_GT(certified, rows / 2);
  EXPECT_TRUE(fs::exists(dir / "index.html"));
  fs::remove_all(dir);
}

TEST(Explore, ACancelledExplorationSaysSoAndKeepsWhatFinished) {
  jobs::ExploreSettings s;
  s.max_n = 30;
  s.stress_set.clear();
  s.large_terms.clear();
  s.accuracy = false;
  s.threads = 1;  // one item at a time: none is under way when the token is set
  CancelToken cancel;
  int finished = 0;
  const auto progress = [&](const Progress& p) {
    if (p.item_finished && ++finished == 5) cancel.cancel();  // as Ctrl-C would, during the builds
  };
  const auto result = jobs::explore(catalogue(), s, {&cancel, progress, ""});
  EXPECT_TRUE(result.cancelled);
  EXPECT_TRUE(result.stages_done.empty());
  // The token is read between items: the fifth build had finished when it was set, and nothing
  // after it starts.
  EXPECT_EQ(result.packings.size(), 5u);
}

// The explorer's member list scans k and p like Catalogue::classify: a class whose n does not grow
// (fuzz/findings/fuzz_catalogue/timeout-n-not-growing.yaml) is a CatalogueError, not an endless
// loop filling memory; the real catalogue's members are all listed.
TEST(Explore, ClassMembersOfAClassWhoseNDoesNotGrowAreACatalogueError) {
  const Catalogue flat = Catalogue::parse(
      "classes:\n  - {id: flat, display: F, n: 'Delta(p)', k_min: 2, builder: {name: x}}\n");
  EXPECT_THROW(pipeline::class_members_up_to(flat, 60), CatalogueError);
  const Catalogue shrinking =
      Catalogue::parse("classes:\n  - {id: s, display: S, n: '50-k', builder: {name: x}}\n");
  EXPECT_THROW(pipeline::class_members_up_to(shrinking, 60), CatalogueError);
  const auto members = pipeline::class_members_up_to(catalogue(), 60);
  EXPECT_FALSE(members.empty());
  for (const auto& m : members)
    EXPECT_LE(catalogue().n_of(catalogue().find(m.class_id), m.k, m.p), 60) << m.class_id;
}

}  // namespace
}  // namespace tripack
