// A linear program in a thin form: columns, rows with bounds, sparse coefficients; solved by
// COIN-OR CLP's simplex, returning primal values and row duals. (GLPK was tried first: on these
// highly degenerate contact LPs it stalled or reported bogus infeasibility; CLP does not.)
#pragma once

#include <limits>
#include <utility>
#include <vector>

namespace tripack {

class LinearProgram {
 public:
  static constexpr double kInf = std::numeric_limits<double>::infinity();

  // A column (variable) with bounds lo <= x <= hi (either may be +-kInf) and objective weight.
  int add_column(double lo, double hi, double objective);
  // A row lo <= sum coeffs * x <= hi (either bound may be infinite; lo == hi for equality).
  int add_row(double lo, double hi, const std::vector<std::pair<int, double>>& coeffs);

  enum class Status { Optimal, Infeasible, Unbounded, Failed };
  struct Solution {
    Status status = Status::Failed;
    double objective = 0;
    std::vector<double> x;     // per column
    std::vector<double> dual;  // per row (CLP sign convention; relax and tests use magnitudes)
    int solver_status = 0;     // CLP's status (0: optimal)
  };
  Solution solve(bool maximize) const;

  // CLP scales rows and columns by default. Relax's step LPs, whose coefficients are unit-vector
  // components and 1 already, solve ~7x faster without (a billiards end state at n = 1000: 4.4 s
  // -> 0.55 s per LP); the certificates' LPs keep it (without, a perturbed sparse-rows k = 8
  // start at n = 53 was judged not rigid).
  void set_scaling(bool on) { scaling_ = on; }

  int columns() const { return static_cast<int>(columns_.size()); }
  int rows() const { return static_cast<int>(rows_.size()); }

 private:
  struct Bounds {
    double lo, hi;
  };
  std::vector<Bounds> columns_;
  std::vector<double> objective_;
  std::vector<Bounds> rows_;
  std::vector<int> ia_, ja_;  // row and column of each coefficient
  std::vector<double> ar_;
  bool scaling_ = true;
};

}  // namespace tripack
