// constructors/chain: the one-unknown ripple chain against the closed forms of docs/classes.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "constructors/chain.hpp"

namespace tripack {
namespace {

// The chain is solved by bisection in long double (eps 1.1e-19); 1e-17 allows the march's
// rounding (a few dozen operations) with margin.
constexpr long double kTol = 1e-17L;

TEST(RippleChain, AnchorStepTwoClosedForms) {
  // docs/classes.md §4a: X_1 = sqrt3/2, X_2 = sqrt(2/3), X_3 = (7 + 2 sqrt11)/(10 sqrt3).
  EXPECT_NEAR(solve_ripple_chain(1, 2).X, std::sqrt(3.0L) / 2, kTol);
  EXPECT_NEAR(solve_ripple_chain(2, 2).X, std::sqrt(2.0L / 3), kTol);
  EXPECT_NEAR(solve_ripple_chain(3, 2).X, (7 + 2 * std::sqrt(11.0L)) / (10 * std::sqrt(3.0L)),
              kTol);
  // X_4^2 is a root of 432x^3 - 63x^2 - 114x + 1 (PSLQ, docs/classes.md §4a). The polynomial's
  // derivative there is ~300, so the residual is ~300 * 2 X * error.
  const long double x = std::pow(solve_ripple_chain(4, 2).X, 2);
  EXPECT_NEAR(432 * x * x * x - 63 * x * x - 114 * x + 1, 0, 1e-15);
}

TEST(RippleChain, AnchorStepOneClosedForms) {
  // docs/classes.md §5-6: Y_1^2 = 3/4, Y_2^2 = 11/12, Y_3 = (1 + sqrt2)/sqrt6,
  // Y_4^2 a root of 432y^3 - 360y^2 - 69y + 1.
  EXPECT_NEAR(std::pow(solve_ripple_chain(1, 1).X, 2), 0.75L, kTol);
  EXPECT_NEAR(std::pow(solve_ripple_chain(2, 1).X, 2), 11.0L / 12, kTol);
  EXPECT_NEAR(solve_ripple_chain(3, 1).X, (1 + std::sqrt(2.0L)) / std::sqrt(6.0L), kTol);
  const long double y = std::pow(solve_ripple_chain(4, 1).X, 2);
  EXPECT_NEAR(432 * y * y * y - 360 * y * y - 69 * y + 1, 0, 1e-15);
  // Y_k -> 1 super-exponentially: 1 - Y_5 = 7.1e-4, 1 - Y_7 = 1.6e-6, 1 - Y_9 = 6.5e-12
  // (docs/classes.md §5-6, two printed digits).
  EXPECT_NEAR(1 - solve_ripple_chain(5, 1).X, 7.1e-4L, 0.05e-4L);
  EXPECT_NEAR(1 - solve_ripple_chain(7, 1).X, 1.6e-6L, 0.05e-6L);
  EXPECT_NEAR(1 - solve_ripple_chain(9, 1).X, 6.5e-12L, 0.05e-12L);
}

TEST(RippleChain, EveryContactHoldsAndTheCornersHoldWithoutError) {
  for (int step : {1, 2}) {
    for (int q : {1, 2, 3, 5, 8, 13, 40}) {
      if (step == 1 && q > 12) continue;  // beyond the class's valid range
      const RippleChain c = solve_ripple_chain(q, step);
      EXPECT_EQ(c.floor.front().x, 0);
      EXPECT_NEAR(c.floor.back().x, c.L, 1e-17L * c.L);
      EXPECT_NEAR(c.L, (q - 1) * step + 2 * c.X, 1e-17L * c.L);
      for (int i = 0; i < q; ++i) {
        const auto& r = c.raised[static_cast<std::size_t>(i)];
        EXPECT_NEAR(norm(r - c.floor[static_cast<std::size_t>(i)]), 1, 1e-16L) << q << " " << i;
        EXPECT_NEAR(norm(r - c.floor[static_cast<std::size_t>(i + 1)]), 1, 1e-16L) << q << " " << i;
        EXPECT_NEAR(norm(r - c.anchor(i)), 1, 1e-16L) << q << " " << i;
      }
    }
  }
}

TEST(RippleChain, LongChainsCloseAndXDecreases) {
  // Long chains (step 2, q >= ~250) cannot be marched just above their root; the solver must
  // still find it. X_p decreases slowly with p (docs/classes.md §4a, "X_p decreases slowly").
  long double previous = 1;
  for (int q : {1, 2, 3, 5, 10, 20, 50, 100, 200, 300, 700}) {
    const RippleChain c = solve_ripple_chain(q, 2);
    EXPECT_LT(c.X, previous) << q;
    previous = c.X;
    long double worst = 0;
    for (int i = 0; i < q; ++i) {
      const auto& r = c.raised[static_cast<std::size_t>(i)];
      worst = std::max(worst, std::fabs(norm(r - c.floor[static_cast<std::size_t>(i)]) - 1));
      worst = std::max(worst, std::fabs(norm(r - c.floor[static_cast<std::size_t>(i + 1)]) - 1));
      worst = std::max(worst, std::fabs(norm(r - c.anchor(i)) - 1));
    }
    // Measured: 3e-17 at q = 200, 1.5e-16 at q = 300..700 (the march amplifies rounding).
    EXPECT_LT(worst, 1e-15L) << q;
  }
  // The paper's bound on lim delta(Delta(k)+1) is 2/sqrt3 - 1 (GL1995 Sec.6), which needs
  // X_p -> 1/sqrt3 from above: every X_p stays above it.
  EXPECT_GT(previous, 1 / std::sqrt(3.0L));
}

TEST(RippleChain, RejectsBadArguments) {
  EXPECT_THROW(solve_ripple_chain(0, 2), std::invalid_argument);
  EXPECT_THROW(solve_ripple_chain(3, 3), std::invalid_argument);
}

}  // namespace
}  // namespace tripack
