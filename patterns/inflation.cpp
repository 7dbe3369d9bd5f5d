#include "patterns/inflation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/neighbours.hpp"

namespace tripack::patterns {

namespace {

// Site (i, j) of the lattice at spacing 1.
Vec2L site_position(long long i, long long j) {
  return {static_cast<long double>(i) + static_cast<long double>(j) / 2,
          static_cast<long double>(j) * kSqrt3 / 2};
}

}  // namespace

std::optional<Packing> inflate_by_two(const Packing& base) {
  const long long n = static_cast<long long>(base.size());
  if (n < 3 || !(base.d > 0)) return std::nullopt;
  long long rows = 1;
  while (triangular(rows) < n) ++rows;
  const long double side = 1 / base.d;  // L: the base triangle's side in diameters
  const long double to_lattice = static_cast<long double>(rows - 1);  // unit triangle -> sites

  // Which disk sits at which site (-1: a vacancy).
  std::vector<long long> disk_at(static_cast<std::size_t>(triangular(rows)), -1);
  std::vector<std::pair<long long, long long>> site_of(static_cast<std::size_t>(n));
  for (long long a = 0; a < n; ++a) {
    const Vec2L p = base.points[static_cast<std::size_t>(a)];
    const long long j = std::llround(p.y * to_lattice / (kSqrt3 / 2));
    const long long i = std::llround(p.x * to_lattice - static_cast<long double>(j) / 2);
    if (i < 0 || j < 0 || i + j >= rows) return std::nullopt;
    long long& at = disk_at[lattice_site(rows, i, j)];
    if (at >= 0) return std::nullopt;
    at = a;
    site_of[static_cast<std::size_t>(a)] = {i, j};
  }

  // The base disks, moved to P + q.
  std::vector<Vec2L> inflated;
  std::vector<Vec2L> moved(static_cast<std::size_t>(n));
  std::vector<long double> displacement(static_cast<std::size_t>(n));  // from the scaled site
  for (long long a = 0; a < n; ++a) {
    const auto [i, j] = site_of[static_cast<std::size_t>(a)];
    const Vec2L p = base.points[static_cast<std::size_t>(a)];
    const Vec2L q = site_position(i, j);
    moved[static_cast<std::size_t>(a)] = {p.x * side + q.x, p.y * side + q.y};
    displacement[static_cast<std::size_t>(a)] =
        std::hypot(p.x * to_lattice - q.x, p.y * to_lattice - q.y);
    inflated.push_back(moved[static_cast<std::size_t>(a)]);
  }
  // A disk on every lattice edge but those between two vacancies.
  static constexpr long long kEdges[3][2] = {{1, 0}, {0, 1}, {-1, 1}};
  for (long long j = 0; j < rows; ++j)
    for (long long i = 0; i + j < rows; ++i)
      for (const auto& edge : kEdges) {
        const long long i2 = i + edge[0], j2 = j + edge[1];
        if (i2 < 0 || i2 + j2 >= rows) continue;
        const long long a = disk_at[lattice_site(rows, i, j)];
        const long long b = disk_at[lattice_site(rows, i2, j2)];
        if (a < 0 && b < 0) continue;
        // One spacing from one end towards the other: the base contact between the ends is kept
        // whole on that side (the middle would halve a tilted one). The end nearer its lattice
        // site keeps it; next to a vacancy, the occupied end.
        bool from_a = a >= 0;
        if (a >= 0 && b >= 0)
          from_a = displacement[static_cast<std::size_t>(a)] <=
                   displacement[static_cast<std::size_t>(b)];
        const Vec2L from = moved[static_cast<std::size_t>(from_a ? a : b)];
        const Vec2L step = site_position(edge[0], edge[1]);
        const long double sign = from_a ? 1 : -1;
        inflated.push_back({from.x + sign * step.x, from.y + sign * step.y});
      }

  const long double new_side = side + static_cast<long double>(rows - 1);
  // Every disk has a neighbour within about one diameter; overlapping ones are closer still.
  const long double closest = min_pair_distance(inflated, 2);
  Packing result;
  for (const Vec2L& p : inflated) result.points.push_back({p.x / new_side, p.y / new_side});
  result.d = closest / new_side;
  return result;
}

std::optional<long long> inflation_base(long long n) {
  long long rows = 1;
  while (triangular(rows) < n) ++rows;
  const long long vacancies = triangular(rows) - n;
  if (rows % 2 == 0 || vacancies % 2 == 0 || vacancies < 3) return std::nullopt;
  const long long base = triangular((rows + 1) / 2) - (vacancies + 1) / 2;
  if (base < 3) return std::nullopt;
  return base;
}

}  // namespace tripack::patterns
