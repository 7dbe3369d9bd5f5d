// The closed-form and contact-system builders, one file per class family (docs/classes.md).
// Each returns a Pattern in the unit triangle with its intended bonds and rattlers; none of them
// validates its arguments against the catalogue (the registry does that) beyond what geometry
// requires. build_pattern finds them by their classes.yaml name, registered in each builder's own
// file (constructors/registry.hpp); the declarations here are for calling a builder directly
// (tests, benchmarks), which a new builder does not need.
#pragma once

#include <string>

#include "core/packing.hpp"

namespace tripack {

Pattern build_hexagonal(long k);            // Delta(k), k >= 2
Pattern build_hexagonal_minus_one(long k);  // Delta(k) - 1: the bottom-left corner removed, k >= 2
Pattern build_four_delta(long k);           // 4 Delta(k), k >= 1

// 2Delta(k+1) + 2Delta(k) - 1. cavity = 0: the rattler packing; cavity = m in 1..k: m disks
// pushed into the cavity (m = k is the full packing).
Pattern build_twin(long k, long cavity);

// Delta(q*block + (q-1)*separator) + (2q+1) Delta(block): a top triangle over q inverted and
// q+1 upright small triangles, blocks separated by `separator` (0 or 1) rattlers. The matrix
// class n_p(k) is (q, block, separator) = (p, k, 1); Delta(k+2)-2 is (k, 1, 0); Delta(2k+3)-3
// is (k, 2, 0). docs/classes.md §4b, §5-6.
struct ChainFamilyShape {
  long q = 1;
  long block = 1;
  int separator = 1;
};
Pattern build_chain_family(const ChainFamilyShape& shape);

// Delta(2k+1) + 1 with the depressed cage (docs/classes.md §7), k >= 3.
Pattern build_odd_ripple_depressed(long k);
// Delta(2k+1) + 1, the other modification (docs/odd-ripple-other.md: t16a33, t29a, t46a, t67b,
// t92b), k >= 2.
Pattern build_odd_ripple_other(long k);

// Delta(k+2) - 2, the sparse corner (t43a, t64a; docs/class6.md), k >= 3.
Pattern build_sparse_corner(long k);

}  // namespace tripack
