// Internal to analysis/: the pieces of the bond system shared by the long double polisher
// (polish.cpp) and the multiprecision one (polish_mp.cpp). Unknowns are the non-rattler centres
// and L, in disk units; equations are one per bond, in the order of the bond list.
#pragma once

#include <Eigen/SPQRSupport>
#include <Eigen/SparseCore>
#include <vector>

#include "core/packing.hpp"

namespace tripack::bond_system {

using SpMat = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;

// Unknown layout: columns 2*u, 2*u+1 for the u-th non-rattler disk, last column for L.
struct Layout {
  std::vector<int> column;  // per disk: first column, or -1 for rattlers
  int unknowns = 0;
  int l_column = 0;
};

Layout make_layout(std::size_t n, const std::vector<int>& rattlers);

// Throws std::invalid_argument if a bond refers to a disk outside 0..n-1.
void check_bonds(std::size_t n, const std::vector<Bond>& bonds);

// The Jacobian of the bond equations at x (disk units), in double: accurate enough for Newton
// steps whose residuals are evaluated in higher precision.
SpMat jacobian(const std::vector<Bond>& bonds, const std::vector<Vec2L>& x, const Layout& lay);

}  // namespace tripack::bond_system
