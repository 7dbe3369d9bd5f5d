// constructors/sparse_corner.cpp: Delta(k+2)-2, the sparse corner (GL1995's t43a; docs/class6.md),
// against the packings billiards finds at n = 26, 34, 43, 53, 64 (k = 5..9).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "analysis/compare.hpp"
#include "constructors/builders.hpp"
#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/io.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"
#include "pipeline/analyze.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack {
namespace {

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

Pattern built(long k) {
  return build_pattern(catalogue(), {"sparse-corner", k, 0, ""});
}

long double rel(long double a, long double b) {
  return std::fabs(a / b - 1);
}

// The sparse-corner packing billiards found at each k: the end state of one run of
// scenes/class6/nN-c0.01.yaml, certified by the analysis (relax, bonds, rigidity, stress) and
// written with 21 digits by
//   tripack billiards --scene scenes/class6/nN-c0.01.yaml --runs 1 --seed S -o DIR --format txt
// (docs/class6/LABEL.txt). d is that file's "# d:" line. Labels are the ranks among all distinct
// packings found at that n (docs/class6.md): the pattern is t26b, t34c, t43a, t53b, t64a.
struct Found {
  long k;
  long long n;
  const char* label;
  unsigned seed;
  long double d;
};
constexpr Found kFound[] = {
    {5, 26, "t26b", 5, 0.166732017260692369338L},   {6, 34, "t34c", 97, 0.142866887845830922132L},
    {7, 43, "t43a", 11, 0.125004280307976895335L},  {8, 53, "t53b", 109, 0.111111573143909637899L},
    {9, 64, "t64a", 110, 0.100000214022275315791L},
};

std::string found_file(const Found& f) {
  return std::string(TRIPACK_SOURCE_DIR) + "/docs/class6/" + f.label + ".txt";
}

pipeline::Analysis analysed(const Packing& p) {
  return pipeline::analyze_packing(p, {});
}

TEST(SparseCorner, DEqualsTheBilliardsPackingsAtK5To9) {
  // Both are long double polishes of the same contact system (they agree to ~3e-19 relative);
  // 1e-16 leaves a margin of ~300 and is 1e8 times finer than the gap to the next packing at
  // any of these n (t53b vs t53c: 2.3e-8 relative).
  for (const Found& f : kFound) {
    const Pattern p = built(f.k);
    EXPECT_EQ(static_cast<long long>(p.packing.size()), f.n);
    EXPECT_LT(rel(p.packing.d, f.d), 1e-16L)
        << f.label << ": built " << static_cast<double>(p.packing.d);
  }
}

TEST(SparseCorner, SameContactGraphAsTheBilliardsPackings) {
  // The stored billiards end states (docs/class6/*.txt), certified anew, are the built packings:
  // same d, and one symmetry of the triangle maps points and bonds onto each other.
  for (const Found& f : kFound) {
    const PointsReading reading = packing_from_points(read_packing_file(found_file(f)), {}, f.n);
    const pipeline::Analysis a = analysed(reading.packing);
    ASSERT_TRUE(a.certified()) << f.label << ": " << a.status();
    const Comparison cmp = compare_packings(built(f.k), a.pattern);
    EXPECT_TRUE(cmp.same) << f.label << ": " << cmp.reason;
  }
}

TEST(SparseCorner, TheDocumentedSeedsReachIt) {
  // The runs behind t43a and t64a, repeated from their scenes and seeds (one run each).
  for (const Found& f : {kFound[2], kFound[4]}) {
    const Scene scene = load_scene(std::string(TRIPACK_SOURCE_DIR) + "/scenes/class6/n" +
                                   std::to_string(f.n) + "-c0.01.yaml");
    std::mt19937_64 rng(f.seed);
    const BilliardsResult run = run_billiards(scene, rng);
    const pipeline::Analysis a = analysed(run.packing);
    ASSERT_TRUE(a.certified()) << f.label << ": " << a.status();
    EXPECT_TRUE(compare_packings(built(f.k), a.pattern).same) << f.label;
    EXPECT_LT(rel(a.pattern.packing.d, f.d), 1e-16L) << f.label;
  }
}

TEST(SparseCorner, BondsRattlersAndCertificateForK3To13) {
  // 3 Delta(k+1) bonds (the catalogue's formula; the same count as sparse-rows), no rattlers,
  // and the analysis of the built points alone finds exactly these bonds and certifies them
  // (rigid, strictly positive stress). From k = 14 the smallest stress (1e-11) is below what
  // the certificate resolves.
  const ClassInfo& c = catalogue().find("sparse-corner");
  for (long k = 3; k <= 13; ++k) {
    const Pattern p = built(k);
    const auto n = catalogue().n_of(c, k, 0);
    EXPECT_EQ(static_cast<long long>(p.packing.size()), n) << k;
    EXPECT_EQ(n, triangular(k + 2) - 2) << k;
    EXPECT_EQ(static_cast<long long>(p.bonds.size()), 3 * triangular(k + 1)) << k;
    EXPECT_EQ(static_cast<long long>(p.bonds.size()), *catalogue().bonds_of(c, k, 0, "")) << k;
    EXPECT_TRUE(p.rattlers.empty()) << k;
    EXPECT_EQ(*catalogue().rattlers_of(c, k, 0, ""), 0) << k;
    const pipeline::Analysis a = analysed(p.packing);
    EXPECT_TRUE(a.certified()) << k << ": " << a.status();
    EXPECT_EQ(a.pattern.bonds, p.bonds) << k;
    EXPECT_LT(rel(a.pattern.packing.d, p.packing.d), 1e-15L) << k;
  }
}

TEST(SparseCorner, AgreesWithAnIndependentHighPrecisionSolution) {
  // The same model solved separately in mpmath at 80 digits (the contact equations written
  // from the description in docs/class6.md, shooting on tau): d to 20 digits.
  const std::pair<long, long double> model[] = {
      {5, 0.16673201726069236938L},  {6, 0.14286688784583092213L}, {7, 0.12500428030797689553L},
      {8, 0.1111115731439096379L},   {9, 0.1000002140222753158L},  {10, 0.090909101042684579712L},
      {12, 0.076923076973756499202L}};
  for (const auto& [k, d] : model) EXPECT_LT(rel(built(k).packing.d, d), 1e-17L) << k;
}

TEST(SparseCorner, BeatsSparseRowsFromK5AndLosesBelow) {
  // t13a and t19a (k = 3, 4) are the sparse-rows pattern; from k = 5 on the sparse corner is
  // denser (both are 1/(k+1) + O(delta), delta -> 0 super-exponentially).
  for (long k = 3; k <= 9; ++k) {
    const long double corner = built(k).packing.d;
    const long double rows = build_pattern(catalogue(), {"sparse-rows", k, 0, ""}).packing.d;
    if (k <= 4)
      EXPECT_LT(corner, rows) << k;
    else
      EXPECT_GT(corner, rows) << k;
  }
}

TEST(SparseCorner, RangeAndValidity) {
  // Built with exactly its intended contacts up to k = 17; at k = 18 the cracks' gaps (~1e-11
  // disk units) are below the bond tolerance, so the catalogue stops at 17.
  EXPECT_THROW(build_sparse_corner(2), std::invalid_argument);
  const ClassInfo& c = catalogue().find("sparse-corner");
  EXPECT_THROW(catalogue().check_parameters(c, 18, 0), CatalogueError);
  const Pattern p = built(17);
  EXPECT_EQ(p.packing.size(), static_cast<std::size_t>(triangular(19) - 2));
  EXPECT_EQ(static_cast<long long>(p.bonds.size()), 3 * triangular(18));
  EXPECT_GT(p.packing.d, 1.0L / 18);
}

}  // namespace
}  // namespace tripack
