// Building blocks shared by the builders: a pattern under construction in disk units, hexagonal
// triangles, rattler placement, and the final step that detects contacts and scales to the unit
// triangle.
#pragma once

#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "core/packing.hpp"

namespace tripack {

// Contacts closer than this (disk units) to exact are bonds. The builders' positions are exact
// to ~1e-15; the closest non-bond in any class (sparse-rows k=12, raised pair) is 1.9e-8 apart.
inline constexpr long double kBondTolerance = 1e-10L;

class DiskUnitsPattern {
 public:
  explicit DiskUnitsPattern(long double side) : L_(side) {}

  long double side() const { return L_; }
  void set_side(long double side) { L_ = side; }
  int add(const Vec2L& p) {
    pts_.push_back(p);
    return static_cast<int>(pts_.size()) - 1;
  }
  // Hexagonal triangle Delta(k): corner + i*a + j*b for i + j <= k - 1. Returns the first index;
  // disk (i, j) is at first + index_in_triangle(k, i, j).
  int add_triangle(const Vec2L& corner, const Vec2L& a, const Vec2L& b, long k);
  static long index_in_triangle(long k, long i, long j);
  void mark_rattler(int i) { rattlers_.push_back(i); }
  void set_bonds(std::vector<Bond> bonds) { bonds_ = std::move(bonds); explicit_bonds_ = true; }

  std::vector<Vec2L>& points() { return pts_; }
  const std::vector<Vec2L>& points() const { return pts_; }
  const std::vector<int>& rattlers() const { return rattlers_; }

  // Moves every rattler to the centre of its cage (the point of largest clearance), then
  // detects the bonds (unless set explicitly), checks the configuration (no overlap, all
  // centres inside, every rattler free) and scales to the unit triangle.
  // Throws std::runtime_error if the pattern is invalid.
  Pattern finish(Provenance provenance);

 private:
  long double L_;
  std::vector<Vec2L> pts_;
  std::vector<int> rattlers_;
  std::vector<Bond> bonds_;
  bool explicit_bonds_ = false;
};

}  // namespace tripack
