// Exact verification of the closed-form constructions (docs/certified.md): Delta(k), Delta(k)-1,
// 4Delta(k) and the twin class have every coordinate in Q(sqrt3) (Pattern::sqrt3), so their bonds
// can be proved to be contacts and their gaps proved open without any rounding.
#pragma once

#include <cstddef>
#include <string>

#include "core/packing.hpp"

namespace tripack {

struct Sqrt3CheckReport {
  bool ok = false;
  // Every bond verified exactly: distance exactly 1 / exactly on its side.
  std::size_t bonds_checked = 0;
  // Non-bond pairs within reach verified strictly > 1, non-bond walls strictly > 0.
  std::size_t gaps_checked = 0;
  std::string failure;  // first failure, one line ("" when ok)
};

// Checks, in exact arithmetic over Q(sqrt3) (disk units, side pattern.sqrt3->L):
//  * the exact data match the packing (L = 1/d, every known disk where the packing has it);
//  * every bond: squared distance exactly 1, or the centre exactly on its side;
//  * every other pair closer than 1.5 (long double candidates): squared distance > 1 strictly;
//  * every side a disk has no wall bond with: wall distance > 0 strictly.
// Disks with known[i] == 0 (rattlers centred numerically) are checked at their long double
// position, converted exactly to a rational. Stops at the first failure (the counts are then
// those verified before it). Throws std::invalid_argument if pattern.sqrt3 is empty or its sizes
// do not match the packing.
Sqrt3CheckReport sqrt3_check(const Pattern& pattern);

}  // namespace tripack
