// Exact coordinates for the closed-form classes. Every coordinate of Delta(k), 4Delta(k) and the
// twin class, in disk units, lies in Q(sqrt3) with denominator 2: (p + q sqrt3) / 2, p, q integers.
// Builders that know them fill Pattern::sqrt3; analysis/sqrt3_check verifies them in CGAL's exact
// arithmetic. Plain int64 pairs keep the bookkeeping as cheap as the long double construction.
#pragma once

#include <stdexcept>
#include <vector>

#include "core/geometry.hpp"

namespace tripack {

struct HalfSurd3 {
  long long p = 0, q = 0;  // (p + q sqrt3) / 2

  static constexpr HalfSurd3 integer(long long n) { return {2 * n, 0}; }
  friend constexpr HalfSurd3 operator+(HalfSurd3 a, HalfSurd3 b) { return {a.p + b.p, a.q + b.q}; }
  friend constexpr HalfSurd3 operator-(HalfSurd3 a, HalfSurd3 b) { return {a.p - b.p, a.q - b.q}; }
  friend constexpr HalfSurd3 operator-(HalfSurd3 a) { return {-a.p, -a.q}; }
  friend constexpr HalfSurd3 operator*(HalfSurd3 a, long long s) { return {a.p * s, a.q * s}; }
  friend bool operator==(HalfSurd3 a, HalfSurd3 b) = default;
  // sqrt3 (p + q sqrt3) / 2 = (3q + p sqrt3) / 2.
  constexpr HalfSurd3 times_sqrt3() const { return {3 * q, p}; }
  // Half of the value; only representable when p and q are even.
  constexpr HalfSurd3 half() const {
    if (p % 2 != 0 || q % 2 != 0) throw std::logic_error("HalfSurd3::half: odd coefficient");
    return {p / 2, q / 2};
  }
  // Two roundings (q * sqrt3, then the sum): within ~1.5 ulp of the true value.
  long double value() const {
    return (static_cast<long double>(p) + static_cast<long double>(q) * kSqrt3) / 2;
  }
};

struct Sqrt3Point {
  HalfSurd3 x, y;

  friend constexpr Sqrt3Point operator+(Sqrt3Point a, Sqrt3Point b) {
    return {a.x + b.x, a.y + b.y};
  }
  friend constexpr Sqrt3Point operator-(Sqrt3Point a, Sqrt3Point b) {
    return {a.x - b.x, a.y - b.y};
  }
  friend constexpr Sqrt3Point operator*(Sqrt3Point a, long long s) { return {a.x * s, a.y * s}; }
  friend bool operator==(Sqrt3Point a, Sqrt3Point b) = default;
  Vec2L value() const { return {x.value(), y.value()}; }
};

// The lattice directions of geometry.hpp's Directions, exactly.
struct Sqrt3Directions {
  static constexpr Sqrt3Point e0{{2, 0}, {0, 0}};
  static constexpr Sqrt3Point e60{{1, 0}, {0, 1}};
  static constexpr Sqrt3Point e120{{-1, 0}, {0, 1}};
  static constexpr Sqrt3Point e180{{-2, 0}, {0, 0}};
  static constexpr Sqrt3Point e240{{-1, 0}, {0, -1}};
  static constexpr Sqrt3Point e300{{1, 0}, {0, -1}};
};

// Disk units: min distance 1, triangle (0,0), (L,0), (L/2, L sqrt3/2).
struct Sqrt3DiskUnits {
  HalfSurd3 L;
  std::vector<Sqrt3Point> points;  // one per disk, in the order of Packing::points
  std::vector<char> known;  // 0 where the coordinate is not exact (rattlers placed numerically)
};

}  // namespace tripack
