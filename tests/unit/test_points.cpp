// core/points: the layout files of tests/data/layouts (t22a in every layout, made by make.py) give
// t22a's d, with a warning for each repaired slip and a one-line error for each bad file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/io.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"
#include "near_long_double.hpp"

namespace tripack {
namespace {

// d(22) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11) (docs/classes.md; 40 digits, mpmath).
constexpr long double kD22 = 0.1793969086118659795612188470507365957414L;

// How close d comes to kD22 depends on the digits the file carries:
//  * 21 significant digits (tripack's own text): each coordinate is exact to the long double
//    it is parsed into, within 5e-20; a distance moves by at most 2 sqrt2 5e-20 and the
//    long double arithmetic adds ~1e-19: 3e-19.
//  * 17 significant digits (every other file): each coordinate within 5e-18 (values below 1);
//    a distance within 2 sqrt2 5e-18 = 1.4e-17. In a container convention d is that distance
//    over the bounding side (0.76, from three support lines each within (1 + sqrt3) 5e-18):
//    1.9e-17 + 0.5e-17 = 2.4e-17. Both bounded by 3e-17.
//  * 6 decimals: each coordinate within 5e-7, a point within sqrt2 5e-7 = 7.1e-7 of its true
//    place; moving it onto the triangle only brings it nearer (the true point lies in the
//    triangle and the projection onto a convex set does not expand distances): 1.42e-6.
constexpr long double kDigits21 = 3e-19L, kDigits17 = 3e-17L, kDecimals6 = 1.42e-6L;

std::string layout_file(const std::string& name) {
  return std::string(TRIPACK_TEST_DATA) + "/layouts/" + name;
}

PointsReading reading_of(const std::string& name, std::optional<Convention> convention = {}) {
  return packing_from_points(read_packing_file(layout_file(name)), convention, 22);
}

bool contains(const std::string& text, const std::string& needle) {
  return text.find(needle) != std::string::npos;
}

TEST(Points, EveryLayoutGivesTheDOfT22a) {
  struct Case {
    const char* file;
    std::optional<Convention> convention;
    long double tolerance;
  };
  const Case cases[] = {
      {"t22a.xy.txt", {}, kDigits21},
      {"t22a.ixy.txt", {}, kDigits17},
      {"t22a.header.csv", {}, kDigits17},
      {"t22a.points.json", {}, kDigits17},
      {"t22a.list.json", {}, kDigits17},
      {"t22a.pck", {}, kDigits17},
      {"t22a.xyr.txt", {}, kDigits17},  // radius implied by the r column
      {"t22a.xyr.txt", Convention::Radius, kDigits17},
  };
  for (const auto& c : cases) {
    const PointsReading r = reading_of(c.file, c.convention);
    EXPECT_TRUE(near_ld(r.packing.d, kD22, c.tolerance)) << c.file;
    // Clean files: wall disks a hair outside (5e-18) are moved silently.
    EXPECT_TRUE(r.warnings.empty()) << c.file << ": " << r.warnings.front();
  }
}

TEST(Points, RoundedCoordinatesAreMovedOntoTheSidesWithOneWarning) {
  const PointsReading r = reading_of("t22a.rounded6.txt");
  EXPECT_TRUE(near_ld(r.packing.d, kD22, kDecimals6));
  ASSERT_EQ(r.warnings.size(), 1u);
  // make.py counts 4 points outside by up to 1.6e-7.
  EXPECT_TRUE(contains(r.warnings[0], "4 points lie outside the unit triangle by up to 1.6e-07"))
      << r.warnings[0];
  EXPECT_TRUE(contains(r.warnings[0], "1e-06")) << r.warnings[0];
  for (const auto& p : r.packing.points)
    for (Side s : kSides) EXPECT_GE(wall_distance(p, s, 1.0L), -1e-18L);
  // A tighter tolerance turns the same slip into an error naming the point.
  try {
    packing_from_points(read_packing_file(layout_file("t22a.rounded6.txt")), {}, 22, 1e-8L);
    ADD_FAILURE() << "accepted with tolerance 1e-8";
  } catch (const InputError& e) {
    EXPECT_TRUE(contains(e.what(), "outside the unit triangle")) << e.what();
  }
}

TEST(Points, UpsideDownAndTransposedContainersGiveTheSamePacking) {
  const PointsReading upright = reading_of("t22a.xyr.txt");
  const PointsReading upside_down = reading_of("t22a.upside-down.txt", Convention::Radius);
  const PointsReading transposed = reading_of("t22a.transposed.txt", Convention::Radius);
  EXPECT_TRUE(near_ld(upside_down.packing.d, kD22, kDigits17));
  EXPECT_TRUE(near_ld(transposed.packing.d, kD22, kDigits17));
  EXPECT_TRUE(near_ld(upside_down.packing.d, upright.packing.d, kDigits17));
  EXPECT_TRUE(near_ld(transposed.packing.d, upright.packing.d, kDigits17));
  ASSERT_EQ(upside_down.warnings.size(), 1u);
  EXPECT_TRUE(contains(upside_down.warnings[0], "upside down")) << upside_down.warnings[0];
  ASSERT_EQ(transposed.warnings.size(), 1u);
  EXPECT_TRUE(contains(transposed.warnings[0], "x and y swapped")) << transposed.warnings[0];
  // Half a turn undoes the upside-down file's turn: the same disks in the same places. The
  // quarter turn that uprights the transposed file leaves it mirrored: (x, y) -> (1 - x, y).
  for (std::size_t i = 0; i < 22; ++i) {
    const Vec2L p = upright.packing.points[i];
    EXPECT_LT(norm(upside_down.packing.points[i] - p), kDigits17) << i;
    EXPECT_LT(norm(transposed.packing.points[i] - Vec2L{1 - p.x, p.y}), kDigits17) << i;
  }
}

TEST(Points, UnitDiskSideScalesLikeRadius) {
  // Circles of radius 1: the x y r file's centres over r, in a container of side S.
  PointsFile file = read_packing_file(layout_file("t22a.xyr.txt"));
  const long double r = *file.radius;
  for (auto& p : file.points) p = p / r;
  file.radius.reset();
  const PointsReading reading = packing_from_points(file, Convention::UnitDiskSide, 22);
  EXPECT_TRUE(near_ld(reading.packing.d, kD22, kDigits17));
  // S = 2/d + 2 sqrt3 carries d's relative error (kDigits17 / d = 1.7e-16) times 2/d = 11: 2e-15.
  EXPECT_TRUE(near_ld(side_from_d(reading.packing.d), 1 / r, 2e-15L));
}

TEST(Points, RadiusFileChecksItsR) {
  const PointsReading r = reading_of("t22a.xyr-wrong-r.txt");
  EXPECT_TRUE(near_ld(r.packing.d, kD22, kDigits17));  // d comes from the centres, not from r
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "do not touch")) << r.warnings[0];
}

TEST(Points, HeaderDIsChecked) {
  PointsFile file = read_packing_file(layout_file("t22a.xy.txt"));
  ASSERT_TRUE(file.declared_d);
  // 21 digits of the polished d (within 1e-20 of d(22)) parsed to long double (half an ulp:
  // 1.4e-20).
  EXPECT_TRUE(near_ld(*file.declared_d, kD22, 3e-20L));
  file.declared_d = 0.18L;
  const PointsReading r = packing_from_points(file, {}, 22);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_TRUE(contains(r.warnings[0], "header's d = 0.18")) << r.warnings[0];
}

// Each bad input: an InputError of one line containing every needle.
void expect_rejected(const PointsFile& file, std::optional<Convention> convention,
                     std::optional<long long> n, std::initializer_list<const char*> needles) {
  try {
    packing_from_points(file, convention, n);
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_FALSE(contains(what, "\n")) << what;
    for (const char* needle : needles) EXPECT_TRUE(contains(what, needle)) << what;
    return;
  }
  ADD_FAILURE() << "accepted; expected: " << *needles.begin();
}

TEST(Points, BadPointSetsAreRejectedWithOneLine) {
  auto file = [](const char* name) { return read_packing_file(layout_file(name)); };
  expect_rejected(file("t22a.bad-outside.txt"), {}, 22,
                  {"point 17", "0.001 outside the unit triangle", "bottom side", "--convention"});
  expect_rejected(file("t22a.bad-flipped.txt"), {}, 22,
                  {"outside the unit triangle", "upside down", "flipped or rotated"});
  expect_rejected(file("t22a.bad-coincide.txt"), {}, 22, {"points 3 and 12 coincide"});
  expect_rejected(file("hexagon.bad-orientation.txt"), Convention::Radius, {},
                  {"cannot tell the triangle's orientation"});
  expect_rejected(file("t22a.xyr.txt"), Convention::UnitTriangle, 22,
                  {"radius", "not unit-triangle"});
  expect_rejected(file("t22a.xyr.txt"), Convention::UnitDiskSide, 22, {"not unit-disk-side"});
  expect_rejected(file("t22a.xy.txt"), {}, 23, {"expected 23 points, the file has 22"});
  expect_rejected(PointsFile{{{0.1L, 0.1L}}, {}, {}, "x y", {}, {}, {}}, {}, {}, {"at least 2"});
}

}  // namespace
}  // namespace tripack
