// Near-pair search on a uniform cell grid: O(n) for points at bounded density, which every
// packing is. Used for contact detection, validation and (later) the billiards engine set-up.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "core/packing.hpp"

namespace tripack {

// Calls f(i, j, dist) once for every unordered pair i < j with |p_i - p_j| <= radius.
template <class T, class F>
void for_each_pair_within(const std::vector<Vec2T<T>>& pts, T radius, F&& f) {
  const std::size_t n = pts.size();
  if (n < 2) return;
  T xmin = pts[0].x, xmax = pts[0].x, ymin = pts[0].y, ymax = pts[0].y;
  for (const auto& p : pts) {
    xmin = std::min(xmin, p.x);
    xmax = std::max(xmax, p.x);
    ymin = std::min(ymin, p.y);
    ymax = std::max(ymax, p.y);
  }
  // Cell size >= radius so neighbours are in the 3x3 block; cap the cell count near n.
  const double span = static_cast<double>(std::max(xmax - xmin, ymax - ymin));
  double cell = std::max(static_cast<double>(radius), span / std::sqrt(static_cast<double>(n)));
  if (!(cell > 0)) cell = 1;
  const auto nx = static_cast<std::int64_t>(static_cast<double>(xmax - xmin) / cell) + 1;
  const auto ny = static_cast<std::int64_t>(static_cast<double>(ymax - ymin) / cell) + 1;
  auto cell_of = [&](const Vec2T<T>& p) {
    auto cx = std::min<std::int64_t>(
        nx - 1, static_cast<std::int64_t>(static_cast<double>(p.x - xmin) / cell));
    auto cy = std::min<std::int64_t>(
        ny - 1, static_cast<std::int64_t>(static_cast<double>(p.y - ymin) / cell));
    return cy * nx + cx;
  };
  // Counting sort of points by cell.
  std::vector<std::int64_t> start(static_cast<std::size_t>(nx * ny + 1), 0);
  std::vector<std::int64_t> cells(n);
  for (std::size_t i = 0; i < n; ++i) {
    cells[i] = cell_of(pts[i]);
    ++start[cells[i] + 1];
  }
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<int> order(n);
  {
    std::vector<std::int64_t> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < n; ++i) order[fill[cells[i]]++] = static_cast<int>(i);
  }
  const T r2 = radius * radius;
  // Prefilter in double (fast SSE arithmetic even when T is long double): a pair is examined in
  // T only if its double distance is within a relative 1e-9 of the radius.
  const double r2_filter = static_cast<double>(r2) * (1 + 1e-9) + 1e-300;
  static constexpr int kStencil[5][2] = {{0, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  for (std::int64_t cy = 0; cy < ny; ++cy) {
    for (std::int64_t cx = 0; cx < nx; ++cx) {
      const std::int64_t c = cy * nx + cx;
      for (const auto& s : kStencil) {
        const std::int64_t ox = cx + s[0], oy = cy + s[1];
        if (ox < 0 || ox >= nx || oy >= ny) continue;
        const std::int64_t o = oy * nx + ox;
        for (auto a = start[c]; a < start[c + 1]; ++a) {
          const auto b0 = (o == c) ? a + 1 : start[o];
          for (auto b = b0; b < start[o + 1]; ++b) {
            const int i = order[a], j = order[b];
            const double dx = static_cast<double>(pts[i].x) - static_cast<double>(pts[j].x);
            const double dy = static_cast<double>(pts[i].y) - static_cast<double>(pts[j].y);
            if (dx * dx + dy * dy > r2_filter) continue;
            const auto dv = pts[i] - pts[j];
            const T q = dot(dv, dv);
            if (q <= r2) {
              using std::sqrt;
              f(std::min(i, j), std::max(i, j), sqrt(q));
            }
          }
        }
      }
    }
  }
}

// Contacts of a configuration in disk units (min distance 1, triangle side L): pairs with
// |dist - 1| <= tol and wall bonds with |wall distance| <= tol. Disks flagged in `skip`
// (rattlers) are left out. The result is sorted.
std::vector<Bond> find_contacts(const std::vector<Vec2L>& pts, long double L, long double tol,
                                const std::vector<char>& skip = {});

// Rattler cages, in disk units (min distance 1, triangle side L). The clearance of a disk at p
// is its distance to the nearest neighbour centre minus 1, or to the nearest side.
long double cage_clearance(const Vec2L& p, const std::vector<Vec2L>& neighbours, long double L);
// The point of largest clearance near p (the cage's centre), by compass search: cheap (a few
// hundred evaluations over a handful of neighbours) and robust to the non-smooth max-min.
Vec2L centre_in_cage(Vec2L p, const std::vector<Vec2L>& neighbours, long double L);
// Moves every listed disk to the centre of its cage (one after the other); returns the smallest
// clearance reached.
long double centre_rattlers(std::vector<Vec2L>& pts, long double L,
                            const std::vector<int>& rattlers);

// Smallest pairwise distance among points no farther apart than `radius` (infinity if none).
long double min_pair_distance(const std::vector<Vec2L>& pts, long double radius);

}  // namespace tripack
