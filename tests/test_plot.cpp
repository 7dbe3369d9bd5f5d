// report/plot: the delta(n) and accuracy plots through gnuplot, on a small synthetic data set
// (Delta(k) at delta 0, 4Delta(k) from the closed form L = 2k - 2 + sqrt(3), a few classless n).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "report/plot.hpp"

namespace tripack::report {
namespace {
namespace fs = std::filesystem;

double oler(double n) {
  return (-3 + std::sqrt(8 * n + 1)) / 2;
}

std::vector<DeltaPoint> synthetic() {
  std::vector<DeltaPoint> points;
  for (long long k = 1; k <= 10; ++k) {
    points.push_back({k * (k + 1) / 2, 0.0, "hexagonal", true, false});
  }
  // GL1995: d(4Delta(k)) = 1/(2k - 2 + sqrt(3)).
  for (long long k = 1; k <= 6; ++k) {
    const long long n = 2 * k * (k + 1);
    points.push_back({n, 2.0 * k - 2 + std::sqrt(3.0) - oler(n), "four-delta", n <= 15, false});
  }
  points.push_back({18, 0.3706, "", false, false});
  points.push_back({23, 0.3754, "", false, true});
  points.push_back({24, 2.0 * 3 - 2 + std::sqrt(3.0) - oler(24), "four-delta", false, true});
  return points;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// A fresh directory per test (tests run as separate processes, in parallel).
fs::path scratch(const std::string& test) {
  const fs::path dir =
      fs::temp_directory_path() / ("tripack_plot_" + test + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

// Sets an environment variable for one scope and puts the old value back.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value, 1);
  }
  ~ScopedEnv() {
    if (old_)
      ::setenv(name_, old_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

void expect_pictures(const fs::path& dir, const std::string& name) {
  const std::string svg = slurp(dir / (name + ".svg"));
  const std::string png = slurp(dir / (name + ".png"));
  const std::string pdf = slurp(dir / (name + ".pdf"));
  EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_EQ(png.rfind("\x89PNG\r\n\x1a\n", 0), 0u);
  EXPECT_EQ(pdf.rfind("%PDF-", 0), 0u);
  EXPECT_NE(pdf.find("%%EOF"), std::string::npos);
}

TEST(Plot, DeltaWritesDataScriptAndPictures) {
  const fs::path dir = scratch("delta");
  const auto points = synthetic();
  plot_delta(points, dir);

  const auto csv = lines(slurp(dir / "delta.csv"));
  ASSERT_EQ(csv.size(), points.size() + 1);
  EXPECT_EQ(csv[0], "n,delta,class,class_no,proven,billiards,atlas");
  // Every point is one row, exactly (shortest round-trip doubles), grouped by class in the
  // order the classes first appear: hexagonal 1, four-delta 2, none 0.
  for (const auto& p : points) {
    const std::string class_no = p.class_id == "hexagonal"    ? "1"
                                 : p.class_id == "four-delta" ? "2"
                                                              : "0";
    int found = 0;
    for (std::size_t i = 1; i < csv.size(); ++i) {
      const auto f = fields(csv[i]);
      ASSERT_EQ(f.size(), 7u) << csv[i];
      if (std::stoll(f[0]) == p.n && std::strtod(f[1].c_str(), nullptr) == p.delta &&
          f[2] == p.class_id && f[3] == class_no && f[4] == (p.proven ? "1" : "0") &&
          f[5] == (p.billiards ? "1" : "0")) {
        ++found;
      }
    }
    EXPECT_EQ(found, 1) << "n = " << p.n << " " << p.class_id;
  }
  // Within a class: constructed rows in n order, then its billiards rows (the line's block).
  EXPECT_EQ(fields(csv[1])[0], "1");
  EXPECT_EQ(fields(csv[10])[0], "55");
  EXPECT_EQ(fields(csv[11])[0], "4");
  EXPECT_EQ(fields(csv[16])[0], "84");
  EXPECT_EQ(fields(csv[17])[5], "1");  // the n = 24 billiards value, after 84

  const std::string gp = slurp(dir / "delta.gp");
  EXPECT_NE(gp.find("data = 'delta.csv'"), std::string::npos);
  EXPECT_NE(gp.find("set ylabel 'delta(n) = L(n) - t(n)'"), std::string::npos);
  EXPECT_NE(gp.find("limit = sqrt(3) - 1.5"), std::string::npos);
  expect_pictures(dir, "delta");
  const std::string svg = slurp(dir / "delta.svg");
  for (const char* legend : {"hexagonal", "four-delta", "in no class", "billiards best",
                             "proven optimum", "limit of delta(4Delta(k))"}) {
    EXPECT_NE(svg.find(std::string("<text>") + legend + "</text>"), std::string::npos) << legend;
  }
  fs::remove_all(dir);
}

// The atlas's points: a column of their own, drawn as grey dots under one legend
// entry, never as the classless open squares even though their class is "".
TEST(Plot, AtlasPointsHaveTheirOwnColumnAndLegend) {
  const fs::path dir = scratch("delta-atlas");
  std::vector<DeltaPoint> points = synthetic();
  for (long long n : {50, 51, 52}) points.push_back({n, 0.3, "", false, false, true});
  plot_delta(points, dir);
  const auto csv = lines(slurp(dir / "delta.csv"));
  int atlas_rows = 0;
  for (std::size_t i = 1; i < csv.size(); ++i) {
    const auto f = fields(csv[i]);
    ASSERT_EQ(f.size(), 7u);
    if (f[6] == "1") {
      ++atlas_rows;
      EXPECT_EQ(f[3], "0");  // class_no 0, yet not an open square (the script filters $7 == 0)
    }
  }
  EXPECT_EQ(atlas_rows, 3);
  const std::string gp = slurp(dir / "delta.gp");
  EXPECT_NE(gp.find("($4 == 0 && $7 == 0 ? $2 : NaN)"), std::string::npos);
  EXPECT_NE(slurp(dir / "delta.svg").find("<text>atlas best</text>"), std::string::npos);
  fs::remove_all(dir);
}

// All three formats are byte-stable: SVG and PNG by themselves (fixed environment), the PDF
// because its creation date is overwritten with 1970-01-01.
TEST(Plot, RerunGivesTheSameBytes) {
  const fs::path dir = scratch("rerun");
  plot_delta(synthetic(), dir, "d");
  plot_accuracy({{"n = 22 billiards", 0.01, 3}, {"n = 22 billiards", 0.1, 6}}, dir, "a");
  std::vector<std::string> first;
  for (const char* f : {"d.svg", "d.png", "d.pdf", "a.svg", "a.png", "a.pdf"}) {
    first.push_back(slurp(dir / f));
  }
  EXPECT_NE(first[2].find("/CreationDate (D:19700101000000"), std::string::npos);
  sleep(1);  // a PDF stamped with the current time would now differ
  plot_delta(synthetic(), dir, "d");
  plot_accuracy({{"n = 22 billiards", 0.01, 3}, {"n = 22 billiards", 0.1, 6}}, dir, "a");
  std::size_t i = 0;
  for (const char* f : {"d.svg", "d.png", "d.pdf", "a.svg", "a.png", "a.pdf"}) {
    EXPECT_TRUE(slurp(dir / f) == first[i++]) << f << " changed on rerun";
  }
  fs::remove_all(dir);
}

TEST(Plot, AccuracyJoinsEachSeriesInTimeOrder) {
  const fs::path dir = scratch("accuracy");
  // Names with a comma and a quote: CSV-quoted for other tools; gnuplot filters on series_no.
  const std::vector<AccuracyPoint> points = {
      {"n = 22 billiards", 0.5, 9},    {"n = 22 billiards", 0.02, 3},
      {"n = 22 billiards", 0.1, 6},    {"n = 22, \"polish\"", 0.6, 15},
      {"n = 22, \"polish\"", 0.9, 30}, {"n = 79 billiards", 0, 1},
      {"n = 79 billiards", 2.0, 3}};
  plot_accuracy(points, dir);
  const auto csv = lines(slurp(dir / "accuracy.csv"));
  ASSERT_EQ(csv.size(), points.size() + 1);
  EXPECT_EQ(csv[0], "series,series_no,seconds,digits");
  EXPECT_EQ(csv[1], "n = 22 billiards,1,0.02,3");
  EXPECT_EQ(csv[2], "n = 22 billiards,1,0.1,6");
  EXPECT_EQ(csv[3], "n = 22 billiards,1,0.5,9");
  EXPECT_EQ(csv[4], "\"n = 22, \"\"polish\"\"\",2,0.6,15");
  EXPECT_EQ(csv[6], "n = 79 billiards,3,0,1");  // kept in the data, not drawable on log x
  EXPECT_NE(slurp(dir / "accuracy.gp").find("data = 'accuracy.csv'"), std::string::npos);
  expect_pictures(dir, "accuracy");
  const std::string svg = slurp(dir / "accuracy.svg");
  EXPECT_NE(svg.find("<text>n = 22 billiards</text>"), std::string::npos);
  EXPECT_NE(svg.find("<text>n = 79 billiards</text>"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Plot, MissingGnuplotNamesThePackage) {
  const fs::path dir = scratch("missing");
  ScopedEnv env("TRIPACK_GNUPLOT", "/nonexistent");
  try {
    find_gnuplot();
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("gnuplot-nox"), std::string::npos) << what;
    EXPECT_NE(what.find("/nonexistent"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_THROW(plot_delta(synthetic(), dir), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir / "delta.csv"));  // checked before anything is written
}

TEST(Plot, GnuplotFailureIsOneLine) {
  const fs::path dir = scratch("failure");
  fs::create_directories(dir);
  const fs::path fake = dir / "fake-gnuplot";
  std::ofstream(fake)
      << "#!/bin/sh\necho 'plot x' >&2\necho \"\\\"$1\\\" line 9: no such thing\" >&2\n"
         "exit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  ScopedEnv env("TRIPACK_GNUPLOT", fake.c_str());
  try {
    plot_delta(synthetic(), dir / "out");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("gnuplot failed on"), std::string::npos) << what;
    EXPECT_NE(what.find("delta.gp\" line 9: no such thing"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
  EXPECT_FALSE(fs::exists(dir / "out" / "delta.png"));
  fs::remove_all(dir);
}

TEST(Plot, WriteFailureNamesTheFile) {
  const fs::path dir = scratch("write");
  fs::create_directories(dir / "delta.csv");  // a directory where the data file should go
  try {
    plot_delta(synthetic(), dir);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "delta.csv").string()), std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "file") << "x";
  try {
    plot_delta(synthetic(), dir / "file" / "sub");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "file" / "sub").string()), std::string::npos)
        << e.what();
  }
  fs::remove_all(dir);
}

TEST(Plot, RejectsBadInput) {
  const fs::path dir = scratch("bad");
  EXPECT_THROW(plot_delta({}, dir), std::invalid_argument);
  EXPECT_THROW(plot_delta(synthetic(), dir, "a/b"), std::invalid_argument);
  EXPECT_THROW(plot_delta({{0, 0.1, "", false, false}}, dir), std::invalid_argument);
  EXPECT_THROW(plot_delta({{5, std::nan(""), "", false, false}}, dir), std::invalid_argument);
  EXPECT_THROW(plot_accuracy({{"s", 0, 3}}, dir), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace tripack::report
