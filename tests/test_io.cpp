// core/io: text, CSV and JSON round trips and malformed input.
#include <gtest/gtest.h>

#include <sstream>

#include "core/io.hpp"

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

TEST(Io, RoundTripIsExactInEveryFormat) {
  const Pattern p = sample();
  for (auto fmt : {FileFormat::Text, FileFormat::Csv, FileFormat::Json}) {
    std::stringstream ss;
    if (fmt == FileFormat::Text) write_text(ss, p);
    if (fmt == FileFormat::Csv) write_csv(ss, p);
    if (fmt == FileFormat::Json) write_json(ss, p);
    const auto pts = read_points(ss, fmt);
    ASSERT_EQ(pts.size(), p.packing.points.size());
    // 21 digits round-trip a long double exactly (text, CSV, and JSON's points_exact).
    for (std::size_t i = 0; i < pts.size(); ++i) EXPECT_EQ(pts[i], p.packing.points[i]);
  }
}

TEST(Io, FormatFromExtension) {
  EXPECT_EQ(format_from_path("a.csv"), FileFormat::Csv);
  EXPECT_EQ(format_from_path("dir/a.json"), FileFormat::Json);
  EXPECT_EQ(format_from_path("a.txt"), FileFormat::Text);
  EXPECT_EQ(format_from_path("a"), FileFormat::Text);
}

TEST(Io, PlainCsvWithoutIndexAndHeader) {
  std::stringstream ss("x,y\n0.1,0.2\n0.3,0.4\n");
  const auto pts = read_points(ss, FileFormat::Csv);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Vec2L(0.3L, 0.4L));
}

TEST(Io, MalformedInputThrowsWithTheLine) {
  auto fails = [](const std::string& text, FileFormat f, const std::string& needle) {
    std::stringstream ss(text);
    try {
      read_points(ss, f);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);  // one line
      return;
    }
    ADD_FAILURE() << "no error for: " << text;
  };
  fails("0.1 0.2\n0.3 x\n", FileFormat::Text, "line 2");
  fails("0.1 0.2 0.3\n", FileFormat::Text, "line 1");
  fails("0.1 nan\n", FileFormat::Text, "finite");
  fails("0.1 inf\n", FileFormat::Text, "finite");
  fails("x,y\n1,2\nfoo,bar\n", FileFormat::Csv, "line 3");
  fails("{\"points\": [[0,1],[2]]}", FileFormat::Json, "point 1");
  fails("{\"pts\": []}", FileFormat::Json, "points");
  fails("{\"points\": [[0,1]", FileFormat::Json, "malformed JSON");
}

TEST(Io, JsonWithPlainNumbersOnly) {
  std::stringstream ss("{\"points\": [[0.25, 0.5], [0.75, 0.125]]}");
  const auto pts = read_points(ss, FileFormat::Json);
  ASSERT_EQ(pts.size(), 2u);
  EXPECT_EQ(pts[1], Vec2L(0.75L, 0.125L));  // exact binary fractions
}

TEST(Io, SignificantDigits) {
  EXPECT_EQ(format_significant(0.179396908611865979561L, 15), "0.179396908611866");
  EXPECT_EQ(format_significant(0.179396908611865979561L, 17), "0.17939690861186598");
}

}  // namespace
}  // namespace tripack
