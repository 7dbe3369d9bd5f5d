// Value types every stage shares: Bond, Packing, Pattern.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/geometry.hpp"
#include "core/sqrt3.hpp"

namespace tripack {

// A bond is a disk-disk pair at distance exactly d, or a disk centre exactly on a side.
struct Bond {
  int a = -1;  // disk index
  int b = -1;  // other disk index, or -1 - side for a wall bond
  static Bond pair(int i, int j) { return i < j ? Bond{i, j} : Bond{j, i}; }
  static Bond wall(int i, Side s) { return Bond{i, -1 - static_cast<int>(s)}; }
  bool is_wall() const { return b < 0; }
  Side side() const { return static_cast<Side>(-1 - b); }
  auto operator<=>(const Bond&) const = default;
};

// n points in the unit triangle (0,0), (1,0), (1/2, sqrt3/2) and their minimum distance d.
// Points and d are long double: the polisher resolves them beyond double, and a distance measured
// from double coordinates would carry an error of ~1e-16 * L relative (3e-14 at n = 80,000).
// The billiards engine keeps its own double arrays.
struct Packing {
  std::vector<Vec2L> points;
  long double d = 0;
  std::size_t size() const { return points.size(); }
};

// Where a pattern came from: the catalogue class and its parameters.
struct Provenance {
  std::string class_id;
  long k = 0;
  long p = 0;  // 0 when the class has no p
  std::string variant;
};

// A packing plus what its builder intends: the bonds and the rattlers.
struct Pattern {
  Packing packing;
  std::vector<Bond> bonds;    // sorted, unique; rattlers carry none
  std::vector<int> rattlers;  // sorted disk indices
  Provenance provenance;
  std::optional<Sqrt3DiskUnits> sqrt3;  // closed-form builders only
};

// n(k) helper used everywhere: Delta(k) = k(k+1)/2.
constexpr long long triangular(long long k) {
  return k * (k + 1) / 2;
}

// Site (i, j) of the k-row triangular lattice (row j from the bottom, i along it) as an index
// 0..Delta(k)-1, row by row.
constexpr std::size_t lattice_site(long long k, long long i, long long j) {
  return static_cast<std::size_t>(j * k - j * (j - 1) / 2 + i);
}

}  // namespace tripack
