#include "pipeline/analyze.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/io.hpp"
#include "core/neighbours.hpp"
#include "pipeline/timing.hpp"

namespace tripack::pipeline {

std::string Analysis::status() const {
  if (!identification.polish.converged)
    return "bond system has no solution near the relaxed state (not certified)";
  if (!rigidity.rigid && rigidity.opening_bonds > 0)
    return fmt::format("NOT rigid: a first-order motion moves {} disks and opens {} bonds",
                       rigidity.moving_disks, rigidity.opening_bonds);
  if (!rigidity.rigid)
    return fmt::format(
        "NOT certified rigid: a motion of {} disks keeps every bond to first order (within the "
        "LP's "
        "resolution; near-degenerate contacts look like this)",
        rigidity.moving_disks);
  if (!stress.exists)
    return "rigid, but no balancing non-negative stress (not a first-order optimum)";
  if (!stress.strictly_positive)
    return "rigid, stress exists but some bond carries none (not certified strict)";
  return "certified: rigid with a strictly positive stress (strict local optimum of d)";
}

std::string Analysis::d_string(int digits) const {
  if (multiprecision && multiprecision->converged) return multiprecision->d;
  return format_significant(pattern.packing.d, std::min(digits, 18));
}

Analysis analyze_packing(const Packing& start, const AnalysisOptions& options) {
  Analysis a;
  a.pattern.packing = start;
  Packing& pk = a.pattern.packing;
  a.relax = timed(a.times.relax, [&] { return relax_packing(pk); });
  a.identification = timed(a.times.bonds, [&] { return identify_bonds(pk, a.relax.active); });
  a.pattern.bonds = a.identification.bonds;
  a.pattern.rattlers = a.identification.rattlers;
  // Relax leaves rattlers wherever its LPs pushed them (often against their cage): centre them.
  if (!a.pattern.rattlers.empty()) {
    const long double L = 1 / pk.d;
    std::vector<Vec2L> x;
    for (const auto& p : pk.points) x.push_back(p * L);
    centre_rattlers(x, L, a.pattern.rattlers);
    for (int r : a.pattern.rattlers)
      pk.points[static_cast<std::size_t>(r)] = x[static_cast<std::size_t>(r)] / L;
  }
  a.rigidity = timed(a.times.rigidity,
                     [&] { return test_rigidity(pk, a.pattern.bonds, a.pattern.rattlers); });
  a.stress = timed(a.times.stress,
                   [&] { return stress_certificate(pk, a.pattern.bonds, a.pattern.rattlers); });
  a.gaps = smallest_gaps(pk, a.pattern.bonds, 64);
  if (options.digits > 18)
    a.multiprecision = timed(a.times.multiprecision, [&] {
      return polish_multiprecision(pk, a.pattern.bonds, a.pattern.rattlers, options.digits);
    });
  return a;
}

Packing packing_from_points(std::vector<Vec2L> pts, Convention c,
                            std::optional<long long> expected_n) {
  if (expected_n && static_cast<long long>(pts.size()) != *expected_n)
    throw InputError(fmt::format("expected {} points, the file has {}", *expected_n, pts.size()));
  if (pts.size() < 2)
    throw InputError(fmt::format("need at least 2 points, the file has {}", pts.size()));
  if (c == Convention::UnitTriangle) {
    // Centres must lie in the unit triangle; 1e-9 forgives coordinates printed to ~10 digits.
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (Side s : kSides)
        if (wall_distance(pts[i], s, 1.0L) < -1e-9L)
          throw InputError(fmt::format(
              "point {} ({}, {}) is outside the unit triangle (beyond its {} side)", i,
              static_cast<double>(pts[i].x), static_cast<double>(pts[i].y), side_name(s)));
  } else {
    // Circles in a container: their centres span a smaller triangle of the same orientation,
    // bounded by y = ymin, sqrt3 x - y = cl and sqrt3 x + y = cr. Map it onto the unit triangle.
    long double ymin = pts[0].y, cl = kSqrt3 * pts[0].x - pts[0].y,
                cr = kSqrt3 * pts[0].x + pts[0].y;
    for (const auto& p : pts) {
      ymin = std::min(ymin, p.y);
      cl = std::min(cl, kSqrt3 * p.x - p.y);
      cr = std::max(cr, kSqrt3 * p.x + p.y);
    }
    const long double side = (cr - cl - 2 * ymin) / kSqrt3;
    if (!(side > 0)) throw InputError("the points do not span a triangle");
    const Vec2L corner{(cl + ymin) / kSqrt3, ymin};
    for (auto& p : pts) p = (p - corner) / side;
  }
  Packing pk;
  pk.points = std::move(pts);
  // Coinciding points make d zero: reject them, naming the pair.
  long double closest = std::numeric_limits<long double>::infinity();
  int ci = -1, cj = -1;
  for_each_pair_within(pk.points, 1e-12L, [&](int i, int j, long double r) {
    if (r < closest) {
      closest = r;
      ci = i;
      cj = j;
    }
  });
  if (ci >= 0) throw InputError(fmt::format("points {} and {} coincide", ci, cj));
  for (long double r = 0.25L;; r *= 2) {
    const long double m = min_pair_distance(pk.points, r);
    if (std::isfinite(m)) {
      pk.d = m;
      break;
    }
  }
  return pk;
}

namespace {

const MultiprecisionPolish* high_digits(const Analysis& a, int wanted) {
  const auto& mp = a.multiprecision;
  return wanted > 18 && mp && mp->converged ? &*mp : nullptr;
}

}  // namespace

std::string FileAnalysis::d_string(int wanted) const {
  if (const auto* mp = high_digits(analysis, wanted)) return mp->d;
  return format_significant(analysis.pattern.packing.d, std::min(wanted, 18));
}

std::string FileAnalysis::L_string(int wanted) const {
  if (const auto* mp = high_digits(analysis, wanted)) return mp->L;
  return format_significant(1 / analysis.pattern.packing.d, std::min(wanted, 18));
}

std::string FileAnalysis::value_string(int wanted) const {
  if (convention == Convention::UnitTriangle) return d_string(wanted);
  if (high_digits(analysis, wanted) && !mp_value_in_convention.empty())
    return mp_value_in_convention;
  return format_significant(from_d(analysis.pattern.packing.d, convention), std::min(wanted, 18));
}

FileAnalysis analyze_file(const AnalyzeRequest& request) {
  FileAnalysis result;
  result.file = request.file;
  result.digits = request.digits;
  const auto start = Clock::now();
  result.convention = request.convention.value_or(Convention::UnitTriangle);
  Packing packing =
      packing_from_points(read_points_file(request.file), result.convention, request.expected_n);
  result.layout = "x y";
  result.read_seconds = seconds_since(start);
  result.analysis = analyze_packing(packing, {request.digits});
  const auto& mp = result.analysis.multiprecision;
  if (mp && mp->converged && result.convention != Convention::UnitTriangle)
    result.mp_value_in_convention =
        radius_or_side_from_d(mp->d, result.convention == Convention::Radius, request.digits);
  return result;
}

}  // namespace tripack::pipeline
