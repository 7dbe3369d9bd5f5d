#include "analysis/certify.hpp"

#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "analysis/linear_program.hpp"
#include "analysis/sparse_cholesky.hpp"
#include "polish/polish_mp.hpp"

namespace tripack {

namespace {

// Inverse iteration from a seeded random start (30 solves with the factorization of A): the
// Rayleigh quotient approaches A's smallest eigenvalue from above; a near-null direction
// dominates after the first solve.
template <class Vector, class Solver, class Matrix>
auto smallest_eigenvalue_estimate(const Solver& solver, const Matrix& A, Eigen::Index columns) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> u(-1, 1);
  Vector x(columns);
  for (auto& v : x) v = u(rng);
  x.normalize();
  for (int it = 0; it < 30; ++it) {
    x = solver.solve(x);
    x.normalize();
  }
  return x.dot(A * x);
}

// Columns of the non-rattlers: 2 per disk, -1 for rattlers.
std::vector<int> motion_columns(std::size_t n, const std::vector<int>& rattlers, int& count) {
  std::vector<int> col(n, 0);
  for (int r : rattlers) col[static_cast<std::size_t>(r)] = -1;
  count = 0;
  for (auto& c : col)
    if (c == 0) {
      c = count;
      count += 2;
    }
  return col;
}

// A certificate declines at once without a moving disk or a bond: `declined` says so.
bool nothing_to_certify(int columns, const std::vector<Bond>& bonds, std::string& declined) {
  if (columns > 0 && !bonds.empty()) return false;
  declined = "no bonds between non-rattlers";
  return true;
}

// The opening-rate row of bond b: coefficients on the motion columns.
std::vector<std::pair<int, double>> opening_row(const Packing& pk, const Bond& b,
                                                const std::vector<int>& col) {
  std::vector<std::pair<int, double>> row;
  const int ca = col[static_cast<std::size_t>(b.a)];
  if (b.is_wall()) {
    const auto nrm = wall_normal<double>(b.side());
    if (ca >= 0) row = {{ca, nrm.x}, {ca + 1, nrm.y}};
    return row;
  }
  const int cb = col[static_cast<std::size_t>(b.b)];
  const Vec2L dv =
      pk.points[static_cast<std::size_t>(b.a)] - pk.points[static_cast<std::size_t>(b.b)];
  const Vec2L u = dv / norm(dv);
  if (ca >= 0) {
    row.emplace_back(ca, static_cast<double>(u.x));
    row.emplace_back(ca + 1, static_cast<double>(u.y));
  }
  if (cb >= 0) {
    row.emplace_back(cb, static_cast<double>(-u.x));
    row.emplace_back(cb + 1, static_cast<double>(-u.y));
  }
  return row;
}

// LP values are O(1) for a real motion in the unit box and ~1e-10 for round-off.
constexpr double kMotionTolerance = 1e-7;

// Smallest forces, the balance residual (long double, exact directions) and the strictness verdict
// of rep.forces.
void judge_stress(const Packing& pk, const std::vector<Bond>& bonds, const std::vector<int>& col,
                  StressReport& rep) {
  rep.min_force = rep.min_pair_force = rep.min_wall_force =
      std::numeric_limits<long double>::infinity();
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    const long double f = rep.forces[b];
    rep.min_force = std::min(rep.min_force, f);
    (bonds[b].is_wall() ? rep.min_wall_force : rep.min_pair_force) =
        std::min(bonds[b].is_wall() ? rep.min_wall_force : rep.min_pair_force, f);
  }
  // Residual of the balance, recomputed in long double with the exact directions.
  std::vector<Vec2L> net(pk.size());
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    const auto& bd = bonds[b];
    const long double f = rep.forces[b];
    if (bd.is_wall()) {
      net[static_cast<std::size_t>(bd.a)] += wall_normal<long double>(bd.side()) * f;
      continue;
    }
    const Vec2L dv =
        pk.points[static_cast<std::size_t>(bd.a)] - pk.points[static_cast<std::size_t>(bd.b)];
    const Vec2L u = dv / norm(dv);
    net[static_cast<std::size_t>(bd.a)] += u * f;
    net[static_cast<std::size_t>(bd.b)] -= u * f;
  }
  for (std::size_t i = 0; i < pk.size(); ++i)
    if (col[i] >= 0) rep.residual = std::max(rep.residual, norm(net[i]));
  // Strictly positive only if the smallest force stands well clear of the solution's own error
  // (its force imbalance): near-degenerate packings (sparse-rows, pairs at k >= 9) have forces
  // below 1e-10 that a double LP cannot resolve, and they are reported as not certified.
  rep.strictly_positive = rep.min_force > 1e-12L && rep.min_force > 100 * rep.residual;
}

}  // namespace

RigidityReport test_rigidity(const Packing& pk, const std::vector<Bond>& bonds,
                             const std::vector<int>& rattlers, std::uint64_t seed) {
  RigidityReport rep;
  int columns = 0;
  const auto col = motion_columns(pk.size(), rattlers, columns);
  if (columns == 0) {
    rep.rigid = true;
    return rep;
  }
  std::vector<std::vector<std::pair<int, double>>> rows;
  for (const auto& b : bonds) rows.push_back(opening_row(pk, b, col));

  auto motion_of = [&](const std::vector<double>& x) {
    std::vector<Vec2L> m(pk.size());
    for (std::size_t i = 0; i < pk.size(); ++i)
      if (col[i] >= 0)
        m[i] = {x[static_cast<std::size_t>(col[i])], x[static_cast<std::size_t>(col[i] + 1)]};
    return m;
  };

  // LP 1: can some motion open bonds without closing any?
  LinearProgram open;
  std::vector<double> objective(static_cast<std::size_t>(columns), 0.0);
  for (const auto& row : rows)
    for (const auto& [c, v] : row) objective[static_cast<std::size_t>(c)] += v;
  for (int c = 0; c < columns; ++c) open.add_column(-1, 1, objective[static_cast<std::size_t>(c)]);
  for (const auto& row : rows) open.add_row(0, LinearProgram::kInf, row);
  const auto s1 = open.solve(true);
  if (s1.status != LinearProgram::Status::Optimal)
    throw std::runtime_error("rigidity LP failed (solver status " +
                             std::to_string(s1.solver_status) + ")");
  rep.opening = s1.objective;
  std::vector<double> found;
  if (rep.opening > kMotionTolerance) found = s1.x;

  // LP 2: a floppy motion keeping every bond at first order (random direction, seeded).
  if (found.empty()) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    LinearProgram flex;
    for (int c = 0; c < columns; ++c) flex.add_column(-1, 1, u(rng));
    for (const auto& row : rows) flex.add_row(0, 0, row);
    const auto s2 = flex.solve(true);
    if (s2.status != LinearProgram::Status::Optimal)
      throw std::runtime_error("rigidity LP failed (solver status " +
                               std::to_string(s2.solver_status) + ")");
    rep.floppy = s2.objective;
    if (rep.floppy > kMotionTolerance) found = s2.x;
  }
  rep.rigid = found.empty();
  if (!rep.rigid) {
    rep.motion = motion_of(found);
    long double largest = 0;
    for (const auto& m : rep.motion) largest = std::max(largest, norm(m));
    for (const auto& m : rep.motion) rep.moving_disks += norm(m) > 1e-6L * largest;
    for (const auto& row : rows) {
      double rate = 0;
      for (const auto& [c, v] : row) rate += v * found[static_cast<std::size_t>(c)];
      rep.opening_bonds += rate > kMotionTolerance;
    }
  }
  return rep;
}

StressReport stress_certificate(const Packing& pk, const std::vector<Bond>& bonds,
                                const std::vector<int>& rattlers) {
  StressReport rep;
  int columns = 0;
  const auto col = motion_columns(pk.size(), rattlers, columns);
  // Pair forces summing to 1 need a pair bond (CLP stops "due to errors" on the empty row
  // instead of reporting it infeasible).
  if (std::none_of(bonds.begin(), bonds.end(), [](const Bond& b) { return !b.is_wall(); }))
    return rep;
  LinearProgram lp;
  for (std::size_t b = 0; b < bonds.size(); ++b) lp.add_column(0, LinearProgram::kInf, 0);
  const int smallest = lp.add_column(-LinearProgram::kInf, LinearProgram::kInf, 1);
  // Balance: the force on disk i is sum_b f_b * (d opening_b / d x_i): pairs push along u_ij,
  // walls along the inward normal. These are the transposed opening rows.
  std::vector<std::vector<std::pair<int, double>>> balance(static_cast<std::size_t>(columns));
  std::vector<std::pair<int, double>> pair_sum;
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    for (const auto& [c, v] : opening_row(pk, bonds[b], col))
      balance[static_cast<std::size_t>(c)].emplace_back(static_cast<int>(b), v);
    if (!bonds[b].is_wall()) pair_sum.emplace_back(static_cast<int>(b), 1.0);
  }
  for (const auto& row : balance) lp.add_row(0, 0, row);
  lp.add_row(1, 1, pair_sum);
  for (std::size_t b = 0; b < bonds.size(); ++b)
    lp.add_row(0, LinearProgram::kInf, {{static_cast<int>(b), 1.0}, {smallest, -1.0}});
  const auto sol = lp.solve(true);
  if (sol.status == LinearProgram::Status::Infeasible) return rep;
  if (sol.status != LinearProgram::Status::Optimal)
    throw std::runtime_error("stress LP failed (solver status " +
                             std::to_string(sol.solver_status) + ")");
  rep.exists = true;
  rep.forces.assign(sol.x.begin(), sol.x.begin() + static_cast<long>(bonds.size()));
  judge_stress(pk, bonds, col, rep);
  return rep;
}

namespace {

using SpMat = Eigen::SparseMatrix<double>;
// G^T G's Cholesky: CHOLMOD's supernodal one from 50,000 disks (4Delta(707), 10^6 disks,
// certifies in 7 minutes; 4Delta(150) in 3.8 s where Eigen's simplicial LDL^T took 4.6 s), Eigen's
// simplicial one below (n = 10,154: 470 against 600 ms; docs/performance.md). A factorization
// that succeeds shows A positive definite in floating point, as the LDL^T's positive pivots did.
using Cholesky = SparseCholesky;

// A strictly positive self-stress, if one exists, by infeasible-start Newton on the analytic
// centre: maximize sum(log f - f) subject to G^T f = 0 (bounded, with its optimum inside
// f > 0, exactly when such a stress exists). Each step solves with G^T F^2 G, the pattern of
// A = G^T G. The plain projection of all-ones already fails at n = 7261 (even-ripple k = 60).
// False when no full (feasible) step was reached; f is then meaningless.
bool analytic_centre(const SpMat& G, const SpMat& A, Eigen::VectorXd& f, int& steps) {
  const Eigen::Index m = G.rows();
  f = Eigen::VectorXd::Ones(m);
  Cholesky weighted(A.rows());
  weighted.analyze_pattern(A);
  bool feasible = false;
  for (int it = 0; it < 60; ++it) {
    ++steps;
    const Eigen::VectorXd f2 = f.cwiseProduct(f);
    const SpMat W = SpMat(G.transpose()) * f2.asDiagonal() * G;
    weighted.factorize(W);
    if (!weighted.succeeded()) break;
    const Eigen::VectorXd nu = weighted.solve(G.transpose() * (2 * f - f2));
    const Eigen::VectorXd df = f - f2 - f2.cwiseProduct(G * nu);
    double step = 1;  // stay inside f > 0 (fraction to the boundary 0.9)
    for (Eigen::Index b = 0; b < m; ++b)
      if (df[b] < 0) step = std::min(step, 0.9 * f[b] / -df[b]);
    f += step * df;
    feasible = feasible || step == 1;
    // Newton decrement: done once the centre is reached to a few digits.
    if (feasible && df.cwiseQuotient(f).squaredNorm() < 1e-8) break;
  }
  return feasible;
}

}  // namespace

FastCertificate fast_certificate(const Packing& pk, const std::vector<Bond>& bonds,
                                 const std::vector<int>& rattlers, double min_eigenvalue,
                                 long double min_force) {
  FastCertificate out;
  int columns = 0;
  const auto col = motion_columns(pk.size(), rattlers, columns);
  const auto m = static_cast<Eigen::Index>(bonds.size());
  if (nothing_to_certify(columns, bonds, out.declined)) return out;
  std::vector<Eigen::Triplet<double>> t;
  for (std::size_t b = 0; b < bonds.size(); ++b)
    for (const auto& [c, v] : opening_row(pk, bonds[b], col))
      t.emplace_back(static_cast<Eigen::Index>(b), c, v);
  SpMat G(m, columns);
  G.setFromTriplets(t.begin(), t.end());
  const SpMat A = SpMat(G.transpose()) * G;
  Cholesky ldlt(A.rows());
  ldlt.compute(A);
  if (!ldlt.succeeded()) {
    out.declined = "G^T G is singular (a first-order motion may keep every bond)";
    return out;
  }
  out.min_eigenvalue = smallest_eigenvalue_estimate<Eigen::VectorXd>(ldlt, A, columns);
  if (!(out.min_eigenvalue > min_eigenvalue)) {
    out.declined = "G^T G is nearly singular (smallest eigenvalue below the threshold)";
    return out;
  }
  Eigen::VectorXd f;
  if (!analytic_centre(G, A, f, out.newton_steps)) {
    out.declined = "no strictly positive stress found (Newton stayed infeasible)";
    return out;
  }
  // Remove the Newton steps' round-off from the balance: one projection onto ker G^T.
  f -= G * ldlt.solve(G.transpose() * f);
  double pair_sum = 0;
  for (std::size_t b = 0; b < bonds.size(); ++b)
    if (!bonds[b].is_wall()) pair_sum += f[static_cast<Eigen::Index>(b)];
  if (!(pair_sum > 0)) {
    out.declined = "the projected stress has no positive pair forces";
    return out;
  }
  auto& rep = out.stress;
  rep.exists = true;
  rep.forces.resize(bonds.size());
  for (std::size_t b = 0; b < bonds.size(); ++b)
    rep.forces[b] = static_cast<long double>(f[static_cast<Eigen::Index>(b)]) / pair_sum;
  judge_stress(pk, bonds, col, rep);
  if (!rep.strictly_positive || rep.min_force <= min_force) {
    out.declined = "the projected stress is not resolved strictly positive";
    return out;
  }
  out.accepted = true;
  return out;
}

MultiprecisionCertificate multiprecision_certificate(const MultiprecisionPolish& polish,
                                                     const std::vector<Bond>& bonds,
                                                     const std::vector<int>& rattlers) {
  using SpL = Eigen::SparseMatrix<long double>;
  using VecL = Eigen::Matrix<long double, Eigen::Dynamic, 1>;
  using LLT = Eigen::SimplicialLLT<SpL, Eigen::Lower, Eigen::AMDOrdering<int>>;
  constexpr long double eps = std::numeric_limits<long double>::epsilon();
  MultiprecisionCertificate out;
  const Packing pk = rounded_packing(polish);
  int columns = 0;
  const auto col = motion_columns(pk.size(), rattlers, columns);
  const auto m = static_cast<Eigen::Index>(bonds.size());
  if (nothing_to_certify(columns, bonds, out.declined)) return out;
  const std::vector<Vec2L> dirs = precise_directions(polish, bonds);
  std::vector<Eigen::Triplet<long double>> t;
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    const auto row = static_cast<Eigen::Index>(b);
    const int ca = col[static_cast<std::size_t>(bonds[b].a)];
    const int cb = bonds[b].is_wall() ? -1 : col[static_cast<std::size_t>(bonds[b].b)];
    if (ca >= 0) {
      t.emplace_back(row, ca, dirs[b].x);
      t.emplace_back(row, ca + 1, dirs[b].y);
    }
    if (cb >= 0) {
      t.emplace_back(row, cb, -dirs[b].x);
      t.emplace_back(row, cb + 1, -dirs[b].y);
    }
  }
  SpL G(m, columns);
  G.setFromTriplets(t.begin(), t.end());
  const SpL Gt = G.transpose();
  const SpL A = Gt * G;
  // The rounding of A's entries: each is a sum of at most k products of direction components
  // (|.| <= 1, each within one rounding of the exact one), k the most bonds on one column.
  long double k = 0;
  for (Eigen::Index c = 0; c < Gt.outerSize(); ++c)
    k = std::max(k, static_cast<long double>(Gt.innerVector(c).nonZeros()));
  const long double rounding_of_A =
      std::sqrt(static_cast<long double>(A.nonZeros())) * (k + 3) * k * eps;

  LLT llt(A);
  if (llt.info() != Eigen::Success) {
    out.declined =
        "G^T G is singular at the polished coordinates (a first-order motion keeps "
        "every bond)";
    return out;
  }
  out.eigenvalue_estimate = smallest_eigenvalue_estimate<VecL>(llt, A, columns);
  const long double mu = out.eigenvalue_estimate / 2;
  SpL shifted = A;
  for (Eigen::Index c = 0; c < columns; ++c) shifted.coeffRef(c, c) -= mu;
  LLT lower(shifted);
  if (!(mu > 0) || lower.info() != Eigen::Success) {
    out.declined = "the smallest eigenvalue of G^T G is not resolved in long double";
    return out;
  }
  {
    const SpL L = lower.matrixL();
    const SpL LLt = L * SpL(L.transpose());
    SpL permuted;
    permuted = shifted.selfadjointView<Eigen::Lower>().twistedBy(lower.permutationP());
    out.eigenvalue_error = SpL(LLt - permuted).norm() + rounding_of_A;
  }
  out.min_eigenvalue = mu - out.eigenvalue_error;
  out.rigid = out.eigenvalue_error <= mu / 2;
  if (!out.rigid) {
    out.declined = "the smallest eigenvalue of G^T G is not resolved above its rounding error";
    return out;
  }

  // A start stress in double: the analytic centre, else the max-min LP.
  const Eigen::SparseMatrix<double> Gd = G.cast<double>();
  const Eigen::SparseMatrix<double> Ad = Eigen::SparseMatrix<double>(Gd.transpose()) * Gd;
  std::vector<long double> start(bonds.size());
  Eigen::VectorXd f0;
  int steps = 0;
  if (analytic_centre(Gd, Ad, f0, steps) && f0.minCoeff() > 0) {
    out.stress_start = "analytic centre";
    for (std::size_t b = 0; b < bonds.size(); ++b) start[b] = f0[static_cast<Eigen::Index>(b)];
  } else {
    const StressReport lp = stress_certificate(pk, bonds, rattlers);
    if (!lp.exists || !(lp.min_force > 0)) {
      out.declined = "no strictly positive stress in double precision to start from";
      return out;
    }
    out.stress_start = "max-min LP";
    start = lp.forces;
  }
  auto solve_with = [](const LLT& f) {
    return [&f](const std::vector<long double>& r) {
      const VecL y = f.solve(Eigen::Map<const VecL>(r.data(), static_cast<Eigen::Index>(r.size())));
      return std::vector<long double>(y.data(), y.data() + y.size());
    };
  };
  PreciseBalance balance =
      balance_multiprecision(polish, bonds, rattlers, start, {}, solve_with(llt));
  auto smallest = [](const std::vector<long double>& f) {
    return f.empty() ? 0.0L : *std::min_element(f.begin(), f.end());
  };
  if (!(smallest(balance.forces) > 0)) {
    // The plain projection moved a small force through zero: the weighted one changes each force
    // in proportion to its square, keeping small forces small.
    std::vector<long double> w(start.size());
    for (std::size_t b = 0; b < w.size(); ++b) w[b] = start[b] * start[b];
    SpL W = Gt * VecL(Eigen::Map<const VecL>(w.data(), m)).asDiagonal() * G;
    LLT weighted(W);
    if (weighted.info() == Eigen::Success) {
      out.weighted = true;
      balance = balance_multiprecision(polish, bonds, rattlers, start, w, solve_with(weighted));
    }
  }
  out.balance_sweeps = balance.sweeps;
  auto& rep = out.stress;
  rep.exists = true;
  rep.forces = balance.forces;
  rep.residual = balance.residual;
  rep.min_force = rep.min_pair_force = rep.min_wall_force =
      std::numeric_limits<long double>::infinity();
  long double norm2 = 0;
  for (std::size_t b = 0; b < bonds.size(); ++b) {
    const long double f = rep.forces[b];
    rep.min_force = std::min(rep.min_force, f);
    auto& side = bonds[b].is_wall() ? rep.min_wall_force : rep.min_pair_force;
    side = std::min(side, f);
    norm2 += f * f;
  }
  const long double direction_error =
      2 * std::pow(10.0L, -static_cast<long double>(polish.digits)) / pk.d;
  out.force_error =
      (std::sqrt(static_cast<long double>(columns)) * balance.residual +
       std::sqrt(2.0L * static_cast<long double>(m)) * direction_error * std::sqrt(norm2)) /
      std::sqrt(out.min_eigenvalue);
  rep.strictly_positive = balance.converged && rep.min_force > 1e6L * out.force_error;
  out.strictly_positive = rep.strictly_positive;
  if (!balance.converged)
    out.declined = "the stress did not balance to the working precision";
  else if (!out.strictly_positive)
    out.declined = "no strictly positive stress resolved at this precision";
  return out;
}

}  // namespace tripack
