// exact/field_kernel.hpp: kernels over number fields by elimination modulo primes. Expected
// values are closed forms (a cross product over Q) or are checked independently: every returned
// vector is evaluated with MPFR at the real root of K(t) and A v must vanish there to the
// working precision, with the shape (1 at its free column, 0 at the others) of a reduced basis.
#include <gtest/gtest.h>
#include <mpfr.h>

#include <string>
#include <vector>

#include "exact/field_kernel.hpp"

namespace tripack::exact {
namespace {

constexpr mpfr_prec_t bits = 4000;

// p/q or p, exactly as an MPFR number at `bits`.
void set_rational(mpfr_t out, const std::string& text) {
  mpfr_t den;
  mpfr_init2(den, bits);
  const auto slash = text.find('/');
  mpfr_set_str(out, text.substr(0, slash).c_str(), 10, MPFR_RNDN);
  mpfr_set_ui(den, 1, MPFR_RNDN);
  if (slash != std::string::npos) mpfr_set_str(den, text.substr(slash + 1).c_str(), 10, MPFR_RNDN);
  mpfr_div(out, out, den, MPFR_RNDN);
  mpfr_clear(den);
}

// The polynomial at t (Horner).
void evaluate(mpfr_t out, const RationalPolynomial& a, const mpfr_t t) {
  mpfr_t c;
  mpfr_init2(c, bits);
  mpfr_set_ui(out, 0, MPFR_RNDN);
  for (auto it = a.coefficients.rbegin(); it != a.coefficients.rend(); ++it) {
    set_rational(c, *it);
    mpfr_mul(out, out, t, MPFR_RNDN);
    mpfr_add(out, out, c, MPFR_RNDN);
  }
  mpfr_clear(c);
}

RationalPolynomial poly(std::vector<std::string> c) {
  return RationalPolynomial{std::move(c)};
}

// max_r |sum_c A[r][c](t) v[c](t)| / max |v(t)|, log2; -infinity-like when exactly 0.
double log2_residual(const std::vector<std::vector<RationalPolynomial>>& a,
                     const std::vector<RationalPolynomial>& v, const mpfr_t t) {
  mpfr_t sum, x, y, worst, scale;
  for (auto* m : {&sum, &x, &y, &worst, &scale}) mpfr_init2(*m, bits);
  mpfr_set_ui(worst, 0, MPFR_RNDN);
  mpfr_set_ui(scale, 0, MPFR_RNDN);
  for (const auto& e : v) {
    evaluate(x, e, t);
    mpfr_abs(x, x, MPFR_RNDN);
    mpfr_max(scale, scale, x, MPFR_RNDN);
  }
  for (const auto& row : a) {
    mpfr_set_ui(sum, 0, MPFR_RNDN);
    for (std::size_t c = 0; c < row.size(); ++c) {
      evaluate(x, row[c], t);
      evaluate(y, v[c], t);
      mpfr_mul(x, x, y, MPFR_RNDN);
      mpfr_add(sum, sum, x, MPFR_RNDN);
    }
    mpfr_abs(sum, sum, MPFR_RNDN);
    mpfr_max(worst, worst, sum, MPFR_RNDN);
  }
  double result = -1e9;
  if (!mpfr_zero_p(worst)) {
    mpfr_div(worst, worst, scale, MPFR_RNDN);
    result = mpfr_get_d(worst, MPFR_RNDN) > 0 ? static_cast<double>(mpfr_get_exp(worst)) : -1e9;
  }
  for (auto* m : {&sum, &x, &y, &worst, &scale}) mpfr_clear(*m);
  return result;
}

bool is_zero(const RationalPolynomial& a) {
  for (const auto& c : a.coefficients)
    if (c != "0") return false;
  return true;
}
bool is_one(const RationalPolynomial& a) {
  if (a.coefficients.empty() || a.coefficients[0] != "1") return false;
  for (std::size_t i = 1; i < a.coefficients.size(); ++i)
    if (a.coefficients[i] != "0") return false;
  return true;
}

// Each basis vector vanishes under A at t0 and has the reduced shape at the free columns.
void expect_reduced_kernel(const std::vector<std::vector<RationalPolynomial>>& a,
                           const FieldKernel& kernel, const mpfr_t t0) {
  ASSERT_TRUE(kernel.reason.empty()) << kernel.reason;
  std::vector<int> free;
  for (int c = 0; c < static_cast<int>(a[0].size()); ++c)
    if (!std::binary_search(kernel.shape.pivot_columns.begin(), kernel.shape.pivot_columns.end(),
                            c))
      free.push_back(c);
  ASSERT_EQ(kernel.basis.size(), free.size());
  for (std::size_t k = 0; k < kernel.basis.size(); ++k) {
    for (std::size_t f = 0; f < free.size(); ++f) {
      const auto& e = kernel.basis[k][static_cast<std::size_t>(free[f])];
      EXPECT_TRUE(f == k ? is_one(e) : is_zero(e)) << "vector " << k << " at free column " << f;
    }
    // Exact vectors: the residual is rounding at `bits` bits (about 2^-3990 relative); a vector
    // that is not in the kernel misses by far more than 2^-3000.
    EXPECT_LT(log2_residual(a, kernel.basis[k], t0), -3000.0) << "vector " << k;
  }
}

// Over Q (K = t): the kernel of [[1, 2, 3], [4, 5, 6]] is the cross product (-3, 6, -3), i.e.
// (1, -2, 1) with 1 at the free column 2.
TEST(FieldKernel, OverTheRationalsIsTheCrossProduct) {
  const IntegerPolynomial k{{"0", "1"}};
  const std::vector<std::vector<RationalPolynomial>> a = {{poly({"1"}), poly({"2"}), poly({"3"})},
                                                          {poly({"4"}), poly({"5"}), poly({"6"})}};
  const FieldKernel kernel = kernel_over_field(a, k);
  ASSERT_TRUE(kernel.reason.empty()) << kernel.reason;
  EXPECT_EQ(kernel.shape.rank, 2);
  EXPECT_EQ(kernel.shape.pivot_columns, (std::vector<int>{0, 1}));
  ASSERT_EQ(kernel.basis.size(), 1u);
  EXPECT_EQ(kernel.basis[0][0].coefficients, (std::vector<std::string>{"1"}));
  EXPECT_EQ(kernel.basis[0][1].coefficients, (std::vector<std::string>{"-2"}));
  EXPECT_EQ(kernel.basis[0][2].coefficients, (std::vector<std::string>{"1"}));
  // The kernel vector with 3/7 at the free column is 3/7 times it.
  const KernelVectors scaled = kernel_vectors(a, k, kernel.shape, {{"3/7"}});
  ASSERT_TRUE(scaled.reason.empty()) << scaled.reason;
  ASSERT_EQ(scaled.vectors.size(), 1u);
  EXPECT_EQ(scaled.vectors[0][0].coefficients, (std::vector<std::string>{"3/7"}));
  EXPECT_EQ(scaled.vectors[0][1].coefficients, (std::vector<std::string>{"-6/7"}));
  EXPECT_EQ(scaled.vectors[0][2].coefficients, (std::vector<std::string>{"3/7"}));
}

// A 3 x 5 matrix over Q(2^(1/3)) with small entries (two free columns), and the same matrix with
// rows of 150-digit rational coefficients, whose kernel has coefficients of hundreds of digits:
// reconstructed from many primes, each vector checked at t0 = 2^(1/3) with MPFR.
TEST(FieldKernel, OverACubicFieldSmallAndTallEntries) {
  const IntegerPolynomial k{{"-2", "0", "0", "1"}};
  mpfr_t t0;
  mpfr_init2(t0, bits);
  mpfr_set_ui(t0, 2, MPFR_RNDN);
  mpfr_cbrt(t0, t0, MPFR_RNDN);
  std::vector<std::vector<RationalPolynomial>> a = {
      {poly({"1", "1"}), poly({"0", "2"}), poly({"3"}), poly({"1", "0", "1"}), poly({"-1"})},
      {poly({"2"}), poly({"1", "-1", "1"}), poly({"0", "0", "5"}), poly({"4"}), poly({"1", "1"})},
      {poly({"0", "3"}), poly({"7"}), poly({"1", "2", "3"}), poly({"-2", "1"}), poly({"0"})}};
  const FieldKernel small = kernel_over_field(a, k);
  EXPECT_EQ(small.shape.rank, 3);
  expect_reduced_kernel(a, small, t0);
  std::string tall = "1", other = "-";
  tall.append(150, '3').append("7/9").append(140, '1');
  other.append(149, '8').append("1/7").append(151, '0').append("3");
  a[0][4] = poly({tall, "1"});
  a[1][2] = poly({other, "0", tall});
  a[2][0] = poly({"5", other});
  const FieldKernel big = kernel_over_field(a, k);
  EXPECT_EQ(big.shape.rank, 3);
  EXPECT_GT(big.primes, 30) << "hundreds of digits need tens of 62-bit primes";
  expect_reduced_kernel(a, big, t0);
  mpfr_clear(t0);
}

// Row 3 = row 1 + t row 2 over Q(sqrt 2): rank 2, so a kernel of dimension 2 in 4 columns, found
// and verified: the rank over K is then 2 exactly. The shape alone says rank 2 of 3 rows.
TEST(FieldKernel, ADependentRowLowersTheRank) {
  const IntegerPolynomial k{{"-2", "0", "1"}};
  mpfr_t t0;
  mpfr_init2(t0, bits);
  mpfr_sqrt_ui(t0, 2, MPFR_RNDN);
  // row 1 = (1, t, 3, 0), row 2 = (2, 1, t, 1); t row 2 = (2t, t, 2, t) since t^2 = 2.
  const std::vector<std::vector<RationalPolynomial>> a = {
      {poly({"1"}), poly({"0", "1"}), poly({"3"}), poly({"0"})},
      {poly({"2"}), poly({"1"}), poly({"0", "1"}), poly({"1"})},
      {poly({"1", "2"}), poly({"0", "2"}), poly({"5"}), poly({"0", "1"})}};
  const FieldKernel kernel = kernel_over_field(a, k);
  EXPECT_EQ(kernel.shape.rank, 2);
  expect_reduced_kernel(a, kernel, t0);
  const KernelShape shape = kernel_shape(a, k);
  EXPECT_EQ(shape.rank, 2);
  EXPECT_EQ(shape.primes, 3) << "a rank below the rows is looked at modulo three primes";
  mpfr_clear(t0);
}

// Entries given unreduced (t^2 in Q(sqrt 2) is 2) and with denominators: the same kernel as the
// reduced integral matrix, (t, 1) for the row (t^2/6, -t/3) = (1/3, -t/3).
TEST(FieldKernel, UnreducedEntriesAndDenominators) {
  const IntegerPolynomial k{{"-2", "0", "1"}};
  const std::vector<std::vector<RationalPolynomial>> a = {
      {poly({"0", "0", "1/6"}), poly({"0", "-1/3"})}};
  const FieldKernel kernel = kernel_over_field(a, k);
  ASSERT_TRUE(kernel.reason.empty()) << kernel.reason;
  ASSERT_EQ(kernel.basis.size(), 1u);
  EXPECT_EQ(kernel.basis[0][0].coefficients, (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(kernel.basis[0][1].coefficients, (std::vector<std::string>{"1"}));
}

// A shape that is not the matrix's (pivots 0 and 2 where they are 0 and 1) gives no vector: every
// prime's elimination disagrees with it, and the call says so rather than return one.
TEST(FieldKernel, AShapeThatIsNotTheMatrixsGivesNoVector) {
  const IntegerPolynomial k{{"0", "1"}};
  const std::vector<std::vector<RationalPolynomial>> a = {{poly({"1"}), poly({"2"}), poly({"3"})},
                                                          {poly({"4"}), poly({"5"}), poly({"6"})}};
  KernelShape wrong;
  wrong.rank = 2;
  wrong.pivot_columns = {0, 2};
  const KernelVectors none = kernel_vectors(a, k, wrong, {{"1"}});
  EXPECT_TRUE(none.vectors.empty());
  EXPECT_NE(none.reason.find("without the shape's pivots"), std::string::npos) << none.reason;
}

}  // namespace
}  // namespace tripack::exact
