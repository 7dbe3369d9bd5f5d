#include "pipeline/analyze.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/io.hpp"
#include "core/neighbours.hpp"
#include "core/points.hpp"
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
  PointsFile file = read_points_file(request.file);
  result.layout = file.layout;
  // An x y r file implies the radius convention.
  result.convention =
      request.convention.value_or(file.radius ? Convention::Radius : Convention::UnitTriangle);
  PointsReading reading =
      packing_from_points(std::move(file), request.convention, request.expected_n);
  result.warnings = std::move(reading.warnings);
  result.read_seconds = seconds_since(start);
  result.analysis = analyze_packing(reading.packing, {request.digits});
  const auto& mp = result.analysis.multiprecision;
  if (mp && mp->converged && result.convention != Convention::UnitTriangle)
    result.mp_value_in_convention =
        radius_or_side_from_d(mp->d, result.convention == Convention::Radius, request.digits);
  return result;
}

}  // namespace tripack::pipeline
