// analysis/sqrt3_check and the builders' exact Q(sqrt3) coordinates (Pattern::sqrt3): the closed
// forms of docs/classes.md §1-§3 verified without rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <regex>
#include <stdexcept>

#include "analysis/sqrt3_check.hpp"
#include "constructors/builders.hpp"

namespace tripack {
namespace {

// The failure message names disk i: "disk i", "disks i and j", "and i:", "bond i-j", "-i:".
bool names_disk(const std::string& failure, long i) {
  const std::string id = std::to_string(i);
  return std::regex_search(failure,
                           std::regex("(disks? |bond |and )" + id + "[^0-9.]|-" + id + ":"));
}

std::size_t count_known(const Pattern& pat) {
  return static_cast<std::size_t>(std::count(pat.sqrt3->known.begin(), pat.sqrt3->known.end(), 1));
}

void expect_sqrt3_ok(const Pattern& pat, std::size_t bonds, const std::string& what) {
  ASSERT_TRUE(pat.sqrt3.has_value()) << what;
  const Sqrt3CheckReport rep = sqrt3_check(pat);
  EXPECT_TRUE(rep.ok) << what << ": " << rep.failure;
  EXPECT_EQ(rep.failure, "") << what;
  EXPECT_EQ(rep.bonds_checked, bonds) << what;
  EXPECT_EQ(pat.bonds.size(), bonds) << what;
  // At least every side without a wall bond of every disk is a verified gap.
  std::size_t wall_bonds = 0;
  for (const Bond& b : pat.bonds) wall_bonds += b.is_wall() ? 1 : 0;
  EXPECT_GE(rep.gaps_checked, 3 * pat.packing.size() - wall_bonds) << what;
}

TEST(Sqrt3Check, FourDeltaKUpTo20) {
  // GL1995 Sec.5: d(4Delta(k)) = 1/(2k - 2 + sqrt3), so L = (p + q sqrt3)/2 with p = 4k - 4,
  // q = 2, exactly; bonds 6k^2 + 3k (docs/classes.md §2; paper: t24a 63, t40a 108).
  for (long k = 1; k <= 20; ++k) {
    const Pattern pat = build_four_delta(k);
    ASSERT_TRUE(pat.sqrt3.has_value()) << k;
    EXPECT_EQ(pat.sqrt3->L, (HalfSurd3{4 * k - 4, 2})) << k;
    EXPECT_EQ(pat.sqrt3->points.size(), pat.packing.size()) << k;
    EXPECT_EQ(count_known(pat), pat.packing.size()) << k;  // no rattlers
    expect_sqrt3_ok(pat, static_cast<std::size_t>(6 * k * k + 3 * k),
                    "4Delta(" + std::to_string(k) + ")");
  }
}

TEST(Sqrt3Check, TwinEveryVariant) {
  // GL1995 Sec.5 / docs/classes.md §3: L = 2k - 1 + sqrt3 for all k+1 packings. Bonds: rattler
  // 6k^2 + 9k - 2 (t7a13, t17a40, t31a79), cavity-m 6k^2 + 9k (t31a81.1, .2), full 6k^2 + 9k + 1
  // (t7a16, t17a43, t31a82).
  for (long k = 1; k <= 6; ++k) {
    for (long m = 0; m <= k; ++m) {
      const std::string what = "twin k=" + std::to_string(k) + " cavity=" + std::to_string(m);
      const Pattern pat = build_twin(k, m);
      ASSERT_TRUE(pat.sqrt3.has_value()) << what;
      EXPECT_EQ(pat.sqrt3->L, (HalfSurd3{4 * k - 2, 2})) << what;
      const long bonds = m == 0  ? 6 * k * k + 9 * k - 2
                         : m < k ? 6 * k * k + 9 * k
                                 : 6 * k * k + 9 * k + 1;
      if (m == 0) {
        // The rattler is centred in its cage numerically: it alone is not known exactly.
        ASSERT_EQ(pat.rattlers.size(), 1u) << what;
        EXPECT_EQ(pat.sqrt3->known[static_cast<std::size_t>(pat.rattlers[0])], 0) << what;
        EXPECT_EQ(count_known(pat), pat.packing.size() - 1) << what;
      } else {
        EXPECT_TRUE(pat.rattlers.empty()) << what;
        EXPECT_EQ(count_known(pat), pat.packing.size()) << what;
      }
      expect_sqrt3_ok(pat, static_cast<std::size_t>(bonds), what);
    }
  }
}

TEST(Sqrt3Check, HexagonalAndMinusOne) {
  // Oler 1961: L(Delta(k)) = k - 1, 3k(k-1)/2 disk bonds and 3k wall bonds (docs/classes.md §1).
  // Delta(k) - 1 loses the corner's 2 disk bonds and 2 wall bonds.
  for (long k = 2; k <= 12; ++k) {
    const Pattern full = build_hexagonal(k);
    ASSERT_TRUE(full.sqrt3.has_value()) << k;
    EXPECT_EQ(full.sqrt3->L, HalfSurd3::integer(k - 1)) << k;
    expect_sqrt3_ok(full, static_cast<std::size_t>(3 * k * (k - 1) / 2 + 3 * k),
                    "Delta(" + std::to_string(k) + ")");
    const Pattern minus = build_hexagonal_minus_one(k);
    ASSERT_TRUE(minus.sqrt3.has_value()) << k;
    EXPECT_EQ(minus.sqrt3->points.size(), static_cast<std::size_t>(triangular(k) - 1)) << k;
    expect_sqrt3_ok(minus, static_cast<std::size_t>(3 * k * (k - 1) / 2 + 3 * k - 4),
                    "Delta(" + std::to_string(k) + ")-1");
  }
}

TEST(Sqrt3Check, TinySqrt3MoveBreaksABond) {
  // 708158977 - 408855776 sqrt3 = 1/(708158977 + 408855776 sqrt3) ~ 7.1e-10 (a Pell pair,
  // x^2 - 3y^2 = 1): the disk moves by 3.5e-10, below any long double tolerance of the
  // check's consistency test, yet its bonds are no longer exactly 1.
  Pattern pat = build_four_delta(4);
  const int i = 17;
  pat.sqrt3->points[i].x = pat.sqrt3->points[i].x + HalfSurd3{708158977, -408855776};
  const Sqrt3CheckReport rep = sqrt3_check(pat);
  EXPECT_FALSE(rep.ok);
  EXPECT_TRUE(names_disk(rep.failure, i)) << rep.failure;
  EXPECT_NE(rep.failure.find("not exactly 0"), std::string::npos) << rep.failure;
}

TEST(Sqrt3Check, Sqrt3DataThatDisagreeWithThePacking) {
  // p += 1 moves the disk by 1/2: the exact data no longer describe the packing.
  Pattern pat = build_twin(3, 2);
  const int i = 30;
  pat.sqrt3->points[i].y.p += 1;
  const Sqrt3CheckReport rep = sqrt3_check(pat);
  EXPECT_FALSE(rep.ok);
  EXPECT_TRUE(names_disk(rep.failure, i)) << rep.failure;
}

TEST(Sqrt3Check, MovingBothCopiesBreaksTheGeometry) {
  // The same move applied to the exact and the long double coordinates: consistent data, wrong
  // packing. Disk 6 of Delta(5), (i, j) = (1, 1) at (3/2, sqrt3/2), moves up by sqrt3/2.
  Pattern pat = build_hexagonal(5);
  const int i = 6;
  pat.sqrt3->points[i].y = pat.sqrt3->points[i].y + HalfSurd3{0, 1};
  pat.packing.points[i] = pat.sqrt3->points[i].value() * pat.packing.d;
  const Sqrt3CheckReport rep = sqrt3_check(pat);
  EXPECT_FALSE(rep.ok);
  EXPECT_TRUE(names_disk(rep.failure, i)) << rep.failure;
}

TEST(Sqrt3Check, BogusBondsAndMissingBonds) {
  const Pattern good = build_four_delta(3);
  {
    // Disks 0 and 5 are 2 apart: not a contact.
    Pattern pat = good;
    pat.bonds.push_back(Bond::pair(0, 5));
    const Sqrt3CheckReport rep = sqrt3_check(pat);
    EXPECT_FALSE(rep.ok);
    EXPECT_TRUE(names_disk(rep.failure, 0) && names_disk(rep.failure, 5)) << rep.failure;
  }
  {
    // The central triangle's lower vertex is 1/2 above the floor.
    Pattern pat = good;
    const int v = static_cast<int>(3 * triangular(3));
    pat.bonds.push_back(Bond::wall(v, Side::Bottom));
    const Sqrt3CheckReport rep = sqrt3_check(pat);
    EXPECT_FALSE(rep.ok);
    EXPECT_TRUE(names_disk(rep.failure, v)) << rep.failure;
  }
  {
    // A contact without a bond is a gap that is not > 1, a side without a wall bond one not > 0.
    for (bool wall : {false, true}) {
      Pattern pat = good;
      const auto it = std::find_if(pat.bonds.begin(), pat.bonds.end(),
                                   [&](const Bond& b) { return b.is_wall() == wall; });
      ASSERT_NE(it, pat.bonds.end());
      const Bond dropped = *it;
      pat.bonds.erase(it);
      const Sqrt3CheckReport rep = sqrt3_check(pat);
      EXPECT_FALSE(rep.ok);
      EXPECT_TRUE(names_disk(rep.failure, dropped.a)) << rep.failure;
      if (!wall) {
        EXPECT_TRUE(names_disk(rep.failure, dropped.b)) << rep.failure;
      }
    }
  }
  {
    Pattern pat = good;
    pat.bonds.push_back(Bond{0, 1000});
    EXPECT_FALSE(sqrt3_check(pat).ok);
  }
}

TEST(Sqrt3Check, RattlerCheckedAtItsRationalPosition) {
  // The twin rattler has no exact coordinates: its long double position is checked exactly.
  Pattern pat = build_twin(2, 0);
  const int r = pat.rattlers.at(0);
  EXPECT_TRUE(sqrt3_check(pat).ok);
  // Move it to 0.42 from the floor disk (1, 0) (index 4 Delta(2) + 1, after the four triangles):
  // an overlap with a non-bond pair, still inside.
  const Vec2L floor1 = pat.packing.points[4 * triangular(2) + 1];
  pat.packing.points[static_cast<std::size_t>(r)] = floor1 + Vec2L{0.3L, 0.3L} * pat.packing.d;
  const Sqrt3CheckReport rep = sqrt3_check(pat);
  EXPECT_FALSE(rep.ok);
  EXPECT_TRUE(names_disk(rep.failure, r)) << rep.failure;
  // Outside the triangle.
  pat.packing.points[static_cast<std::size_t>(r)] = Vec2L{0.5L, -1e-18L};
  const Sqrt3CheckReport out = sqrt3_check(pat);
  EXPECT_FALSE(out.ok);
  EXPECT_TRUE(names_disk(out.failure, r)) << out.failure;
}

TEST(Sqrt3Check, ThrowsWithoutSqrt3Data) {
  Pattern pat = build_four_delta(2);
  Pattern wrong_size = pat;
  wrong_size.sqrt3->points.pop_back();
  EXPECT_THROW(sqrt3_check(wrong_size), std::invalid_argument);
  pat.sqrt3.reset();
  EXPECT_THROW(sqrt3_check(pat), std::invalid_argument);
}

TEST(Sqrt3Check, TimeForFourDelta20And100) {
  // Once slow: sqrt3_check of 4Delta(20) (n = 840) and 4Delta(100) (n = 20,200).
  for (long k : {20L, 100L}) {
    const Pattern pat = build_four_delta(k);
    const auto t0 = std::chrono::steady_clock::now();
    const Sqrt3CheckReport rep = sqrt3_check(pat);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_TRUE(rep.ok) << rep.failure;
    RecordProperty("seconds_k" + std::to_string(k), std::to_string(s));
    std::printf("sqrt3_check 4Delta(%ld), n = %zu: %.4f s\n", k, pat.packing.size(), s);
  }
}

}  // namespace
}  // namespace tripack
