#include "exact/optimality.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>

#include "exact/field_kernel.hpp"
#include "exact/flint_tools.hpp"

namespace tripack::exact {

namespace {

using flint::Arb;
using flint::FmpqPoly;

// A matrix of elements of K.
class Matrix {
 public:
  Matrix(int rows, int columns) : rows_(rows), columns_(columns) {
    cells_.reserve(static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns));
    for (int i = 0; i < rows * columns; ++i) cells_.push_back(std::make_unique<FmpqPoly>());
  }
  fmpq_poly_struct* at(int r, int c) { return cells_[index(r, c)]->value; }
  int rows() const { return rows_; }
  int columns() const { return columns_; }
  void swap_rows(int a, int b) {
    for (int c = 0; c < columns_; ++c) std::swap(cells_[index(a, c)], cells_[index(b, c)]);
  }

 private:
  std::size_t index(int r, int c) const {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(columns_) +
           static_cast<std::size_t>(c);
  }
  int rows_, columns_;
  std::vector<std::unique_ptr<FmpqPoly>> cells_;
};

using Vector = std::vector<std::unique_ptr<FmpqPoly>>;  // a vector of elements of K, one a bond

Vector zero_vector(int size) {
  Vector v;
  for (int i = 0; i < size; ++i) v.push_back(std::make_unique<FmpqPoly>());
  return v;
}

// G^T over K: one row per coordinate of a held disk (column_of: the disk's first row), one column
// per bond.
Matrix transposed_bond_matrix(const ConfigurationInput& in, const ExactConfiguration& config,
                              const flint::Field& field, const std::map<int, int>& column_of) {
  const int bonds = static_cast<int>(in.bonds.size());
  Matrix gt(2 * static_cast<int>(column_of.size()), bonds);
  FmpqPoly xa, ya, xb, yb, s3;
  field.set(s3.value, config.sqrt3_in_field);
  for (int b = 0; b < bonds; ++b) {
    const Bond& bond = in.bonds[static_cast<std::size_t>(b)];
    const int ca = column_of.at(bond.a);
    field.set(xa.value, config.points[static_cast<std::size_t>(bond.a)][0]);
    field.set(ya.value, config.points[static_cast<std::size_t>(bond.a)][1]);
    if (bond.is_wall()) {
      switch (bond.side()) {
        case Side::Bottom:
          fmpq_poly_one(gt.at(ca + 1, b));
          break;
        case Side::Left:
          fmpq_poly_set(gt.at(ca, b), s3.value);
          fmpq_poly_set_si(gt.at(ca + 1, b), -1);
          break;
        case Side::Right:
          fmpq_poly_neg(gt.at(ca, b), s3.value);
          fmpq_poly_set_si(gt.at(ca + 1, b), -1);
          break;
      }
      continue;
    }
    const int cb = column_of.at(bond.b);
    field.set(xb.value, config.points[static_cast<std::size_t>(bond.b)][0]);
    field.set(yb.value, config.points[static_cast<std::size_t>(bond.b)][1]);
    fmpq_poly_sub(gt.at(ca, b), xa.value, xb.value);
    fmpq_poly_sub(gt.at(ca + 1, b), ya.value, yb.value);
    fmpq_poly_neg(gt.at(cb, b), gt.at(ca, b));
    fmpq_poly_neg(gt.at(cb + 1, b), gt.at(ca + 1, b));
  }
  return gt;
}

// G^T's rows as strings, for exact/field_kernel.hpp.
std::vector<std::vector<RationalPolynomial>> rows_of(Matrix& m) {
  std::vector<std::vector<RationalPolynomial>> rows(static_cast<std::size_t>(m.rows()));
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < m.columns(); ++c)
      rows[static_cast<std::size_t>(r)].push_back(flint::strings_from_fmpq_poly(m.at(r, c)));
  return rows;
}

// The reduced basis of the self-stresses at t0, numerically: 1 at its free column, 0 at the
// others, and V_P = -A_P^-1 A_F at the pivot columns P (A_P is square and invertible: G^T has
// full row rank). Only the combination below is taken from it; the stress itself is exact.
Eigen::MatrixXd numerical_basis(Matrix& gt, const std::vector<int>& pivots, const arb_t t0,
                                slong prec) {
  const auto rows = static_cast<Eigen::Index>(gt.rows());
  Eigen::MatrixXd a(rows, gt.columns());
  Arb value;
  for (int r = 0; r < gt.rows(); ++r)
    for (int c = 0; c < gt.columns(); ++c) {
      flint::Field::evaluate(value.value, gt.at(r, c), t0, prec);
      a(r, c) = arf_get_d(arb_midref(value.value), ARF_RND_NEAR);
    }
  const std::vector<int> free = free_columns(pivots, gt.columns());
  Eigen::MatrixXd a_pivot(rows, rows), a_free(rows, static_cast<Eigen::Index>(free.size()));
  for (Eigen::Index i = 0; i < rows; ++i)
    a_pivot.col(i) = a.col(pivots[static_cast<std::size_t>(i)]);
  for (std::size_t f = 0; f < free.size(); ++f)
    a_free.col(static_cast<Eigen::Index>(f)) = a.col(free[f]);
  const Eigen::MatrixXd v_pivot = -a_pivot.partialPivLu().solve(a_free);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero(gt.columns(), a_free.cols());
  for (Eigen::Index i = 0; i < rows; ++i)
    basis.row(pivots[static_cast<std::size_t>(i)]) = v_pivot.row(i);
  for (std::size_t f = 0; f < free.size(); ++f) basis(free[f], static_cast<Eigen::Index>(f)) = 1.0;
  return basis;
}

// The combination of the basis: one basis vector (sign made positive), or the least-squares fit
// of the numerical stress, rescaled to our rows (pair rows carry d, the side walls 2). Empty, with
// `reason` set, when there are several and no numerical stress.
std::optional<Eigen::VectorXd> stress_combination(const ConfigurationInput& in,
                                                  const ExactConfiguration& config,
                                                  const flint::Field& field,
                                                  const Eigen::MatrixXd& basis,
                                                  const std::vector<long double>& forces,
                                                  const arb_t t0, slong prec, std::string& reason) {
  const int bonds = static_cast<int>(in.bonds.size());
  Eigen::VectorXd coefficients(basis.cols());
  if (basis.cols() == 1) {
    coefficients(0) = basis.col(0).sum() < 0 ? -1.0 : 1.0;
    return coefficients;
  }
  if (forces.size() != static_cast<std::size_t>(bonds)) {
    reason = fmt::format("{} self-stresses and no numerical stress to combine them", basis.cols());
    return std::nullopt;
  }
  Arb dv;
  FmpqPoly dk;
  field.set(dk.value, config.d_in_field);
  flint::Field::evaluate(dv.value, dk.value, t0, prec);
  const double d = arf_get_d(arb_midref(dv.value), ARF_RND_NEAR);
  Eigen::VectorXd target(bonds);
  for (int b = 0; b < bonds; ++b) {
    const Bond& bond = in.bonds[static_cast<std::size_t>(b)];
    const double f = static_cast<double>(forces[static_cast<std::size_t>(b)]);
    target(b) = !bond.is_wall() ? f / d : (bond.side() == Side::Bottom ? f : f / 2);
  }
  coefficients = basis.colPivHouseholderQr().solve(target);
  return coefficients;
}

// The combination's coefficients rounded to rationals (52 bits of the largest), as the stress's
// values at the free columns: the stress is then exact whatever the coefficients are.
std::vector<std::string> free_values(const Eigen::VectorXd& coefficients) {
  std::vector<std::string> out;
  const double scale = coefficients.cwiseAbs().maxCoeff();
  for (Eigen::Index k = 0; k < coefficients.size(); ++k)
    out.push_back(fmt::format("{:.0f}/4503599627370496",
                              std::round(coefficients(k) / scale * 4503599627370496.0)));
  return out;
}

// The stress times the positive rational that makes its entries integral with no common factor:
// the same stress up to scale, written without a denominator per coefficient (t18a's
// certificate: the stress was 60 MB of its 108).
void make_primitive(Vector& stress) {
  flint::Fmpz scale, content, c;
  fmpz_one(scale.value);
  for (const auto& s : stress) fmpz_lcm(scale.value, scale.value, fmpq_poly_denref(s->value));
  for (const auto& s : stress) fmpq_poly_scalar_mul_fmpz(s->value, s->value, scale.value);
  for (const auto& s : stress) {
    _fmpz_vec_content(c.value, fmpq_poly_numref(s->value), fmpq_poly_length(s->value));
    fmpz_gcd(content.value, content.value, c.value);
  }
  if (fmpz_is_zero(content.value) || fmpz_is_one(content.value)) return;
  for (const auto& s : stress) fmpq_poly_scalar_div_fmpz(s->value, s->value, content.value);
}

}  // namespace

StrictOptimality prove_strict_optimality(const ConfigurationInput& in,
                                         const ExactConfiguration& config,
                                         const std::vector<long double>& forces) {
  StrictOptimality out;
  if (!config.proven) {
    out.reason = "statement (I) is not proven";
    return out;
  }
  const flint::Field field(config.field);
  const int digits = in.digits;
  const slong prec = flint::bits_for(2 * digits);
  // Held disks and their columns.
  const std::set<int> rattlers(in.rattlers.begin(), in.rattlers.end());
  std::map<int, int> column_of;
  for (int i = 0; i < in.n; ++i)
    if (!rattlers.count(i)) column_of[i] = 2 * static_cast<int>(column_of.size());
  const int columns = 2 * static_cast<int>(column_of.size());
  const int bonds = static_cast<int>(in.bonds.size());
  out.columns = columns;
  Matrix gt = transposed_bond_matrix(in, config, field, column_of);
  // rank G = 2h: proven by a minor that is a unit modulo a prime (G^T's pivot columns).
  const auto rows = rows_of(gt);
  const KernelShape shape = kernel_shape(rows, config.field);
  if (!shape.reason.empty()) {
    out.reason = "the rank of G: " + shape.reason;
    return out;
  }
  out.rank = shape.rank;
  out.stresses = bonds - out.rank;
  if (out.rank < columns) {
    out.reason = fmt::format(
        "G has rank {} < {} modulo primes: the held disks may have a first-order motion", out.rank,
        columns);
    return out;
  }
  if (out.stresses == 0) {
    out.reason = "no self-stress (G^T is injective)";
    return out;
  }
  Arb t0, value;
  flint::ball_of(t0.value, config.embedding, prec);
  const auto coefficients = stress_combination(
      in, config, field, numerical_basis(gt, shape.pivot_columns, t0.value, prec), forces, t0.value,
      prec, out.reason);
  if (!coefficients) return out;
  // The one self-stress with those values at the free columns, found modulo primes and verified
  // over K (exact/field_kernel.hpp).
  const KernelVectors found =
      kernel_vectors(rows, config.field, shape, {free_values(*coefficients)});
  if (!found.reason.empty()) {
    out.reason = "the self-stress over K: " + found.reason;
    return out;
  }
  Vector stress = zero_vector(bonds);
  for (int b = 0; b < bonds; ++b)
    flint::fmpq_poly_from_strings(stress[static_cast<std::size_t>(b)]->value,
                                  found.vectors[0][static_cast<std::size_t>(b)].coefficients);
  make_primitive(stress);
  // G^T s = 0 was verified exactly over K by kernel_vectors (make_primitive only scales it by a
  // positive rational); strictly positive at t0 (Arb):
  // The stress is integral (make_primitive): its values overflow a double, their ratio does not.
  Arb smallest, largest;
  for (int b = 0; b < bonds; ++b) {
    flint::Field::evaluate(value.value, stress[static_cast<std::size_t>(b)]->value, t0.value, prec);
    if (!arb_is_positive(value.value)) {
      out.reason =
          fmt::format("the exact stress is not strictly positive on bond {} ({} self-stresses)",
                      b + 1, out.stresses);
      return out;
    }
    if (b == 0 || arf_cmp(arb_midref(value.value), arb_midref(smallest.value)) < 0)
      arb_set(smallest.value, value.value);
    if (b == 0 || arf_cmp(arb_midref(value.value), arb_midref(largest.value)) > 0)
      arb_set(largest.value, value.value);
  }
  for (const auto& s : stress) out.stress.push_back(flint::strings_from_fmpq_poly(s->value));
  arb_div(value.value, smallest.value, largest.value, prec);
  out.smallest_stress_ratio = arf_get_d(arb_midref(value.value), ARF_RND_NEAR);
  out.proven = true;
  return out;
}

}  // namespace tripack::exact
