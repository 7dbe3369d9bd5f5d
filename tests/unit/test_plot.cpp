// report/plot: the delta(n) and accuracy plots through gnuplot, on a small synthetic data set
// (Delta(k) at delta 0, 4Delta(k) from the closed form L = 2k - 2 + sqrt(3), a few classless n).
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "one_line_error.hpp"
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
  for (const char* legend :
       {"hexagonal", "four-delta", "in no class: best found", "best of the billiards runs",
        "proven optimum", "limit of delta(4Delta(k))"}) {
    EXPECT_NE(svg.find(std::string("<text>") + legend + "</text>"), std::string::npos) << legend;
  }
  fs::remove_all(dir);
}

// The synthetic points and atlas points (in no class, delta `delta`) at `ns`, plotted in the
// scratch directory `name`.
fs::path plot_with_atlas_points(const std::string& name, std::initializer_list<long long> ns,
                                double delta) {
  const fs::path dir = scratch(name);
  std::vector<DeltaPoint> points = synthetic();
  for (long long n : ns) points.push_back({n, delta, "", false, false, true});
  plot_delta(points, dir);
  return dir;
}

// The atlas's points: a column of their own, drawn as grey dots under one legend
// entry, never as the classless open squares even though their class is "".
TEST(Plot, AtlasPointsHaveTheirOwnColumnAndLegend) {
  const fs::path dir = plot_with_atlas_points("delta-atlas", {50, 51, 52}, 0.3);
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
  EXPECT_NE(slurp(dir / "delta.svg").find("<text>atlas best known</text>"), std::string::npos);
  fs::remove_all(dir);
}

// The clauses of the script's first `plot` command, continuation lines joined, split at the
// commas outside quotes, brackets and parentheses.
std::vector<std::string> plot_clauses(const std::string& gp) {
  const auto all = lines(gp);
  std::string command;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (command.empty() && all[i].rfind("plot ", 0) != 0) continue;
    std::string line = all[i];
    const bool more = !line.empty() && line.back() == '\\';
    if (more) line.pop_back();
    command += line;
    if (!more) break;
  }
  std::vector<std::string> clauses;
  std::string clause;
  int depth = 0;
  bool quoted = false;
  for (char c : command.substr(command.empty() ? 0 : 5)) {
    if (c == '\'') quoted = !quoted;
    if (!quoted && (c == '(' || c == '[')) ++depth;
    if (!quoted && (c == ')' || c == ']')) --depth;
    if (!quoted && depth == 0 && c == ',') {
      clauses.push_back(clause);
      clause.clear();
    } else {
      clause += c;
    }
  }
  if (!clause.empty()) clauses.push_back(clause);
  return clauses;
}

// The title of a clause: a non-empty quoted string or classes[i]; "" when it has none.
std::string clause_title(const std::string& clause) {
  if (clause.find("notitle") != std::string::npos) return "";
  const auto at = clause.find(" title ");
  if (at == std::string::npos) return "";
  std::string title = clause.substr(at + 7);
  title.erase(title.find_last_not_of(" ") + 1);
  if (title == "classes[i]") return title;
  if (title.size() < 3 || title.front() != '\'' || title.back() != '\'') return "";
  return title.substr(1, title.size() - 2);
}

// Every layer drawn with points has a key entry that says what it is, and the atlas's grey dots
// are drawn last, on top of the squares, crosses and rings at the same n (they were drawn
// first, hidden under them).
TEST(Plot, EveryMarkerKindHasAKeyEntryAndTheAtlasIsOnTop) {
  const fs::path dir = plot_with_atlas_points("delta-key", {18, 23, 50}, 0.37);
  const auto clauses = plot_clauses(slurp(dir / "delta.gp"));
  ASSERT_GE(clauses.size(), 6u);
  std::vector<std::string> marker_styles;
  for (const auto& clause : clauses) {
    if (clause.find("with points") == std::string::npos &&
        clause.find("with linespoints") == std::string::npos)
      continue;
    EXPECT_NE(clause_title(clause), "") << "a layer without a key entry: " << clause;
    const auto ls = clause.find(" ls ");
    ASSERT_NE(ls, std::string::npos) << clause;
    marker_styles.push_back(clause.substr(ls + 4, clause.find(' ', ls + 4) - ls - 4));
  }
  // Classes (ls i), open squares (101), crosses (102), rings (103), atlas dots (105) last.
  EXPECT_EQ(marker_styles, (std::vector<std::string>{"i", "101", "102", "103", "105"}));
  for (const auto& clause : clauses) {
    if (clause.find("ls 101") != std::string::npos) {
      EXPECT_NE(clause_title(clause).find("no class"), std::string::npos) << clause;
    }
    if (clause.find("ls 102") != std::string::npos) {
      EXPECT_NE(clause_title(clause).find("billiards"), std::string::npos) << clause;
    }
    if (clause.find("ls 103") != std::string::npos) {
      EXPECT_NE(clause_title(clause).find("proven"), std::string::npos) << clause;
    }
    if (clause.find("ls 105") != std::string::npos) {
      EXPECT_NE(clause_title(clause).find("atlas"), std::string::npos) << clause;
    }
  }
  fs::remove_all(dir);
}

// With as many class lines as the explorer draws (31 at max-n 200), every key entry is in the
// picture: a single key column ran off the canvas's bottom edge, and gnuplot left out the
// entries of the squares, crosses, rings and atlas dots (listed after the classes).
TEST(Plot, KeyOfManyClassesFitsInThePicture) {
  const fs::path dir = scratch("delta-many");
  std::vector<DeltaPoint> points = synthetic();
  std::vector<std::string> legends = {"hexagonal", "four-delta"};
  for (int p = 1; p <= 29; ++p) {
    const std::string line = fmt::format("vacancy-segment p={}", p);
    legends.push_back(line);
    for (long long n : {30 + p, 60 + p}) points.push_back({n, 0.3 + 0.001 * p, line});
  }
  for (long long n : {18, 23, 50}) points.push_back({n, 0.37, "", false, false, true});
  for (const char* marker : {"in no class: best found", "best of the billiards runs",
                             "proven optimum", "atlas best known", "limit of delta(4Delta(k))"})
    legends.push_back(marker);
  plot_delta(points, dir);
  const std::string svg = slurp(dir / "delta.svg");
  const auto box = svg.find("viewBox=\"0 0 ");
  ASSERT_NE(box, std::string::npos);
  double width = 0, height = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + box, "viewBox=\"0 0 %lf %lf", &width, &height), 2);
  for (const auto& legend : legends) {
    const auto text = svg.find("<text>" + legend + "</text>");
    ASSERT_NE(text, std::string::npos) << "no key entry '" << legend << "' in the picture";
    // The text's position: the last translate(x,y) before it.
    const auto at = svg.rfind("translate(", text);
    ASSERT_NE(at, std::string::npos);
    double x = -1, y = -1;
    ASSERT_EQ(std::sscanf(svg.c_str() + at, "translate(%lf,%lf)", &x, &y), 2);
    // A key entry's text starts at x and runs about 7 pixels a character at 12 points.
    EXPECT_GT(x, 0) << legend;
    EXPECT_LT(x + 7.0 * static_cast<double>(legend.size()), width) << legend;
    EXPECT_GT(y, 0) << legend;
    EXPECT_LT(y, height) << legend;
  }
  expect_pictures(dir, "delta");
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
  expect_one_line_error([] { find_gnuplot(); }, {"gnuplot-nox", "/nonexistent"});
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
  expect_one_line_error([&] { plot_delta(synthetic(), dir / "out"); },
                        {"gnuplot failed on", "delta.gp\" line 9: no such thing"});
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
