// An independent check of the committed atlas: data/atlas.csv and every coordinates
// file it names are re-read here with a parser of this file's own and checked in MPFR, without
// any tripack code (this program links only MPFR and GoogleTest). For every row: the file holds n
// points in the triangle (0,0), (1,0), (1/2, sqrt3/2), and their minimum distance equals the row's
// d to its 30 digits. Also: every n = 2..300 has a certified rank-1 row; ranks of n are 1..m with
// d non-increasing; n = 16..34 keep at most 20 rows.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr mpfr_prec_t kBits = 256;  // ~77 digits: far beyond the files' 30

// An MPFR number that cleans up after itself.
struct Real {
  mpfr_t v;
  Real() { mpfr_init2(v, kBits); }
  explicit Real(const std::string& decimal) : Real() {
    if (mpfr_set_str(v, decimal.c_str(), 10, MPFR_RNDN) != 0)
      throw std::runtime_error("not a decimal number: '" + decimal + "'");
  }
  Real(const Real&) = delete;
  Real& operator=(const Real&) = delete;
  ~Real() { mpfr_clear(v); }
  double to_double() const { return mpfr_get_d(v, MPFR_RNDN); }
};

std::filesystem::path data_dir() {
  if (const char* dir = std::getenv("TRIPACK_ATLAS_DIR")) return dir;
  return std::filesystem::path(TRIPACK_SOURCE_DIR) / "data";
}

struct Row {
  long n = 0, rank = 0, bonds = 0, rattlers = 0, confirmations = 0;
  std::string label, d, L, delta, certified, source, file, provenance;
};

// Plain comma splitting with "..." quoting (RFC 4180), enough for this table.
std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> f(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      f.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      f.emplace_back();
    } else if (c != '\r') {
      f.back() += c;
    }
  }
  return f;
}

std::vector<Row> read_table() {
  std::ifstream in(data_dir() / "atlas.csv");
  if (!in) throw std::runtime_error("cannot read " + (data_dir() / "atlas.csv").string());
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header{
      "n",        "rank",      "label",         "d",      "L",    "delta",     "bonds",
      "rattlers", "certified", "confirmations", "source", "file", "provenance"};
  if (fields_of(line) != header) throw std::runtime_error("atlas.csv: unexpected header " + line);
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto f = fields_of(line);
    if (f.size() != header.size()) throw std::runtime_error("atlas.csv: bad line " + line);
    Row r;
    r.n = std::stol(f[0]);
    r.rank = std::stol(f[1]);
    r.label = f[2];
    r.d = f[3];
    r.L = f[4];
    r.delta = f[5];
    r.bonds = std::stol(f[6]);
    r.rattlers = std::stol(f[7]);
    r.certified = f[8];
    r.confirmations = std::stol(f[9]);
    r.source = f[10];
    r.file = f[11];
    r.provenance = f[12];
    rows.push_back(r);
  }
  return rows;
}

// Significant digits of a decimal string (leading zeros and the point not counted).
int significant_digits(const std::string& s) {
  int digits = 0;
  bool leading = true;
  for (char c : s) {
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++digits;
  }
  return digits;
}

struct PointsFile {
  std::string d;  // the "# d:" header
  long n = -1;    // the "# n:" header
  std::vector<std::pair<std::string, std::string>> points;
};

PointsFile read_points(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  PointsFile file;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# d: ", 0) == 0) file.d = line.substr(5);
    if (line.rfind("# n: ", 0) == 0) file.n = std::stol(line.substr(5));
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    std::string x, y, extra;
    if (!(fields >> x >> y) || (fields >> extra))
      throw std::runtime_error(path.string() + ": not an 'x y' line: " + line);
    file.points.emplace_back(x, y);
  }
  return file;
}

TEST(AtlasData, EveryNFrom2To300HasACertifiedBestRowWithItsFile) {
  const auto rows = read_table();
  std::map<long, std::vector<const Row*>> by_n;
  for (const auto& r : rows) by_n[r.n].push_back(&r);
  for (long n = 2; n <= 300; ++n) {
    ASSERT_TRUE(by_n.count(n)) << "n = " << n << " has no row";
    const Row& best = *by_n[n].front();
    EXPECT_EQ(best.rank, 1) << "n = " << n;
    EXPECT_EQ(best.certified, "true") << "n = " << n;
    EXPECT_TRUE(std::filesystem::is_regular_file(data_dir() / best.file)) << best.file;
    EXPECT_FALSE(best.provenance.empty()) << best.label << " says nothing of who reached it";
  }
  std::set<std::string> files;
  for (const auto& [n, of_n] : by_n) {
    // Ranks 1..m in order, d non-increasing, labels and files unique.
    for (std::size_t i = 0; i < of_n.size(); ++i) {
      EXPECT_EQ(of_n[i]->rank, static_cast<long>(i + 1)) << "n = " << n;
      const std::string prefix = std::string("t").append(std::to_string(n));
      EXPECT_EQ(of_n[i]->label.rfind(prefix, 0), 0u) << of_n[i]->label;
      EXPECT_TRUE(files.insert(of_n[i]->file).second) << of_n[i]->file << " named twice";
      if (i > 0) {
        const Real a(of_n[i - 1]->d), b(of_n[i]->d);
        EXPECT_GE(mpfr_cmp(a.v, b.v), 0) << of_n[i - 1]->label << " below " << of_n[i]->label;
      }
    }
    if (n >= 16 && n <= 34)
      EXPECT_LE(of_n.size(), 20u) << "n = " << n;
    else
      EXPECT_EQ(of_n.size(), 1u) << "n = " << n;
  }
}

// Every best of n = 2..300 was reached by at least 3 independent searches (a builder
// counts as one), or data/atlas-unconfirmed.csv (`n,why`) names it with the reason; a listed n
// must really be below 3, so the list cannot outlive the data.
TEST(AtlasData, EveryBestIsConfirmedThreeTimesOrSaysWhyNot) {
  std::map<long, std::string> unconfirmed;
  std::ifstream list(data_dir() / "atlas-unconfirmed.csv");
  ASSERT_TRUE(list) << "cannot read atlas-unconfirmed.csv";
  std::string line;
  std::getline(list, line);
  ASSERT_EQ(line, "n,why");
  while (std::getline(list, line)) {
    if (line.empty()) continue;
    const auto f = fields_of(line);
    ASSERT_EQ(f.size(), 2u) << line;
    ASSERT_FALSE(f[1].empty()) << "n = " << f[0] << " without a reason";
    unconfirmed[std::stol(f[0])] = f[1];
  }
  for (const auto& r : read_table()) {
    if (r.rank != 1 || r.n < 2 || r.n > 300) continue;
    EXPECT_GE(r.confirmations, 0) << r.label;
    if (unconfirmed.count(r.n))
      EXPECT_LT(r.confirmations, 3) << r.label << " is confirmed: remove it from the list";
    else
      EXPECT_GE(r.confirmations, 3) << r.label << " has " << r.confirmations
                                    << " confirmations and no reason in atlas-unconfirmed.csv";
  }
}

// Containment and the minimum distance of every file, in MPFR. Tolerances: the coordinates are
// written with 30 decimals (rounding <= 5e-31 each), so a distance or a signed distance to a side
// is off by at most ~2e-30 of the side; d >= 1/30 here, so 1e-28 relative is 30x that margin and
// far below the 1e-15 a double computation would reach.
TEST(AtlasData, EveryFileIsInsideTheTriangleWithMinimumDistanceD) {
  const auto rows = read_table();
  ASSERT_FALSE(rows.empty());
  Real root3, tolerance, dx, dy, dist, side, bound;
  mpfr_sqrt_ui(root3.v, 3, MPFR_RNDN);
  mpfr_set_str(tolerance.v, "1e-29", 10, MPFR_RNDN);
  long checked = 0;
  for (const auto& row : rows) {
    SCOPED_TRACE(row.label);
    EXPECT_EQ(significant_digits(row.d), 30) << row.d;
    const PointsFile file = read_points(data_dir() / row.file);
    ASSERT_EQ(file.n, row.n);
    ASSERT_EQ(static_cast<long>(file.points.size()), row.n);
    ASSERT_EQ(file.d, row.d) << "the file's # d: header is not the table's d";
    const Real d(row.d);
    std::vector<Real> x(file.points.size()), y(file.points.size());
    std::vector<double> xd, yd;
    for (std::size_t i = 0; i < file.points.size(); ++i) {
      mpfr_set_str(x[i].v, file.points[i].first.c_str(), 10, MPFR_RNDN);
      mpfr_set_str(y[i].v, file.points[i].second.c_str(), 10, MPFR_RNDN);
      xd.push_back(x[i].to_double());
      yd.push_back(y[i].to_double());
      // Signed distances to the three sides: y, (sqrt3 x - y)/2, (sqrt3 (1 - x) - y)/2.
      mpfr_neg(bound.v, tolerance.v, MPFR_RNDN);
      EXPECT_GE(mpfr_cmp(y[i].v, bound.v), 0) << "disk " << i << " below the floor";
      mpfr_mul(side.v, root3.v, x[i].v, MPFR_RNDN);
      mpfr_sub(side.v, side.v, y[i].v, MPFR_RNDN);
      mpfr_div_ui(side.v, side.v, 2, MPFR_RNDN);
      EXPECT_GE(mpfr_cmp(side.v, bound.v), 0) << "disk " << i << " beyond the left side";
      mpfr_ui_sub(side.v, 1, x[i].v, MPFR_RNDN);
      mpfr_mul(side.v, side.v, root3.v, MPFR_RNDN);
      mpfr_sub(side.v, side.v, y[i].v, MPFR_RNDN);
      mpfr_div_ui(side.v, side.v, 2, MPFR_RNDN);
      EXPECT_GE(mpfr_cmp(side.v, bound.v), 0) << "disk " << i << " beyond the right side";
    }
    // Every pair in double first (1e-16 relative); the pairs within 1e-9 of d again in MPFR.
    const double d_double = d.to_double();
    double smallest_double = 1e300;
    Real smallest;
    mpfr_set_inf(smallest.v, 1);
    for (std::size_t i = 0; i < xd.size(); ++i)
      for (std::size_t j = i + 1; j < xd.size(); ++j) {
        const double dd = std::hypot(xd[i] - xd[j], yd[i] - yd[j]);
        smallest_double = std::min(smallest_double, dd);
        if (dd > d_double * (1 + 1e-9)) continue;
        mpfr_sub(dx.v, x[i].v, x[j].v, MPFR_RNDN);
        mpfr_sub(dy.v, y[i].v, y[j].v, MPFR_RNDN);
        mpfr_hypot(dist.v, dx.v, dy.v, MPFR_RNDN);
        mpfr_min(smallest.v, smallest.v, dist.v, MPFR_RNDN);
      }
    ASSERT_GE(smallest_double, d_double * (1 - 1e-9)) << "a pair far closer than d";
    // |min distance - d| <= 1e-28 d.
    mpfr_sub(dist.v, smallest.v, d.v, MPFR_RNDN);
    mpfr_abs(dist.v, dist.v, MPFR_RNDN);
    mpfr_div(dist.v, dist.v, d.v, MPFR_RNDN);
    mpfr_set_str(bound.v, "1e-28", 10, MPFR_RNDN);
    EXPECT_LE(mpfr_cmp(dist.v, bound.v), 0)
        << "min distance " << smallest.to_double() << " is not d = " << row.d << " (relative "
        << dist.to_double() << ")";
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<long>(rows.size()));
}

}  // namespace
