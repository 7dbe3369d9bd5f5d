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

long double cage_clearance(const Vec2L& p, const std::vector<Vec2L>& neighbours, long double L) {
  long double c = std::numeric_limits<long double>::infinity();
  for (const auto& q : neighbours) c = std::min(c, norm(p - q) - 1);
  for (Side s : kSides) c = std::min(c, wall_distance(p, s, L));
  return c;
}

Vec2L centre_in_cage(Vec2L p, const std::vector<Vec2L>& neighbours, long double L) {
  long double best = cage_clearance(p, neighbours, L);
  long double h = 0.25L;
  constexpr long double r = 0.70710678118654752440L;
  static const Vec2L dirs[8] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1},
                                {r, r}, {-r, r}, {r, -r}, {-r, -r}};
  // At most 64 moves per step size: a disk wedged between contacts (no real rattler) can creep
  // along a ridge of the max-min by ever smaller gains (55 s for the 991 such disks of a
  // perturbed pattern).
  for (int moves = 0; h > 1e-13L; ++moves) {
    bool moved = false;
    for (const auto& d : dirs) {
      const Vec2L t = p + d * h;
      const long double c = cage_clearance(t, neighbours, L);
      if (c > best) {
        best = c;
        p = t;
        moved = true;
      }
    }
    if (!moved || moves == 64) {
      h /= 2;
      moves = 0;
    }
  }
  return p;
}

long double centre_rattlers(std::vector<Vec2L>& pts, long double L,
                            const std::vector<int>& rattlers) {
  if (rattlers.empty()) return std::numeric_limits<long double>::infinity();
  std::vector<char> is_rattler(pts.size(), 0);
  for (int r : rattlers) is_rattler[static_cast<std::size_t>(r)] = 1;
  std::vector<std::vector<int>> near(pts.size());
  for_each_pair_within(pts, 2.5L, [&](int i, int j, long double) {
    if (is_rattler[static_cast<std::size_t>(i)]) near[static_cast<std::size_t>(i)].push_back(j);
    if (is_rattler[static_cast<std::size_t>(j)]) near[static_cast<std::size_t>(j)].push_back(i);
  });
  long double room = std::numeric_limits<long double>::infinity();
  for (int r : rattlers) {
    std::vector<Vec2L> nb;
    for (int j : near[static_cast<std::size_t>(r)]) nb.push_back(pts[static_cast<std::size_t>(j)]);
    auto& p = pts[static_cast<std::size_t>(r)];
    p = centre_in_cage(p, nb, L);
    room = std::min(room, cage_clearance(p, nb, L));
  }
  return room;
}

long double min_pair_distance(const std::vector<Vec2L>& pts, long double radius) {
  long double best = std::numeric_limits<long double>::infinity();
  for_each_pair_within(pts, radius,
                       [&](int, int, long double dist) { best = std::min(best, dist); });
  return best;
}

}  // namespace tripack
