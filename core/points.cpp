#include "core/points.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/geometry.hpp"
#include "core/neighbours.hpp"

namespace tripack {

namespace {

// ----- unit-triangle convention: rounded wall disks ------------------------------------------

// How far p lies beyond side s of the unit triangle (<= 0 inside).
long double beyond(const Vec2L& p, Side s) {
  return -wall_distance(p, s, 1.0L);
}

Side farthest_side(const Vec2L& p) {
  return *std::max_element(kSides.begin(), kSides.end(),
                           [&](Side a, Side b) { return beyond(p, a) < beyond(p, b); });
}

// The point of the unit triangle nearest to p (p itself when inside): the nearest of the
// projections onto the three edges, so a point beyond a corner lands on the corner.
Vec2L nearest_in_unit_triangle(const Vec2L& p) {
  if (beyond(p, farthest_side(p)) <= 0) return p;
  const std::array<Vec2L, 3> corner{Vec2L{0, 0}, Vec2L{1, 0}, Vec2L{0.5L, kSqrt3 / 2}};
  Vec2L best = corner[0];
  long double best_distance = std::numeric_limits<long double>::infinity();
  for (std::size_t k = 0; k < 3; ++k) {
    const Vec2L a = corner[k], edge = corner[(k + 1) % 3] - a;
    const long double t = std::clamp(dot(p - a, edge) / dot(edge, edge), 0.0L, 1.0L);
    const Vec2L q = a + edge * t;
    if (norm(p - q) < best_distance) {
      best_distance = norm(p - q);
      best = q;
    }
  }
  // Exactly on the bottom side rather than 1e-20 off it (the other two sides are not
  // representable exactly anyway).
  if (best.y < 0) best.y = 0;
  return best;
}

// ----- container conventions: the triangle's orientation --------------------------------------

// The orientations files come in: the upright triangle turned by 0, 30, 60, 90 degrees
// counter-clockwise. Turns by 120 degrees and mirror images give one of these again (swapping x
// and y gives the 30-degree one), so they are all the triangles with a side horizontal or
// vertical. Each is brought upright by a multiple of a quarter turn, exact in floating point
// ((x, y) -> (-y, x)), so undoing it adds no rounding.
struct Orientation {
  const char* looks;  // how the file's triangle looks, for the warning
  int quarter_turns;  // counter-clockwise quarter turns that make it upright
};
constexpr std::array<Orientation, 4> kOrientations{{
    {"is upright", 0},
    {"points right (a vertical side on its left: x and y swapped, or turned clockwise?)", 1},
    {"is upside down", 2},
    {"points left (a vertical side on its right: turned counter-clockwise?)", 3},
}};

std::vector<Vec2L> turned(std::vector<Vec2L> pts, int quarter_turns) {
  for (auto& p : pts)
    for (int q = 0; q < quarter_turns; ++q) p = {-p.y, p.x};
  return pts;
}

// The smallest upright triangle holding the points: bounded by y = ymin, sqrt3 x - y = cl and
// sqrt3 x + y = cr.
struct Bounding {
  long double side = 0;
  Vec2L corner;  // its bottom-left vertex
};

Bounding upright_bounding(const std::vector<Vec2L>& pts) {
  long double ymin = pts[0].y, cl = kSqrt3 * pts[0].x - pts[0].y, cr = kSqrt3 * pts[0].x + pts[0].y;
  for (const auto& p : pts) {
    ymin = std::min(ymin, p.y);
    cl = std::min(cl, kSqrt3 * p.x - p.y);
    cr = std::max(cr, kSqrt3 * p.x + p.y);
  }
  return {(cr - cl - 2 * ymin) / kSqrt3, {(cl + ymin) / kSqrt3, ymin}};
}

// The orientation whose bounding triangle is smallest, and the sides of all four.
struct OrientationFit {
  std::size_t best = 0;
  std::array<long double, 4> side{};
};

OrientationFit fit_orientation(const std::vector<Vec2L>& pts) {
  OrientationFit fit;
  for (std::size_t o = 0; o < kOrientations.size(); ++o)
    fit.side[o] = upright_bounding(turned(pts, kOrientations[o].quarter_turns)).side;
  fit.best = static_cast<std::size_t>(std::min_element(fit.side.begin(), fit.side.end()) -
                                      fit.side.begin());
  return fit;
}

// Circles in a container: the centres' bounding triangle (of the container's orientation) maps
// onto the unit triangle. Returns that triangle's side in the file's units.
long double map_container_onto_unit_triangle(std::vector<Vec2L>& pts,
                                             std::vector<std::string>& warnings) {
  const OrientationFit fit = fit_orientation(pts);
  const long double smallest = fit.side[fit.best];
  if (!(smallest > 0) || !std::isfinite(smallest))
    throw InputError("the points do not span a triangle");
  // A relative 1e-6 is far above rounding (1e-16) and far below the gap between a packing's own
  // orientation and any other: when the centres fill their triangle to its corners, the
  // bounding triangles turned from it are sqrt3 and 2 times larger (t22a: 1.73, 2, 1.73).
  for (std::size_t o = 0; o < kOrientations.size(); ++o)
    if (o != fit.best && fit.side[o] <= smallest * (1 + 1e-6L))
      throw InputError(fmt::format(
          "cannot tell the triangle's orientation: the points' bounding triangle that {} and the "
          "one that {} have sides {:.9g} and {:.9g}, within a relative 1e-6",
          kOrientations[fit.best].looks, kOrientations[o].looks, static_cast<double>(smallest),
          static_cast<double>(fit.side[o])));
  const Orientation& o = kOrientations[fit.best];
  pts = turned(std::move(pts), o.quarter_turns);
  constexpr std::array<const char*, 4> kTurn{"", "a quarter turn counter-clockwise", "half a turn",
                                             "a quarter turn clockwise"};
  if (o.quarter_turns)
    warnings.push_back(fmt::format("the file's triangle {}; turned {} to upright", o.looks,
                                   kTurn[static_cast<std::size_t>(o.quarter_turns)]));
  const Bounding b = upright_bounding(pts);
  for (auto& p : pts) p = (p - b.corner) / b.side;
  return b.side;
}

// Below this distance outside (in units of the side) a point is on the side to the precision a
// file can carry; 1e9 times smaller than the rounding slips the warning is about.
constexpr long double kRepresentationSlack = 1e-15L;

// Unit-triangle convention: move points within `tolerance` outside onto the triangle (one
// warning); farther out is an error with a hint at the likely mix-up.
void snap_into_unit_triangle(std::vector<Vec2L>& pts, long double tolerance,
                             std::vector<std::string>& warnings) {
  std::size_t moved = 0;
  long double farthest = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2L inside = nearest_in_unit_triangle(pts[i]);
    if (inside == pts[i]) continue;
    const long double outside = norm(pts[i] - inside);
    if (outside > tolerance) {
      std::string hint =
          "if the file gives circles in a container, use --convention radius or unit-disk-side";
      const OrientationFit fit = fit_orientation(pts);
      if (fit.best != 0 && fit.side[fit.best] <= 1 + tolerance)
        hint += fmt::format(
            "; the points fit a side-1 triangle that {}: the file may be flipped or rotated",
            kOrientations[fit.best].looks);
      throw InputError(fmt::format(
          "point {} ({}, {}) lies {:.3g} outside the unit triangle (beyond its {} side; the "
          "rounding tolerance is {:.3g} of the side); {}",
          i, format_significant(pts[i].x, 17), format_significant(pts[i].y, 17),
          static_cast<double>(outside), side_name(farthest_side(pts[i])),
          static_cast<double>(tolerance), hint));
    }
    pts[i] = inside;
    // A wall disk written exactly is still a hair outside after decimal and binary rounding
    // (17 digits: 5e-18; the side's equation in long double: 1e-19): moving it is no news.
    if (outside <= std::min(tolerance, kRepresentationSlack)) continue;
    ++moved;
    farthest = std::max(farthest, outside);
  }
  if (moved)
    warnings.push_back(fmt::format(
        "{} point{} lie{} outside the unit triangle by up to {:.2g} (within the rounding "
        "tolerance {:.2g} of the side: rounded input?); moved onto its sides",
        moved, moved == 1 ? "" : "s", moved == 1 ? "s" : "", static_cast<double>(farthest),
        static_cast<double>(tolerance)));
}

// The minimum distance; coinciding points (which would make it zero) are an error naming them.
long double minimum_distance(const std::vector<Vec2L>& pts) {
  long double closest = std::numeric_limits<long double>::infinity();
  int ci = -1, cj = -1;
  for_each_pair_within(pts, 1e-12L, [&](int i, int j, long double r) {
    if (r < closest) {
      closest = r;
      ci = i;
      cj = j;
    }
  });
  if (ci >= 0) throw InputError(fmt::format("points {} and {} coincide", ci, cj));
  // Grow the search radius until a pair is found: O(n) per try for a packing's density.
  for (long double r = 0.25L;; r *= 2) {
    const long double m = min_pair_distance(pts, r);
    if (std::isfinite(m)) return m;
  }
}

}  // namespace

PointsReading packing_from_points(PointsFile file, std::optional<Convention> convention,
                                  std::optional<long long> expected_n,
                                  long double rounding_tolerance) {
  auto& pts = file.points;
  if (expected_n && static_cast<long long>(pts.size()) != *expected_n)
    throw InputError(fmt::format("expected {} points, the file has {}", *expected_n, pts.size()));
  if (file.declared_n && static_cast<long long>(pts.size()) != *file.declared_n)
    throw InputError(fmt::format("the header says n = {} but the file holds {} points (truncated?)",
                                 *file.declared_n, pts.size()));
  if (pts.size() < 2)
    throw InputError(fmt::format("need at least 2 points, the file has {}", pts.size()));
  if (convention && file.declared_convention && *convention != *file.declared_convention)
    throw InputError(
        fmt::format("the file declares the {} convention (a '# convention:' line or "
                    "JSON \"convention\"), not {}",
                    convention_name(*file.declared_convention), convention_name(*convention)));
  if (!convention) convention = file.declared_convention;
  Convention c = convention.value_or(Convention::UnitTriangle);
  if (file.radius) {
    if (convention && *convention != Convention::Radius)
      throw InputError(fmt::format(
          "the file gives circles of radius r = {} (layout '{}'), so its convention is radius, "
          "not {}",
          format_significant(*file.radius, 17), file.layout, convention_name(*convention)));
    c = Convention::Radius;
  }

  PointsReading reading;
  reading.convention = c;
  reading.label = file.declared_label;
  long double file_units_per_side = 1;  // lengths in the file per unit-triangle length
  if (c == Convention::UnitTriangle)
    snap_into_unit_triangle(pts, rounding_tolerance, reading.warnings);
  else
    file_units_per_side = map_container_onto_unit_triangle(pts, reading.warnings);

  Packing& pk = reading.packing;
  pk.points = std::move(pts);
  pk.d = minimum_distance(pk.points);

  if (file.declared_d)
    reading.stated_d = file.declared_d;
  else if (file.radius)
    reading.stated_d = 2 * *file.radius / file_units_per_side;
  if (file.radius) {
    const long double closest = pk.d * file_units_per_side, diameter = 2 * *file.radius;
    if (std::fabs(closest / diameter - 1) > 1e-6L)
      reading.warnings.push_back(fmt::format(
          "the closest centres are {} apart, not 2r = {}: the circles {}",
          format_significant(closest, 10), format_significant(diameter, 10),
          closest < diameter ? "overlap" : "do not touch (is r the packing's radius?)"));
  }
  // Rounding moves each point by up to the tolerance, so d by up to twice it.
  reading.header_d_differs =
      file.declared_d && std::fabs(pk.d - *file.declared_d) > 2 * rounding_tolerance;
  if (reading.header_d_differs)
    reading.warnings.push_back(fmt::format("the header's d = {} differs from the points' d = {}",
                                           format_significant(*file.declared_d, 17),
                                           format_significant(pk.d, 17)));
  return reading;
}

}  // namespace tripack
