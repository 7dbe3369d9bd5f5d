#include "analysis/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>

#include "analysis/openmp_regions.hpp"

namespace tripack {

struct SparseCholesky::Factorization {
  bool supernodal = false;
  Eigen::CholmodSupernodalLLT<Matrix> supernodal_llt;
  Eigen::SimplicialLLT<Matrix> simplicial_llt;
};

SparseCholesky::SparseCholesky(Eigen::Index unknowns, Eigen::Index supernodal_from)
    : f_(std::make_unique<Factorization>()) {
  f_->supernodal = unknowns >= supernodal_from;
  if (f_->supernodal) {
    f_->supernodal_llt.cholmod().print = 0;
    run_openmp_regions_on_this_thread();
  }
}

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze_pattern(const Matrix& a) {
  if (f_->supernodal)
    f_->supernodal_llt.analyzePattern(a);
  else
    f_->simplicial_llt.analyzePattern(a);
}

void SparseCholesky::factorize(const Matrix& a) {
  if (f_->supernodal)
    f_->supernodal_llt.factorize(a);
  else
    f_->simplicial_llt.factorize(a);
}

void SparseCholesky::compute(const Matrix& a) {
  analyze_pattern(a);
  factorize(a);
}

bool SparseCholesky::succeeded() const {
  return (f_->supernodal ? f_->supernodal_llt.info() : f_->simplicial_llt.info()) == Eigen::Success;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (f_->supernodal) return f_->supernodal_llt.solve(b);
  return f_->simplicial_llt.solve(b);
}

}  // namespace tripack
