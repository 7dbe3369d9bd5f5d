// A sparse LL^T that picks its implementation by size, so that CHOLMOD's headers stay in one
// file: Eigen's simplicial Cholesky below `supernodal_from` unknowns, CHOLMOD's supernodal one
// (METIS ordering, BLAS) from there. Per factorization the simplicial one is faster up to tens
// of thousands of disks, the supernodal one above (docs/performance.md, "build --n against n"
// and "10^6 disks"). A factorization that succeeds shows the matrix positive definite in
// floating point; CHOLMOD is told not to print when it is not (that is a verdict, not a warning).
#pragma once

#include <Eigen/SparseCore>
#include <memory>

namespace tripack {

class SparseCholesky {
 public:
  using Matrix = Eigen::SparseMatrix<double>;
  static constexpr Eigen::Index kSupernodalFrom = 2 * 50000;  // unknowns (2 per disk)

  explicit SparseCholesky(Eigen::Index unknowns, Eigen::Index supernodal_from = kSupernodalFrom);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  void analyze_pattern(const Matrix& a);  // the fill-reducing ordering, kept for factorize
  void factorize(const Matrix& a);        // a with the analysed pattern
  void compute(const Matrix& a);          // both
  bool succeeded() const;                 // the last factorization's
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Factorization;
  std::unique_ptr<Factorization> f_;
};

}  // namespace tripack
