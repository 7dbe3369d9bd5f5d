#include "analysis/linear_program.hpp"

#include <algorithm>
#include <cmath>
#include <coin/ClpSimplex.hpp>
#include <coin/CoinPackedMatrix.hpp>

namespace tripack {

namespace {

double clp_bound(double v) {
  if (v == LinearProgram::kInf) return COIN_DBL_MAX;
  if (v == -LinearProgram::kInf) return -COIN_DBL_MAX;
  return v;
}

}  // namespace

int LinearProgram::add_column(double lo, double hi, double objective) {
  columns_.push_back({lo, hi});
  objective_.push_back(objective);
  return columns() - 1;
}

int LinearProgram::add_row(double lo, double hi,
                           const std::vector<std::pair<int, double>>& coeffs) {
  rows_.push_back({lo, hi});
  for (const auto& [c, v] : coeffs) {
    // Unit-vector components below 1e-15 are rounding noise of an axis-aligned direction; kept,
    // they only worsen the scaling (coefficient ratios of 1e19).
    if (std::fabs(v) < 1e-15) continue;
    ia_.push_back(rows() - 1);
    ja_.push_back(c);
    ar_.push_back(v);
  }
  return rows() - 1;
}

LinearProgram::Solution LinearProgram::solve(bool maximize) const {
  const CoinPackedMatrix matrix(true, ia_.data(), ja_.data(), ar_.data(),
                                static_cast<CoinBigIndex>(ar_.size()));
  std::vector<double> col_lo, col_hi, row_lo, row_hi;
  for (const auto& b : columns_) {
    col_lo.push_back(clp_bound(b.lo));
    col_hi.push_back(clp_bound(b.hi));
  }
  for (const auto& b : rows_) {
    row_lo.push_back(clp_bound(b.lo));
    row_hi.push_back(clp_bound(b.hi));
  }
  ClpSimplex model;
  model.setLogLevel(0);
  // loadProblem needs the matrix to span every row and column, even empty ones.
  CoinPackedMatrix full(matrix);
  full.setDimensions(rows(), columns());
  model.loadProblem(full, col_lo.data(), col_hi.data(), objective_.data(), row_lo.data(),
                    row_hi.data());
  model.setOptimizationDirection(maximize ? -1 : 1);
  model.setMaximumIterations(std::max(20000, 100 * (rows() + columns())));
  // Tighter than CLP's 1e-7 defaults: contact forces in near-degenerate packings (sparse-rows,
  // pairs at k = 8) are ~1e-8 and must be resolved.
  model.setPrimalTolerance(1e-10);
  model.setDualTolerance(1e-10);
  if (!scaling_) model.scaling(0);
  // These LPs are highly degenerate (many contacts active at once); CLP's dual simplex handles
  // them, with the primal simplex as a second opinion.
  model.dual();
  if (model.status() != 0) model.primal();
  Solution sol;
  sol.solver_status = model.status();
  switch (model.status()) {
    case 0:
      sol.status = Status::Optimal;
      break;
    case 1:
      sol.status = Status::Infeasible;
      return sol;
    case 2:
      sol.status = Status::Unbounded;
      return sol;
    default:
      return sol;
  }
  sol.objective = model.objectiveValue();
  const double* x = model.primalColumnSolution();
  const double* y = model.dualRowSolution();
  sol.x.assign(x, x + columns());
  sol.dual.assign(y, y + rows());
  return sol;
}

}  // namespace tripack
