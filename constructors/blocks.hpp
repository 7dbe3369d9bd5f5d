// Building blocks shared by the builders: a pattern under construction in disk units, hexagonal
// triangles, rattler placement, exact Q(sqrt3) bookkeeping for the closed forms, and the final
// step that detects contacts and scales to the unit triangle.
#pragma once

#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "core/packing.hpp"

namespace tripack {

// Contacts closer than this (disk units) to exact are bonds when a builder lets finish() detect
// them. Builders with near-degenerate gaps (the chain family: sparse-rows k = 11 has a disk
// 1.5e-11 from a wall, k = 12 has 5e-16) record their bonds from the construction instead.
inline constexpr long double kBondTolerance = 1e-10L;

class DiskUnitsPattern {
 public:
  explicit DiskUnitsPattern(long double side) : L_(side) {}
  // A pattern that also tracks exact coordinates (p + q sqrt3)/2: finish() fills Pattern::sqrt3.
  // Disks added from long double coordinates, and rattlers (centred numerically), are marked
  // not known. The long double coordinates of exact disks are derived from the exact ones.
  explicit DiskUnitsPattern(const HalfSurd3& side)
      : L_(side.value()), sqrt3_L_(side), tracks_sqrt3_(true) {}

  long double side() const { return L_; }
  bool tracks_sqrt3() const { return tracks_sqrt3_; }
  void set_side(long double side);  // not for exact patterns (throws std::logic_error)
  int add(const Vec2L& p) {
    pts_.push_back(p);
    sync_sqrt3();
    return static_cast<int>(pts_.size()) - 1;
  }
  int add_sqrt3(const Sqrt3Point& p);  // exact patterns only (named apart: {x, y} stays a Vec2L)
  void reserve(std::size_t n);
  // Moves disk i to an exact position (exact patterns only).
  void move_sqrt3(int i, const Sqrt3Point& p);
  // Removes disk i; later indices shift down by one (in rattlers and recorded bonds too).
  void erase(int i);
  // Hexagonal triangle Delta(k): corner + i*a + j*b for i + j <= k - 1 (a, b unit vectors 60
  // degrees apart). Returns the first index; disk (i, j) is at first + index_in_triangle(k, i, j).
  // Its 3k(k-1)/2 internal lattice bonds are recorded.
  int add_triangle(const Vec2L& corner, const Vec2L& a, const Vec2L& b, long k);
  // The same from exact data (exact patterns only): integer arithmetic, then one conversion.
  int add_triangle(const Sqrt3Point& corner, const Sqrt3Point& a, const Sqrt3Point& b, long k);
  static long index_in_triangle(long k, long i, long j);
  // The three edges of a triangle added at `first`: along a (j = 0), along b (i = 0), and the
  // far edge (i + j = k - 1, ordered by j). Each lists k indices.
  enum class Edge { A, B, Far };
  static std::vector<int> triangle_edge(int first, long k, Edge e);
  void mark_rattler(int i) { rattlers_.push_back(i); }

  // Bonds. By default finish() detects them geometrically (kBondTolerance). A builder that knows
  // its contacts calls use_recorded_bonds(): then the bonds are the triangles' lattice bonds plus
  // those added here (bonds touching rattlers are dropped). set_bonds() replaces everything.
  void add_bond(int i, int j) { recorded_.push_back(Bond::pair(i, j)); }
  void add_wall_bond(int i, Side s) { recorded_.push_back(Bond::wall(i, s)); }
  void use_recorded_bonds() { mode_ = BondMode::Recorded; }
  void set_bonds(std::vector<Bond> bonds) {
    bonds_ = std::move(bonds);
    mode_ = BondMode::Set;
  }

  // Moving a disk of an exact pattern through points() desynchronises it: finish() throws.
  std::vector<Vec2L>& points() { return pts_; }
  const std::vector<Vec2L>& points() const { return pts_; }
  const std::vector<int>& rattlers() const { return rattlers_; }

  // Moves every rattler to the centre of its cage (the point of largest clearance), then
  // settles the bonds (see above), checks the configuration (no overlap, all
  // centres inside, every rattler free) and scales to the unit triangle.
  // Throws std::runtime_error if the pattern is invalid.
  Pattern finish(Provenance provenance);

 private:
  void record_triangle_bonds(int first, long k);
  // Disks added without exact data: not known.
  void sync_sqrt3() {
    if (tracks_sqrt3_) {
      ex_.resize(pts_.size());
      known_.resize(pts_.size(), 0);
    }
  }

  long double L_;
  HalfSurd3 sqrt3_L_;
  bool tracks_sqrt3_ = false;
  std::vector<Sqrt3Point> ex_;
  std::vector<char> known_;
  std::vector<Vec2L> pts_;
  std::vector<int> rattlers_;
  std::vector<Bond> bonds_;
  std::vector<Bond> recorded_;
  enum class BondMode { Detect, Recorded, Set } mode_ = BondMode::Detect;
};

}  // namespace tripack
