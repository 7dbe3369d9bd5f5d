// core/io: round trips, every layout of tests/data/layouts (t22a, made by make.py), and malformed
// input.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "formats/formats.hpp"
#include "near_long_double.hpp"

namespace tripack {
namespace {

Pattern sample() {
  Pattern p;
  p.packing.points = {{0, 0}, {1, 0}, {0.5L, kSqrt3 / 2}, {0.5L, 1 / (2 * kSqrt3)}};
  p.packing.d = 0.57735026918962576451L;
  p.bonds = {Bond::pair(0, 3), Bond::wall(0, Side::Bottom), Bond::wall(0, Side::Left)};
  p.rattlers = {};
  p.provenance = {"four-delta", 1, 0, ""};
  return p;
}

// A stream read by the format table's reader of `name` (formats/formats.hpp).
PointsFile read_as(std::istream& in, const std::string& name) {
  return find_format(name)->read(in);
}

TEST(Io, RoundTripKeepsEveryDigitInEveryFormat) {
  const Pattern p = sample();
  for (std::string fmt : {"txt", "csv", "json"}) {
    std::stringstream ss;
    if (fmt == "txt") write_text(ss, p);
    if (fmt == "csv") write_csv(ss, p);
    if (fmt == "json") write_json(ss, p);
    const PointsFile back = read_as(ss, fmt);
    const auto& pts = back.points;
    ASSERT_EQ(pts.size(), p.packing.points.size());
    // 21 digits round-trip a long double exactly (text, CSV, and JSON's points_decimal).
    for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(pts[i], p.packing.points[i]);
    // Text and JSON state d, which packing_from_points checks against the points.
    if (fmt != "csv") {
      EXPECT_EQ(back.declared_d, p.packing.d);
    }
  }
}

TEST(Io, FormatFromExtension) {
  EXPECT_EQ(format_of_path("a.csv").name, "csv");
  EXPECT_EQ(format_of_path("dir/a.json").name, "json");
  EXPECT_EQ(format_of_path("a.txt").name, "txt");
  EXPECT_EQ(format_of_path("a").name, "txt");
  EXPECT_EQ(format_of_path("t22a.pck").name, "records");
  EXPECT_EQ(format_of_path("t22a.records").name, "records");
}

TEST(Io, PlainCsvWithoutIndexAndHeader) {
  std::stringstream ss("x,y\n0.1,0.2\n0.3,0.4\n");
  const auto pts = read_as(ss, "csv").points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Vec2L(0.3L, 0.4L));
}

TEST(Io, MalformedInputThrowsWithTheLine) {
  auto fails = [](const std::string& text, const std::string& f, const std::string& needle) {
    std::stringstream ss(text);
    try {
      read_as(ss, f);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // one line
      return;
    }
    ADD_FAILURE() << "no error for: " << text;
  };
  fails("0.1 0.2\n0.3 x\n", "txt", "line 2");
  fails("0.1 0.2 0.3 0.4\n", "txt", "line 1");
  fails("0.1 nan\n", "txt", "finite");
  fails("0.1 inf\n", "txt", "finite");
  fails("x,y\n1,2\nfoo,bar\n", "csv", "line 3");
  fails("{\"points\": [[0,1],[2]]}", "json", "point 1");
  fails("{\"pts\": []}", "json", "points");
  fails("{\"points\": [[0,1]", "json", "malformed JSON");
}

TEST(Io, JsonWithPlainNumbersOnly) {
  std::stringstream ss("{\"points\": [[0.25, 0.5], [0.75, 0.125]]}");
  const auto pts = read_as(ss, "json").points;
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Vec2L(0.75L, 0.125L));  // exact binary fractions
}

TEST(Io, SignificantDigits) {
  EXPECT_EQ(format_significant(0.179396908611865979561L, 15), "0.179396908611866");
  EXPECT_EQ(format_significant(0.179396908611865979561L, 17), "0.17939690861186598");
}

// ----- records -------------------------------------------------------------------------------

TEST(Io, RecordsRoundTripAndHeader) {
  RecordsTable table = records_table(sample(), 21);
  table.label = "t4a";
  std::stringstream ss;
  write_records(ss, table);
  const std::string text = ss.str();
  for (const char* line :
       {"# layout: i x y\n", "# n: 4\n", "# label: t4a\n", "# class: four-delta k=1\n",
        "# bonds: 3\n", "# rattlers:\n", "# convention: unit-triangle"})
    EXPECT_NE(text.find(line), std::string::npos) << line << " missing in\n" << text;
  EXPECT_NE(text.find("# d: " + format_significant(sample().packing.d, 21) + "\n"),
            std::string::npos);
  // r and S of d (docs/conventions.md), L = 1/d.
  EXPECT_EQ(table.r, format_significant(radius_from_d(sample().packing.d), 21));
  EXPECT_EQ(table.S, format_significant(side_from_d(sample().packing.d), 21));
  EXPECT_EQ(table.L, format_significant(1 / sample().packing.d, 21));
  EXPECT_NE(text.find("\n3 0.5 0.288675134594812882"), std::string::npos) << text;
  const PointsFile back = read_as(ss, "records");
  EXPECT_EQ(back.layout, "i x y");
  ASSERT_TRUE(back.declared_d);
  EXPECT_EQ(*back.declared_d, sample().packing.d);
  EXPECT_EQ(back.points, sample().packing.points);  // 21 digits: exact
}

TEST(Io, RecordsCarryTheCallersDigits) {
  // More than 21 digits cannot come from a long double: the helper stops there ...
  EXPECT_EQ(records_table(sample(), 40).d, records_table(sample(), 21).d);
  EXPECT_EQ(records_table(sample(), 5).d, "0.57735");
  // ... but strings from an MPFR polish reach the file unchanged.
  RecordsTable table = records_table(sample(), 17);
  table.d = "0.57735026918962576450914878050195745564760175127013";
  std::stringstream ss;
  write_records(ss, table);
  EXPECT_NE(ss.str().find("# d: 0.57735026918962576450914878050195745564760175127013\n"),
            std::string::npos);
}

// ----- the layout files ----------------------------------------------------------------------

std::string layout_file(const std::string& name) {
  return std::string(TRIPACK_TEST_DATA) + "/layouts/" + name;
}

// Each file holds t22a's 22 points as make.py derived them from t22a.xy.txt (21 digits).
// Tolerances are the files' precision: 17 significant digits put a coordinate below 1 within
// 5e-18 of its value, plus 1e-19 of long double parsing and arithmetic: 1e-17. Six decimals:
// within 5e-7.
constexpr long double kDigits17 = 1e-17L, kDecimals6 = 5e-7L + 1e-17L;

void expect_same_points(const std::vector<Vec2L>& got, const std::vector<Vec2L>& want,
                        long double tolerance, const std::string& what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_TRUE(near_ld(got[i].x, want[i].x, tolerance)) << what << " point " << i;
    EXPECT_TRUE(near_ld(got[i].y, want[i].y, tolerance)) << what << " point " << i;
  }
}

TEST(Io, EveryLayoutReadsTheSame22Points) {
  const PointsFile reference = read_packing_file(layout_file("t22a.xy.txt"));
  ASSERT_EQ(reference.points.size(), 22u);
  EXPECT_EQ(reference.layout, "x y");
  EXPECT_FALSE(reference.radius);
  const auto& want = reference.points;
  struct Case {
    const char* file;
    const char* layout;
    long double tolerance;
  };
  for (const Case& c :
       {Case{"t22a.ixy.txt", "i x y", kDigits17}, Case{"t22a.header.csv", "csv", kDigits17},
        Case{"t22a.points.json", "json points", kDigits17},
        Case{"t22a.list.json", "json list", kDigits17}, Case{"t22a.pck", "i x y", kDigits17},
        Case{"t22a.rounded6.txt", "x y", kDecimals6}}) {
    const PointsFile f = read_packing_file(layout_file(c.file));
    EXPECT_EQ(f.layout, c.layout) << c.file;
    EXPECT_FALSE(f.radius) << c.file;
    expect_same_points(f.points, want, c.tolerance, c.file);
  }

  // Radius convention: circles of radius r in the side-1 triangle; their centres fill the
  // triangle inset by r: corner (sqrt3 r, r), side 1 - 2 sqrt3 r (docs/conventions.md).
  const PointsFile xyr = read_packing_file(layout_file("t22a.xyr.txt"));
  EXPECT_EQ(xyr.layout, "x y r");
  ASSERT_TRUE(xyr.radius);
  const long double r = radius_from_d(*reference.declared_d);
  EXPECT_TRUE(near_ld(*xyr.radius, r, kDigits17));
  std::vector<Vec2L> circles, upside_down, transposed;
  for (const auto& p : want) {
    const Vec2L c = Vec2L{kSqrt3 * r, r} + p * (1 - 2 * kSqrt3 * r);
    circles.push_back(c);
    upside_down.push_back({1 - c.x, kSqrt3 / 2 - c.y});
    transposed.push_back({c.y, c.x});
  }
  expect_same_points(xyr.points, circles, kDigits17, "x y r");
  const PointsFile ud = read_packing_file(layout_file("t22a.upside-down.txt"));
  expect_same_points(ud.points, upside_down, kDigits17, "upside down");
  const PointsFile tr = read_packing_file(layout_file("t22a.transposed.txt"));
  expect_same_points(tr.points, transposed, kDigits17, "transposed");
}

// Reading `name` fails with one line naming the path and containing every needle.
void expect_bad_file(const std::string& name, std::initializer_list<const char*> needles) {
  try {
    read_packing_file(layout_file(name));
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(name), std::string::npos) << what;
    for (const char* needle : needles) EXPECT_NE(what.find(needle), std::string::npos) << what;
    return;
  }
  ADD_FAILURE() << name << " was accepted";
}

TEST(Io, EveryBadLayoutFileGivesOneLineNamingTheLine) {
  expect_bad_file("t22a.bad-radius-varies.txt", {"line 12: r = 0.07 differs from line 3"});
  expect_bad_file("t22a.bad-radius-zero.txt", {"line 3: r = 0 is not a finite number > 0"});
  expect_bad_file("t22a.bad-neither.txt",
                  {"neither as 'x y r' (line 2: r = 0", "nor as 'i x y' (line 2: index '0.5'",
                   "# layout: x y r"});
  expect_bad_file("t22a.bad-index-repeats.txt", {"line 10: index 3 repeats line 6"});
  expect_bad_file("t22a.bad-index-beyond.txt", {"line 24: index 22 is beyond 0..21"});
  expect_bad_file("t22a.bad-columns.txt", {"line 6: expected 2 numbers", "got 3"});
  expect_bad_file("t22a.bad-layout.txt", {"line 2: unknown layout 'x y z'"});
  expect_bad_file("t22a.bad-no-y.csv", {"line 1: the header names no 'y' column"});
  expect_bad_file("t22a.bad-row.csv", {"line 7: 'half' is not a number"});
  expect_bad_file("t22a.bad-point.json", {"point 4: expected [x, y]"});
}

// ----- three columns: x y r or i x y ---------------------------------------------------------

PointsFile read_text(const std::string& text, std::string format = "txt") {
  std::stringstream ss(text);
  return read_as(ss, format);
}

TEST(Io, ThreeColumnsAreToldApart) {
  // Constant third column > 0: circles of that radius.
  const PointsFile xyr = read_text("0.1 0.2 0.05\n0.3 0.4 0.05\n");
  EXPECT_EQ(xyr.layout, "x y r");
  EXPECT_EQ(xyr.radius, 0.05L);
  // Otherwise a permutation in the first column: ordered by it (1-based here).
  const PointsFile ixy = read_text("2 0.3 0.4\n1 0.1 0.2\n");
  EXPECT_EQ(ixy.layout, "i x y");
  EXPECT_FALSE(ixy.radius);
  ASSERT_EQ(ixy.points.size(), 2u);
  EXPECT_EQ(ixy.points[0], Vec2L(0.1L, 0.2L));
  // A layout comment decides: this file would read as x y r.
  const PointsFile forced = read_text("# layout: i x y\n1 0.5 0.5\n0 0.2 0.5\n");
  EXPECT_EQ(forced.layout, "i x y");
  EXPECT_EQ(forced.points[0], Vec2L(0.2L, 0.5L));
  // ... and is checked: this one's third column differs.
  try {
    read_text("#  Layout:  x  y  r\n0 0.1 0.1\n1 0.3 0.2\n");
    ADD_FAILURE() << "varying r accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3: r = 0.2 differs from line 2"), std::string::npos)
        << e.what();
  }
  // Records files are i x y even when the third column is constant.
  EXPECT_EQ(read_text("1 0.5 0.5\n0 0.2 0.5\n", "records").points[0], Vec2L(0.2L, 0.5L));
}

// ----- CSV headers and JSON shapes -----------------------------------------------------------

TEST(Io, CsvHeaderNamesTheColumns) {
  const PointsFile f = read_text(
      " Radius , ID,rattler, Y ,X,label\n0.05,1,0,0.2,0.1,a\n"
      "0.05,0,1,\"0.4\",0.3,b\n",
      "csv");
  EXPECT_EQ(f.layout, "csv");
  EXPECT_EQ(f.radius, 0.05L);
  ASSERT_EQ(f.points.size(), 2u);
  EXPECT_EQ(f.points[0], Vec2L(0.3L, 0.4L));  // ordered by id, quoted number read
  EXPECT_EQ(f.points[1], Vec2L(0.1L, 0.2L));
  // Header-less three columns are told apart like text.
  EXPECT_EQ(read_text("0.1,0.2,0.05\n0.3,0.4,0.05\n", "csv").radius, 0.05L);
  auto fails = [](const std::string& text, const std::string& needle) {
    try {
      read_text(text, "csv");
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted: " << text;
  };
  fails("x,y,x\n1,2,3\n", "line 1: two columns name 'x'");
  fails("x,y\n1,2\n3,4,5\n", "line 3: 3 fields, expected 2");
  fails("index,x,y\n0,1,2\n0,3,4\n", "line 3: index 0 repeats line 2");
  fails("x,y,r\n1,2,0.5\n3,4,0.25\n", "line 3: r = 0.25 differs");
}

TEST(Io, JsonShapes) {
  const PointsFile objects =
      read_text(R"({"points": [{"x": 0.25, "y": "0.5"}, {"y": 0.125, "x": 0.75}]})", "json");
  EXPECT_EQ(objects.layout, "json points");
  ASSERT_EQ(objects.points.size(), 2u);
  EXPECT_EQ(objects.points[1], Vec2L(0.75L, 0.125L));
  const PointsFile list = read_text(R"([[0.25, 0.5], ["0.75", 0.125]])", "json");
  EXPECT_EQ(list.layout, "json list");
  EXPECT_EQ(list.points[1], Vec2L(0.75L, 0.125L));
  // Numbers are parsed to long double, not through double.
  const PointsFile precise = read_text(R"([[0.179396908611865979561, 0.1], [0.2, 0.3]])", "json");
  EXPECT_EQ(precise.points[0].x, 0.179396908611865979561L);
  EXPECT_NE(precise.points[0].x, static_cast<long double>(0.179396908611865979561));
}

}  // namespace
}  // namespace tripack

namespace tripack {
namespace {

// PreciseReal rounds its decimal text half up to the digits asked for (decimal arithmetic by
// hand: 0.19999951 -> 0.200000 at 6 digits; 9.9996 -> 10.000 at 5; -0.00123456 -> -0.00123 at 3).
TEST(PreciseReal, RoundsItsTextHalfUpAndNeverClaimsMoreDigitsThanItHas) {
  EXPECT_EQ(PreciseReal(0.2L, "0.19999951000000000000000", 23).str(20), "0.19999951000000000000");
  EXPECT_EQ(PreciseReal(10, "9.9996000000000000000000", 23).str(19), "9.999600000000000000");
  EXPECT_EQ(PreciseReal(0.2L, "0.1999995100000000000000000000", 28).str(6 + kLongDoubleDigits),
            "0.199999510000000000000000");
  EXPECT_EQ(PreciseReal(-0.001L, "-0.001234560000000000000000", 24).str(21),
            "-0.00123456000000000000000");
  EXPECT_EQ(PreciseReal(1, "0.999999999999999999999999999999", 30).str(20),
            "1.0000000000000000000");
  // More digits than known: what is known, not more.
  EXPECT_EQ(PreciseReal(0.5L, "0.50000000000000000000001", 23).str(40),
            "0.50000000000000000000001");
  EXPECT_EQ(PreciseReal(0.25L).str(30), format_significant(0.25L, kLongDoubleDigits));
  EXPECT_EQ(significant_digits("-0.000120"), 3);
}

}  // namespace
}  // namespace tripack
