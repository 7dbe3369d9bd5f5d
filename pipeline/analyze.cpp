#include "pipeline/analyze.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "core/neighbours.hpp"
#include "core/points.hpp"
#include "core/timing.hpp"
#include "formats/formats.hpp"

namespace tripack::pipeline {

std::string Analysis::status() const {
  if (!identification.polish.converged)
    return "bond system has no solution near the relaxed state (not certified)";
  if (pattern.bonds.empty())
    return "no bonds: every disk is a rattler by the surround test (not certified)";
  if (lps_skipped && !fast.accepted)
    return "not certified: the LP-free certificate declined (" + fast.declined +
           "), and the LPs are not run above " + std::to_string(lp_limit) +
           " disks (analyze --lp-any-size runs them)";
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
  return record_of(*this).d.str(digits);
}

void apply_multiprecision(PackingRecord& record, const MultiprecisionPolish& polish) {
  if (!polish.converged) return;
  record.d = PreciseReal(record.pattern.packing.d, polish.d, polish.digits);
  record.L = PreciseReal(1 / record.pattern.packing.d, polish.L, polish.digits);
  record.precise_points = polish.points;
}

PackingRecord record_of(const Analysis& analysis) {
  PackingRecord record = PackingRecord::of(analysis.pattern);
  if (analysis.multiprecision) apply_multiprecision(record, *analysis.multiprecision);
  record.certified = analysis.certified();
  record.verdict = analysis.status();
  record.forces = analysis.stress.forces;
  record.seconds = analysis.times.total();
  identify(record);
  return record;
}

namespace {

// Relax leaves rattlers wherever its LPs pushed them (often against their cage): centre them.
void centre_pattern_rattlers(Pattern& pat) {
  if (pat.rattlers.empty()) return;
  Packing& pk = pat.packing;
  const long double L = 1 / pk.d;
  std::vector<Vec2L> x;
  for (const auto& p : pk.points) x.push_back(p * L);
  centre_rattlers(x, L, pat.rattlers);
  for (int r : pat.rattlers)
    pk.points[static_cast<std::size_t>(r)] = x[static_cast<std::size_t>(r)] / L;
}

// Smallest non-bond gap in units of d (rattlers' play included); +inf if there is none.
long double smallest_gap(const Pattern& pat) {
  const auto g = smallest_gaps(pat.packing, pat.bonds, 1);
  return g.empty() ? std::numeric_limits<long double>::infinity() : g.front().gap;
}

// Relax fast path. If the start, with the contacts it has within 1e-6 d polished
// shut, is rigid with a strictly positive stress f and every other gap is open, it is a strict
// local maximum of d and relax has nothing to gain: its step LP maximizes g subject to
// u_ij.(yi - yj) >= g for the contact pairs (and n.yi >= 0 for the wall contacts, among other
// rows), and summing those rows with the weights f (G^T f = 0, pair forces summing to 1) gives
// 0 >= g. So relax would stop after one LP without moving; skipping that LP (212 s at n = 5051,
// where it is massively degenerate) changes nothing. Returns false, with `a` untouched, when the
// start does not certify this way: the full pipeline then runs.
// Reports a stage's start (or a step in it) when someone listens.
void tell(const ProgressFn& progress, const std::string& stage, int step = 0, long double d = 0) {
  if (!progress) return;
  Progress p;
  p.stage = stage;
  p.step = step;
  p.d = d;
  progress(p);
}

bool certified_start(const Packing& start, const ProgressFn& progress, Analysis& a) {
  const auto t0 = Clock::now();
  Analysis f;
  f.pattern.packing = start;
  Packing& pk = f.pattern.packing;
  if (pk.size() < 2) return false;
  // Same start as relax: centres projected inside (rounding-level excursions of wall contacts),
  // d the true minimum distance.
  for (auto& p : pk.points)
    for (int pass = 0; pass < 2; ++pass)
      for (Side s : kSides) {
        const long double w = wall_distance(p, s, 1.0L);
        if (w < 0) p = p - wall_normal<long double>(s) * w;
      }
  pk.d = min_pair_distance(pk.points, pk.d > 0 ? 1.5L * pk.d : 1);
  if (!std::isfinite(pk.d) || !(pk.d > 0)) return false;
  const long double d_start = pk.d;
  tell(progress, "bonds + polish of the start", 0, pk.d);
  // No rejections: a start whose near contacts do not polish shut is no certified optimum, and
  // dropping candidates one polish at a time took 56 s on a perturbed n = 991 start.
  f.identification = timed(f.times.bonds, [&] { return identify_bonds(pk, {}, 1e-6L, 0); });
  if (!f.identification.polish.converged || f.identification.rejected > 0) return false;
  f.pattern.bonds = f.identification.bonds;
  f.pattern.rattlers = f.identification.rattlers;
  if (f.pattern.bonds.empty()) return false;
  tell(progress, "LP-free certificate of the start", 0, pk.d);
  f.fast = timed(f.times.rigidity,
                 [&] { return fast_certificate(pk, f.pattern.bonds, f.pattern.rattlers); });
  if (!f.fast.accepted) return false;
  // (Rattlers are centred only now: a perturbed start of n = 991 has every disk a rattler by the
  // 1e-6 d contacts, and centring them all took 55 s.) The polished d must be the minimum
  // distance: every non-bond gap clearly open, the rattlers' play included.
  centre_pattern_rattlers(f.pattern);
  if (!(smallest_gap(f.pattern) > 1e-9L)) return false;
  f.relax.converged = f.relax.fast_path = true;
  f.relax.d_start = d_start;
  f.relax.d_end = pk.d;
  for (std::size_t b = 0; b < f.pattern.bonds.size(); ++b) {
    f.relax.active.push_back(f.pattern.bonds[b]);
    f.relax.forces.push_back(f.fast.stress.forces[b]);
  }
  f.rigidity.rigid = true;
  f.stress = f.fast.stress;
  f.times.relax = seconds_since(t0) - f.times.bonds - f.times.rigidity;
  a = std::move(f);
  return true;
}

// The interior-point relax, then the same test as certified_start on its result. On success `a`
// is that analysis; otherwise `a` keeps only the interior report (and its time as relax time).
bool certified_after_interior_relax(const Packing& start, const AnalysisOptions& options,
                                    Analysis& a, Packing& moved) {
  moved = start;
  double seconds = 0;
  InteriorRelaxOptions relax = options.interior;
  if (options.progress)
    relax.on_step = [&](int step, long double D) {
      tell(options.progress, "relax (interior point)", step, D);
    };
  tell(options.progress, "relax (interior point)");
  const InteriorRelaxReport report = timed(seconds, [&] { return interior_relax(moved, relax); });
  Analysis b;
  if (report.converged && certified_start(moved, options.progress, b)) {
    b.relax.interior = true;
    b.relax.newton_steps = report.newton_steps;
    b.relax.d_start = report.d_start;
    b.times.relax += seconds;
    b.interior = report;
    a = std::move(b);
    return true;
  }
  a.interior = report;
  a.times.relax = seconds;
  return false;
}

// Bonds (the `loaded` contacts and those within 1e-6 d), rattlers centred, the LP-free
// certificate, and the rigidity and stress LPs when it declines and `lps` allows them.
void bonds_and_certificates(Analysis& a, const std::vector<Bond>& loaded, bool lps,
                            const ProgressFn& progress) {
  Packing& pk = a.pattern.packing;
  tell(progress, "bonds + polish", 0, pk.d);
  a.identification = timed(a.times.bonds, [&] { return identify_bonds(pk, loaded); });
  a.pattern.bonds = a.identification.bonds;
  a.pattern.rattlers = a.identification.rattlers;
  centre_pattern_rattlers(a.pattern);
  const Pattern& p = a.pattern;
  tell(progress, "LP-free certificate", 0, pk.d);
  a.fast =
      timed(a.times.rigidity, [&] { return fast_certificate(p.packing, p.bonds, p.rattlers); });
  if (a.fast.accepted) {
    a.rigidity.rigid = true;
    a.stress = a.fast.stress;
    return;
  }
  if (!lps) return;
  const double fast_seconds = a.times.rigidity;
  tell(progress, "rigidity LPs", 0, pk.d);
  a.rigidity =
      timed(a.times.rigidity, [&] { return test_rigidity(p.packing, p.bonds, p.rattlers); });
  a.times.rigidity += fast_seconds;
  tell(progress, "stress LP", 0, pk.d);
  a.stress =
      timed(a.times.stress, [&] { return stress_certificate(p.packing, p.bonds, p.rattlers); });
}

}  // namespace

Analysis analyze_packing(const Packing& start, const AnalysisOptions& options) {
  Analysis a;
  const auto t0 = Clock::now();
  const auto& progress = options.progress;
  if (certified_start(start, progress, a)) {
  } else if (Packing moved; start.size() >= options.interior_from &&
                            certified_after_interior_relax(start, options, a, moved)) {
  } else if (start.size() > options.lp_limit && a.interior) {
    // Too large for the LPs: the interior-point relax's result, with what the LP-free
    // certificate says of it.
    a.lps_skipped = true;
    a.lp_limit = options.lp_limit;
    a.pattern.packing = moved;
    a.relax.d_start = a.interior->d_start;
    a.relax.d_end = moved.d;
    a.relax.newton_steps = a.interior->newton_steps;
    a.times.relax = seconds_since(t0);
    bonds_and_certificates(a, {}, false, progress);
  } else {
    a.pattern.packing = start;
    RelaxOptions relax;
    if (progress)
      relax.on_step = [&](int step, long double d) { tell(progress, "relax (LP steps)", step, d); };
    tell(progress, "relax (LP steps)");
    a.relax = relax_packing(a.pattern.packing, relax);
    a.times.relax = seconds_since(t0);  // declined fast paths count as relax time
    bonds_and_certificates(a, a.relax.active, true, progress);
  }
  Packing& pk = a.pattern.packing;
  a.gaps = smallest_gaps(pk, a.pattern.bonds, 64);
  if (options.digits > kLongDoubleDigits) tell(progress, "multiprecision polish", 0, pk.d);
  if (options.digits > kLongDoubleDigits)
    a.multiprecision = timed(a.times.multiprecision, [&] {
      return polish_multiprecision(pk, a.pattern.bonds, a.pattern.rattlers, options.digits);
    });
  return a;
}

namespace {

const MultiprecisionPolish* high_digits(const Analysis& a, int wanted) {
  const auto& mp = a.multiprecision;
  return wanted > kLongDoubleDigits && mp && mp->converged ? &*mp : nullptr;
}

}  // namespace

std::string FileAnalysis::d_string(int wanted) const {
  if (const auto* mp = high_digits(analysis, wanted)) return mp->d;
  return format_significant(analysis.pattern.packing.d, std::min(wanted, kLongDoubleDigits));
}

std::string FileAnalysis::L_string(int wanted) const {
  if (const auto* mp = high_digits(analysis, wanted)) return mp->L;
  return format_significant(1 / analysis.pattern.packing.d, std::min(wanted, kLongDoubleDigits));
}

std::string FileAnalysis::value_string(int wanted) const {
  if (convention == Convention::UnitTriangle) return d_string(wanted);
  if (high_digits(analysis, wanted) && !mp_value_in_convention.empty())
    return mp_value_in_convention;
  return format_significant(from_d(analysis.pattern.packing.d, convention),
                            std::min(wanted, kLongDoubleDigits));
}

FileAnalysis analyze_file(const AnalyzeRequest& request) {
  FileAnalysis result;
  result.file = request.file;
  result.digits = request.digits;
  const auto start = Clock::now();
  PointsFile file = read_packing_file(request.file);
  result.layout = file.layout;
  PointsReading reading = packing_from_points(
      std::move(file), request.convention,
      request.expected_n ? std::optional<long long>(request.expected_n) : std::nullopt);
  // As read: the file's declared convention, radius for an x y r file.
  result.convention = reading.convention;
  result.label = reading.label;
  result.warnings = std::move(reading.warnings);
  result.read_seconds = seconds_since(start);
  AnalysisOptions options;
  options.digits = request.digits;
  options.progress = request.progress;
  if (request.lp_any_size) options.lp_limit = SIZE_MAX;
  result.analysis = analyze_packing(reading.packing, options);
  const auto& mp = result.analysis.multiprecision;
  if (mp && mp->converged && result.convention != Convention::UnitTriangle)
    result.mp_value_in_convention =
        radius_or_side_from_d(mp->d, result.convention == Convention::Radius, request.digits);
  return result;
}

}  // namespace tripack::pipeline
