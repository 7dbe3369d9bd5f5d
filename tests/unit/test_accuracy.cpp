// jobs/accuracy: digits of d against time (docs/accuracy.md) and the hard cases' stability.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "jobs/accuracy.hpp"

namespace tripack::jobs {
namespace {

// d(22) = 5 sqrt3 / (20 sqrt3 + 7 + 2 sqrt11) (docs/classes.md), 50 digits.
const std::string kD22 = "0.17939690861186597956121884705073659574141764618876";

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

// ctest runs every TEST in its own process, so the table (n = 22, ~0.1 s) and the hard cases
// (~4 s) are measured by the tests that need them, each once.
const AccuracyStudy& table() {
  static const AccuracyStudy s = [] {
    AccuracySettings settings;
    settings.n = {22};
    settings.hard_cases = false;
    return measure_accuracy(catalogue(), settings);
  }();
  return s;
}

const AccuracyStudy& hard() {
  static const AccuracyStudy s = [] {
    AccuracySettings settings;
    settings.n = {};
    settings.hard_case_dir = TRIPACK_SOURCE_DIR "/data/hard";
    return measure_accuracy(catalogue(), settings);
  }();
  return s;
}

std::vector<const AccuracyRow*> rows_of(const std::string& method) {
  std::vector<const AccuracyRow*> out;
  for (const auto& r : table().rows)
    if (r.method == method) out.push_back(&r);
  return out;
}

TEST(Accuracy, CorrectDigitsCountsAgreeingDigitsOfDecimalStrings) {
  // Equal strings: the cap.
  EXPECT_EQ(correct_digits(kD22, kD22, 50), 50);
  // d(22) cut after 25 decimals: |error| = 4.7050736...e-26, relative 2.6227e-25: 24.5812 digits.
  EXPECT_NEAR(correct_digits("0.1793969086118659795612188", kD22, 100), 24.58125, 1e-4);
  // A borrow across many digits, and the value above the reference: 0.18 - d(22) = 6.0309e-4,
  // relative 3.3618e-3: 2.4734 digits.
  EXPECT_NEAR(correct_digits("0.18", kD22, 100), 2.47343, 1e-4);
  // Integer parts and unequal lengths: |1.5 - 1.25| / 1.25 = 0.2.
  EXPECT_NEAR(correct_digits("1.5", "1.25", 100), -std::log10(0.2), 1e-12);
  EXPECT_EQ(correct_digits("0.1793", kD22, 3), 3);  // capped
  EXPECT_THROW(correct_digits("1e-3", kD22, 10), std::invalid_argument);
}

TEST(Accuracy, BilliardsDigitsGrowWithTheGapAndPolishersReachTheirPrecision) {
  const auto billiards = rows_of("billiards");
  ASSERT_EQ(billiards.size(), 4u);
  const std::vector<std::string> targets{"gap 1e-3", "gap 1e-6", "gap 1e-9", "gap 1e-12"};
  for (std::size_t i = 0; i < billiards.size(); ++i) {
    EXPECT_EQ(billiards[i]->target, targets[i]);
    EXPECT_EQ(billiards[i]->n, 22);
    EXPECT_GT(billiards[i]->seconds, 0);
  }
  // Each target is 1000x tighter: 3 more digits, less the error of the engine's gap estimate,
  // which is conservative by a factor 2-10 (sim/README.md): at most 1 digit off at either end,
  // so a step gains >= 2 digits.
  for (std::size_t i = 1; i < billiards.size(); ++i)
    EXPECT_GE(billiards[i]->digits, billiards[i - 1]->digits + 2) << billiards[i]->target;
  EXPECT_GE(billiards.back()->digits, 10);

  const auto polish = rows_of("polish (long double)");
  ASSERT_EQ(polish.size(), 1u);
  EXPECT_EQ(polish[0]->target, "double");
  EXPECT_GE(polish[0]->digits, 14);

  // MPFR prints `digits` significant digits, rounded: half a unit in the last place over a
  // d = m 10^e with 0.1 <= m < 1 is a relative error of at most 5 10^-digits, so >= digits - 0.7.
  const auto mpfr = rows_of("mpfr");
  ASSERT_EQ(mpfr.size(), 3u);
  const std::vector<std::pair<std::string, double>> asked{
      {"30 digits", 29}, {"50 digits", 49}, {"100 digits", 99}};
  for (std::size_t i = 0; i < mpfr.size(); ++i) {
    EXPECT_EQ(mpfr[i]->target, asked[i].first);
    EXPECT_GE(mpfr[i]->digits, asked[i].second) << mpfr[i]->target;
    EXPECT_LE(mpfr[i]->digits, asked[i].second + 1) << "capped at the precision asked";
  }
  // Every row names the packing it measured and carries its reference.
  for (const auto& r : table().rows) {
    EXPECT_FALSE(r.label.empty());
    EXPECT_EQ(r.reference.size(), 22u) << r.method << " " << r.target;
  }
  EXPECT_GT(table().seconds, 0);
  EXPECT_TRUE(table().hard_cases.empty());
}

const HardCase* hard_case(const std::string& prefix) {
  for (const auto& h : hard().hard_cases)
    if (h.name.rfind(prefix, 0) == 0) return &h;
  return nullptr;
}

bool says(const HardCase* h, const std::string& text) {
  return h && h->evidence.find(text) != std::string::npos;
}

TEST(Accuracy, HardCasesAreStableReproduceThePaperAndKeepTheOrderOf33) {
  const auto& cases = hard().hard_cases;
  ASSERT_EQ(cases.size(), 8u);
  EXPECT_TRUE(hard().rows.empty());
  for (const auto& h : cases) {
    EXPECT_TRUE(h.stable) << h.name << ": " << h.evidence;
    EXPECT_FALSE(h.what.empty()) << h.name;
    EXPECT_EQ(h.evidence.find("error"), std::string::npos) << h.name << ": " << h.evidence;
  }
  // Near contacts as the paper gives them (GL1995, remarks on t18, t33, t34).
  EXPECT_TRUE(says(hard_case("t18a"), "= 0.0048728 d"));
  EXPECT_TRUE(says(hard_case("t33a"), "= 0.0017032 d"));
  EXPECT_TRUE(says(hard_case("t34a"), "gaps 5 x 0.021359, 2 x 0.024750, 2 x 0.042561"));
  // The corner case is t22a: d(22) rounded to the 15 digits the evidence prints (the paper's
  // 0.17939 69086 11866; the closed form continues 0.1793969086118659|79...).
  EXPECT_TRUE(says(hard_case("corner"), "d = 0.179396908611866)"));
  // The two packings of 33 disks 8.5e-9 apart: three searches over different seeds and thread
  // counts each rank the 78-bond one above the 74-bond one, under different labels.
  const HardCase* pair = hard_case("t33 close pair");
  ASSERT_NE(pair, nullptr);
  std::size_t above = 0;
  for (auto at = pair->evidence.find(" above "); at != std::string::npos;
       at = pair->evidence.find(" above ", at + 1))
    ++above;
  EXPECT_EQ(above, 3u) << pair->evidence;
  EXPECT_FALSE(says(pair, "not both found")) << pair->evidence;
}

}  // namespace
}  // namespace tripack::jobs
