// core/expression: the catalogue's formula language.
#include <gtest/gtest.h>

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
