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

// The self-stresses {s : G^T s = 0}: a basis over K by exact/field_kernel.hpp (elimination
// modulo primes, verified over K), one vector per free bond.
std::vector<Vector> self_stress_basis(Matrix& gt, const FieldKernel& kernel) {
  std::vector<Vector> basis;
  for (const auto& v : kernel.basis) {
    Vector vector = zero_vector(gt.columns());
    for (std::size_t b = 0; b < v.size(); ++b)
      flint::fmpq_poly_from_strings(vector[b]->value, v[b].coefficients);
    basis.push_back(std::move(vector));
  }
  return basis;
}

// G^T's rows as strings, for exact/field_kernel.hpp.
std::vector<std::vector<RationalPolynomial>> rows_of(Matrix& m) {
  std::vector<std::vector<RationalPolynomial>> rows(static_cast<std::size_t>(m.rows()));
  for (int r = 0; r < m.rows(); ++r)
    for (int c = 0; c < m.columns(); ++c)
      rows[static_cast<std::size_t>(r)].push_back(flint::strings_from_fmpq_poly(m.at(r, c)));
  return rows;
}

// The combination of the basis: one basis vector (sign made positive), or the least-squares fit
// of the numerical stress, rescaled to our rows (pair rows carry d, the side walls 2). Empty, with
// `reason` set, when there are several and no numerical stress.
std::optional<Eigen::VectorXd> stress_combination(const ConfigurationInput& in,
                                                  const ExactConfiguration& config,
                                                  const flint::Field& field,
                                                  const std::vector<Vector>& basis,
                                                  const std::vector<long double>& forces,
                                                  const arb_t t0, slong prec, std::string& reason) {
  const int bonds = static_cast<int>(in.bonds.size());
  // The basis at t0.
  Arb value;
  Eigen::MatrixXd at(bonds, static_cast<Eigen::Index>(basis.size()));
  for (std::size_t k = 0; k < basis.size(); ++k)
    for (int c = 0; c < bonds; ++c) {
      flint::Field::evaluate(value.value, basis[k][static_cast<std::size_t>(c)]->value, t0, prec);
      at(c, static_cast<Eigen::Index>(k)) = arf_get_d(arb_midref(value.value), ARF_RND_NEAR);
    }
  Eigen::VectorXd coefficients(static_cast<Eigen::Index>(basis.size()));
  if (basis.size() == 1) {
    coefficients(0) = at.col(0).sum() < 0 ? -1.0 : 1.0;
    return coefficients;
  }
  if (forces.size() != static_cast<std::size_t>(bonds)) {
    reason = fmt::format("{} self-stresses and no numerical stress to combine them", basis.size());
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
  coefficients = at.colPivHouseholderQr().solve(target);
  return coefficients;
}

// The stress: the combination's coefficients rounded to rationals (52 bits of the largest): the
// stress is then exact whatever the coefficients are.
Vector exact_stress(const std::vector<Vector>& basis, const Eigen::VectorXd& coefficients,
                    int bonds) {
  FmpqPoly term;
  flint::Fmpz numerator, denominator;
  fmpz_one(denominator.value);
  fmpz_mul_2exp(denominator.value, denominator.value, 52);
  flint::Fmpq c;
  Vector stress = zero_vector(bonds);
  const double scale = coefficients.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < basis.size(); ++k) {
    fmpz_set_d(numerator.value,
               std::round(coefficients(static_cast<Eigen::Index>(k)) / scale * 4503599627370496.0));
    fmpq_set_fmpz_frac(c.value, numerator.value, denominator.value);
    for (int b = 0; b < bonds; ++b) {
      fmpq_poly_scalar_mul_fmpq(term.value, basis[k][static_cast<std::size_t>(b)]->value, c.value);
      fmpq_poly_add(stress[static_cast<std::size_t>(b)]->value,
                    stress[static_cast<std::size_t>(b)]->value, term.value);
    }
  }
  return stress;
}

// G^T stress = 0 exactly (by construction; checked).
bool balances_exactly(Matrix& gt, const Vector& stress, const flint::Field& field) {
  FmpqPoly sum, product;
  for (int r = 0; r < gt.rows(); ++r) {
    fmpq_poly_zero(sum.value);
    for (int b = 0; b < gt.columns(); ++b) {
      field.mul(product.value, gt.at(r, b), stress[static_cast<std::size_t>(b)]->value);
      fmpq_poly_add(sum.value, sum.value, product.value);
    }
    if (!field.is_zero(sum.value)) return false;
  }
  return true;
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
  // rank G = 2h: proven by a nonzero minor modulo a prime (G^T's pivot columns), and with the
  // kernel verified over K it is the rank over K exactly.
  const FieldKernel kernel = kernel_over_field(rows_of(gt), config.field, true);
  out.rank = kernel.rank;
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
  if (!kernel.reason.empty()) {
    out.reason = "the self-stresses over K: " + kernel.reason;
    return out;
  }
  const std::vector<Vector> basis = self_stress_basis(gt, kernel);
  Arb t0, value;
  flint::ball_of(t0.value, config.embedding, prec);
  const auto coefficients =
      stress_combination(in, config, field, basis, forces, t0.value, prec, out.reason);
  if (!coefficients) return out;
  const Vector stress = exact_stress(basis, *coefficients, bonds);
  // Exactly balanced, strictly positive at t0 (Arb).
  if (!balances_exactly(gt, stress, field)) {
    out.reason = "the stress does not balance exactly";
    return out;
  }
  double smallest = INFINITY, largest = 0;
  for (int b = 0; b < bonds; ++b) {
    flint::Field::evaluate(value.value, stress[static_cast<std::size_t>(b)]->value, t0.value, prec);
    if (!arb_is_positive(value.value)) {
      out.reason =
          fmt::format("the exact stress is not strictly positive on bond {} ({} self-stresses)",
                      b + 1, basis.size());
      return out;
    }
    const double v = arf_get_d(arb_midref(value.value), ARF_RND_NEAR);
    smallest = std::min(smallest, v);
    largest = std::max(largest, v);
  }
  for (const auto& s : stress) out.stress.push_back(flint::strings_from_fmpq_poly(s->value));
  out.smallest_stress_ratio = smallest / largest;
  out.proven = true;
  return out;
}

}  // namespace tripack::exact
