// core/expression: the catalogue's formula language.
#include <gtest/gtest.h>

#include "constructors/catalogue.hpp"
#include "core/expression.hpp"

namespace tripack {
namespace {

ExpressionEnv<long long> ints(long long k, long long p = 0) {
  ExpressionEnv<long long> e;
  e.variable = [=](std::string_view n) -> std::optional<long long> {
    if (n == "k") return k;
    if (n == "p") return p;
    return std::nullopt;
  };
  return e;
}

TEST(Expression, PrecedenceAndAssociativity) {
  EXPECT_EQ(Expression::parse("1+2*3").eval<long long>({}), 7);
  EXPECT_EQ(Expression::parse("(1+2)*3").eval<long long>({}), 9);
  EXPECT_EQ(Expression::parse("10-4-3").eval<long long>({}), 3);
  EXPECT_EQ(Expression::parse("2^3^2").eval<long long>({}), 512);  // right-associative
  EXPECT_EQ(Expression::parse("-2^2").eval<long long>({}), -4);
  EXPECT_EQ(Expression::parse("6*k^2+3*k").eval<long long>(ints(3)), 63);
}

TEST(Expression, DeltaAndTheMatrixFormula) {
  // GL1995 eq.(3): n_p(k) = Delta((k+1)(p+1)-2) + k = Delta((k+1)p-1) + (2p+1) Delta(k).
  const auto a = Expression::parse("Delta((k+1)*(p+1)-2)+k");
  const auto b = Expression::parse("Delta((k+1)*p-1)+(2*p+1)*Delta(k)");
  for (long long p = 1; p <= 20; ++p)
    for (long long k = 1; k <= 20; ++k)
      EXPECT_EQ(a.eval<long long>(ints(k, p)), b.eval<long long>(ints(k, p)));
  EXPECT_EQ(a.eval<long long>(ints(1, 3)), 22);
}

// max(a, b): the odd-ripple other modification's one extra bond at k = 2 (its R1 touches A2).
TEST(Expression, MaxForASmallKException) {
  const auto e = Expression::parse("6*k^2+k+6 + max(0, 3-k)");
  EXPECT_EQ(e.eval<long long>(ints(2)), 33);   // t16a33
  EXPECT_EQ(e.eval<long long>(ints(3)), 63);   // t29a
  EXPECT_EQ(e.eval<long long>(ints(4)), 106);  // t46a
  EXPECT_EQ(Expression::parse("max(2.5, -1)").eval<long double>({}), 2.5L);
}

TEST(Expression, RealsAndSqrt) {
  const auto e = Expression::parse("2*k-2+sqrt(3)");
  ExpressionEnv<long double> env;
  env.variable = [](std::string_view n) -> std::optional<long double> {
    if (n == "k") return 3.0L;
    return std::nullopt;
  };
  EXPECT_NEAR(e.eval<long double>(env), 4 + std::sqrt(3.0L), 1e-18);
  EXPECT_NEAR(Expression::parse("1.5e1/3").eval<long double>({}), 5, 0);
}

TEST(Expression, ErrorsAreReported) {
  EXPECT_THROW(Expression::parse("1+"), ExpressionError);
  EXPECT_THROW(Expression::parse("(1+2"), ExpressionError);
  EXPECT_THROW(Expression::parse("1 2"), ExpressionError);
  EXPECT_THROW(Expression::parse("k$"), ExpressionError);
  EXPECT_THROW(Expression::parse("q+1").eval<long long>(ints(1)),
               ExpressionError);                                                // unknown variable
  EXPECT_THROW(Expression::parse("7/2").eval<long long>({}), ExpressionError);  // inexact
  EXPECT_THROW(Expression::parse("sqrt(4)").eval<long long>({}), ExpressionError);  // not integral
  EXPECT_THROW(Expression::parse("foo(1)").eval<long double>({}),
               ExpressionError);  // unknown function
  EXPECT_EQ(Expression::parse("k*p+k").variables(), (std::vector<std::string>{"k", "p"}));
}

}  // namespace
}  // namespace tripack

namespace tripack {
namespace {

// Findings of the fuzzers (fuzz/findings/fuzz_formula): each is now a one-line ExpressionError.
TEST(Expression, FuzzFindingsAreErrorsNotCrashes) {
  auto error_of = [](const std::string& formula) -> std::string {
    try {
      Expression::parse(formula).eval<long long>({});
    } catch (const ExpressionError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error_of("33^22").find("integer overflow"), std::string::npos);
  EXPECT_NE(error_of("9999999999*9999999999").find("integer overflow"), std::string::npos);
  EXPECT_NE(error_of("9223372036854775807+1").find("integer overflow"), std::string::npos);
  EXPECT_NE(error_of("Delta(4294967296)").find("integer overflow"), std::string::npos);
  // 1^(10^12) and 2^62 by square and multiply: exact, at once.
  EXPECT_EQ(Expression::parse("1^999999999999").eval<long long>({}), 1);
  EXPECT_EQ(Expression::parse("2^62").eval<long long>({}), 4611686018427387904LL);
  EXPECT_EQ(Expression::parse("(-3)^5").eval<long long>({}), -243);
  EXPECT_NE(error_of("2^63").find("integer overflow"), std::string::npos);
  EXPECT_THROW(Expression::parse(std::string(3000, '(') + "1"), ExpressionError);
  EXPECT_EQ(
      Expression::parse(std::string(50, '(') + "1" + std::string(50, ')')).eval<long long>({}), 1);
  // ripple(q) needs an integer chain length the solver can take.
  for (const char* bad : {"ripple(1e300)", "ripple(100000000)", "ripple(-1)", "ripple(2.5)"})
    EXPECT_THROW(Expression::parse(bad).eval<long double>(real_env(1, 0)), ExpressionError) << bad;
}

}  // namespace
}  // namespace tripack
