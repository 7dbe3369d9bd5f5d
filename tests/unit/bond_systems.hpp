// Small hand-made bond systems that both polishers are tested on (tests/unit/test_polish.cpp in
// long double, tests/unit/test_multiprecision.cpp in MPFR).
#pragma once

#include <vector>

#include "core/packing.hpp"

namespace tripack {

struct BondSystem {
  Packing packing;
  std::vector<Bond> bonds;
};

// Under-determined but consistent: a floor pair (disk 1 starts 2e-4 off its place) and a disk
// with no bonds at all, not declared a rattler: its column is empty.
inline BondSystem floor_pair_and_an_unbonded_disk() {
  BondSystem s;
  s.packing.points = {{0.2, 0.0}, {0.5001, 0.0002}, {0.5, 0.4}};
  s.packing.d = 0.3;
  s.bonds = {Bond::pair(0, 1), Bond::wall(0, Side::Bottom), Bond::wall(1, Side::Bottom)};
  return s;
}

}  // namespace tripack
