#include "core/neighbours.hpp"

#include <limits>

namespace tripack {

std::vector<Bond> find_contacts(const std::vector<Vec2L>& pts, long double L, long double tol,
                                const std::vector<char>& skip) {
  std::vector<Bond> bonds;
  auto skipped = [&](int i) { return !skip.empty() && skip[static_cast<std::size_t>(i)]; };
  for_each_pair_within(pts, 1.0L + tol, [&](int i, int j, long double dist) {
    if (skipped(i) || skipped(j)) return;
    if (std::fabs(dist - 1.0L) <= tol) bonds.push_back(Bond::pair(i, j));
  });
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (skipped(static_cast<int>(i))) continue;
    for (Side s : kSides) {
      if (std::fabs(wall_distance(pts[i], s, L)) <= tol)
        bonds.push_back(Bond::wall(static_cast<int>(i), s));
    }
  }
  std::sort(bonds.begin(), bonds.end());
  return bonds;
}

long double min_pair_distance(const std::vector<Vec2L>& pts, long double radius) {
  long double best = std::numeric_limits<long double>::infinity();
  for_each_pair_within(pts, radius,
                       [&](int, int, long double dist) { best = std::min(best, dist); });
  return best;
}

}  // namespace tripack
