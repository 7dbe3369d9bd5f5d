#include "pipeline/analyze.hpp"

#include <fmt/format.h>

#include <algorithm>
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

namespace {

// The smallest non-bond gap between held disks (rattlers' play apart), +inf if none.
long double smallest_held_gap(const std::vector<Gap>& gaps) {
  for (const auto& g : gaps)
    if (!g.rattler) return g.gap;
  return std::numeric_limits<long double>::infinity();
}

}  // namespace

std::string Analysis::status() const {
  if (precise && precise->certified)
    return fmt::format(
        "certified at {} digits (multiprecision): rigid with a strictly positive stress (strict "
        "local optimum of d)",
        precise->digits);
  if (precise)
    return fmt::format("not certified: the multiprecision certificate ({} digits) declined: {}",
                       precise->digits, precise->declined);
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
  record.min_force = analysis.stress.exists ? analysis.stress.min_force : 0;
  record.smallest_gap = smallest_held_gap(analysis.gaps);
  record.certificate_digits = analysis.precise ? analysis.precise->digits : 0;
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
  for (auto& p : pk.points) project_inside(p, 2);
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

// The multiprecision certificate (docs/certified.md, "The multiprecision certificate").

// Why the double-precision verdict cannot stand alone (empty: it can). The margins are measured
// against the long double positions' resolution: the polish leaves each bond equation exact to
// its residual, which places the centres to about residual / sigma, sigma = sqrt(lambda_min(G^T
// G)) the smallest singular value of the bond-opening map (the LP-free certificate's estimate).
// A gap or a force within 1000x of that is not told from zero.
std::string precise_reason(const Analysis& a, const AnalysisOptions& o) {
  if (!a.certified()) return "the double-precision certificate declined";
  if (o.reference_bonds && a.pattern.bonds != *o.reference_bonds)
    return "the bonds from geometry differ from the builder's";
  if (o.reference_rattlers && a.pattern.rattlers != *o.reference_rattlers)
    return "the rattlers from geometry differ from the builder's";
  const long double lambda = a.fast.min_eigenvalue;
  if (!(lambda > 0)) return "G^T G is singular in double precision (the LPs decided rigidity)";
  const long double sigma = std::sqrt(lambda);
  const long double L = 1 / a.pattern.packing.d;
  const long double residual =
      std::max(a.identification.polish.max_residual,
               std::numeric_limits<long double>::epsilon() * std::max(1.0L, L));
  const long double position = residual / sigma;  // disk units = units of d
  const long double gap = smallest_held_gap(a.gaps);
  if (gap < 1e3L * position)
    return fmt::format(
        "the smallest non-bond gap, {:.3Lg} d, is within 1000x of the long double positions' "
        "resolution, {:.2Lg} d",
        gap, position);
  const long double force = a.stress.residual / sigma;
  if (a.stress.min_force < 1e3L * force)
    return fmt::format(
        "the smallest force, {:.3Lg}, is within 1000x of its resolution in double, {:.2Lg}",
        a.stress.min_force, force);
  return {};
}

// Digits: the smallest gap double precision saw, g = 10^-e (e capped at long double's 19), is
// resolved by e + 20 orders at 2e + 20 digits; at least 40.
int precise_digits(const Analysis& a) {
  long double g = smallest_held_gap(a.gaps);
  if (!std::isfinite(g))
    for (const auto& x : a.gaps)
      if (x.gap > 0) {
        g = x.gap;
        break;
      }
  const int e = g > 0 && std::isfinite(g)
                    ? std::clamp(static_cast<int>(std::ceil(-std::log10(g))), 1, 19)
                    : 19;
  return std::max(40, 2 * e + 20);
}

// The deep relax: relax's LP steps on to long double's resolution. Relax stops once a step
// gains less than 1e-13 relative; a contact whose force is 1e-10 then can still stand 1e-7 d
// open, where a true gap is 1e-11 d, and no candidate set is right (build --n 188: every disk a
// rattler). From the analysis' input: the double path's result has its rattlers centred in their
// cages, and where it called every disk a rattler that moved every disk. `start` and `loaded`
// become its result and its loaded contacts unless the double path ended higher.
void deep_relax(PreciseStage& st, Packing& start, std::vector<Bond>& loaded, const Packing& input,
                const AnalysisOptions& o) {
  tell(o.progress, "multiprecision certificate: deep relax (LP steps)", 0, start.d);
  RelaxOptions deep;
  deep.stationary = 1e-18L;
  deep.min_trust = 1e-19L;
  if (o.progress)
    deep.on_step = [&](int step, long double d) {
      tell(o.progress, "multiprecision certificate: deep relax (LP steps)", step, d);
    };
  Packing moved = input;
  st.deep_relax = timed(st.deep_relax_seconds, [&] { return relax_packing(moved, deep); });
  st.deep_relaxed = true;
  // Relax never lowers d below its start; keep its result (and its loaded contacts) unless the
  // double path ended higher.
  if (moved.d >= start.d) {
    start = std::move(moved);
    loaded = st.deep_relax.active;
  }
}

// The state's own contacts: the gaps below the widest jump (ratio) between consecutive gaps
// under 1e-6 d, sorted; st's contacts, contact_gap and next_gap say where the jump is. Gaps below
// long double's resolution of a distance (coordinates to ~1e-19, divided by d) count as that
// resolution: their ratios mean nothing. After the deep relax the jump is clean where the packing
// has settled (sparse-rows k = 10: 1.2e-18 d, then 2.1e-8 d).
std::vector<Bond> state_contacts(PreciseStage& st, const Packing& start) {
  std::vector<Bond> contacts;
  const auto all = smallest_gaps(start, {}, SIZE_MAX);
  const long double resolution = 64 * std::numeric_limits<long double>::epsilon() / start.d;
  auto positive = [&](long double g) { return std::max(g, resolution); };
  std::size_t cut = 0;
  long double jump = 0;
  for (std::size_t k = 1; k < all.size() && all[k - 1].gap < 1e-6L; ++k) {
    const long double ratio = positive(all[k].gap) / positive(all[k - 1].gap);
    if (ratio > jump) {
      jump = ratio;
      cut = k;
    }
  }
  for (std::size_t k = 0; k < cut; ++k) contacts.push_back(all[k].contact);
  std::sort(contacts.begin(), contacts.end());
  if (cut > 0) {
    st.contacts = static_cast<int>(cut);
    st.contact_gap = all[cut - 1].gap;
    st.next_gap = all[cut].gap;
  }
  return contacts;
}

// One identification and certificate at t.digits; false when more digits could not help.
bool attempt_certificate(PreciseStage& t, const Packing& start, const std::vector<Bond>& from,
                         long double threshold, DropRule rule, const ProgressFn& progress) {
  tell(progress, fmt::format("multiprecision certificate ({} digits)", t.digits), 0, start.d);
  t.identification = identify_bonds_multiprecision(start, from, threshold, t.digits, rule);
  const auto& id = t.identification;
  if (!id.found) {
    t.declined = id.failure;
    return false;
  }
  t.gap_floor = std::max(std::pow(10.0L, -static_cast<long double>(t.digits)), id.gaps.bond_floor);
  t.smallest_gap = std::numeric_limits<long double>::infinity();
  for (const auto& g : id.gaps.gaps)
    if (!g.rattler) {
      t.smallest_gap = g.gap;
      t.smallest_gap_contact = g.contact;
      break;
    }
  t.certificate = multiprecision_certificate(id.polish, id.bonds, id.rattlers);
  // A gap is resolved when it stands half the working digits above the floor (1e-11 d against
  // a floor of 1e-42 at 42 digits: 31 orders).
  const long double resolved = t.gap_floor * std::pow(10.0L, t.digits / 2.0L);
  const bool gaps_resolved = t.smallest_gap > resolved;
  const bool cages = !(id.rattler_clearance < -t.gap_floor);
  t.certified = t.certificate.certified() && gaps_resolved && cages;
  if (t.certified) return false;
  t.declined = !cages ? "a rattler has no room in its cage"
               : !t.certificate.certified()
                   ? t.certificate.declined
                   : fmt::format(
                         "the smallest non-bond gap, {:.3Lg} d, is not resolved "
                         "above {:.2Lg} d",
                         t.smallest_gap, resolved);
  return cages && (!gaps_resolved || (t.certificate.rigid && !t.certificate.strictly_positive));
}

// Both drop rules (analysis/bonds.hpp), then twice the digits if precision was short. Keeps the
// certified attempt, else the last that found bonds, else the last (each a copy of st).
PreciseStage kept_attempt(const PreciseStage& st, const Packing& start,
                          const std::vector<Bond>& hints, const std::vector<Bond>& contacts,
                          int first, const ProgressFn& progress) {
  std::optional<PreciseStage> kept;
  for (int round = 0; round < 2 && !(kept && kept->certified); ++round) {
    bool short_of_digits = false;
    // The candidates within 1e-6 d by either drop rule, then the state's own contacts alone.
    for (int way = 0; way < 3; ++way) {
      if (way == 2 && contacts.empty()) break;
      PreciseStage t = st;
      t.attempts = round + 1;
      t.digits = round == 0 ? first : 2 * first;
      const bool more =
          way < 2 ? attempt_certificate(t, start, hints, 1e-6L,
                                        way == 0 ? DropRule::Widest : DropRule::Stretched, progress)
                  : attempt_certificate(t, start, contacts, 0, DropRule::Widest, progress);
      short_of_digits = more || short_of_digits;
      if (!kept || t.certified || t.identification.found || !kept->identification.found)
        kept = std::move(t);
      if (kept->certified) break;
    }
    if (!short_of_digits) break;
  }
  return std::move(*kept);
}

// Why no bond set was found, from the state's own contacts (st.contacts > 0).
std::string no_bond_set_reason(const PreciseStage& st, const Packing& start,
                               const std::vector<Bond>& contacts, std::size_t lp_limit) {
  std::vector<Bond> held = contacts;
  const auto rattlers = find_rattlers(start, held);
  return fmt::format(
      "{} contacts within {:.2Lg} d (the next gap {:.2Lg} d){}; {}", st.contacts, st.contact_gap,
      st.next_gap,
      st.deep_relax.converged ? ", first-order stationary (no LP step gains 1e-18)"
      : st.deep_relaxed       ? ""
                              : fmt::format(" (no deep relax above {} disks)", lp_limit),
      held.empty()
          ? std::string("with them every disk is a rattler by the surround test: not jammed "
                        "at first order") +
                (st.deep_relax.converged
                     ? " (a degenerate maximum no first-order certificate covers)"
                     : "")
          : fmt::format("with them {} rattlers, but no bond set with a solution: {}",
                        rattlers.size(), st.identification.failure));
}

// The certified configuration replaces the double path's: packing, bonds, rattlers, stress and
// the 64 smallest gaps; st counts the reference bonds it leaves open.
void adopt_certified(Analysis& a, PreciseStage& st, const AnalysisOptions& o) {
  auto& id = st.identification;
  if (o.reference_bonds) {
    st.reference_open = 0;
    for (const Bond& b : *o.reference_bonds)
      if (!std::binary_search(id.bonds.begin(), id.bonds.end(), b) &&
          !std::binary_search(id.rattlers.begin(), id.rattlers.end(), b.a) &&
          (b.is_wall() || !std::binary_search(id.rattlers.begin(), id.rattlers.end(), b.b)))
        ++st.reference_open;
  }
  a.pattern.packing = rounded_packing(id.polish);
  a.pattern.bonds = id.bonds;
  a.pattern.rattlers = id.rattlers;
  a.rigidity = {};
  a.rigidity.rigid = true;
  a.stress = st.certificate.stress;
  a.gaps.clear();
  for (const auto& g : id.gaps.gaps) {
    if (a.gaps.size() == 64) break;
    a.gaps.push_back({g.contact, g.gap, g.rattler});
  }
}

void precise_stage(Analysis& a, const Packing& input, const AnalysisOptions& o,
                   std::string reason) {
  const auto t0 = Clock::now();
  PreciseStage st;
  st.reason = std::move(reason);
  // The deep relax first, not above lp_limit disks (its LPs do not scale).
  Packing start = a.pattern.packing;
  std::vector<Bond> loaded = a.relax.active;
  if (start.size() <= o.lp_limit) deep_relax(st, start, loaded, input, o);
  // Candidates: the double path's bonds, the relaxes' loaded contacts, the builder's bonds, and
  // (in identify_bonds_multiprecision) every contact within 1e-6 d, the double path's own
  // threshold.
  std::vector<Bond> hints = a.pattern.bonds;
  hints.insert(hints.end(), a.relax.active.begin(), a.relax.active.end());
  hints.insert(hints.end(), loaded.begin(), loaded.end());
  if (o.reference_bonds)
    hints.insert(hints.end(), o.reference_bonds->begin(), o.reference_bonds->end());
  const std::vector<Bond> contacts = state_contacts(st, start);
  st = kept_attempt(st, start, hints, contacts, precise_digits(a), o.progress);
  if (!st.identification.found && st.contacts > 0)
    st.declined = no_bond_set_reason(st, start, contacts, o.lp_limit);
  if (st.certified) adopt_certified(a, st, o);
  st.seconds = seconds_since(t0);
  a.times.certificate_mp = st.seconds;
  a.precise = std::move(st);
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
  a.gaps = smallest_gaps(a.pattern.packing, a.pattern.bonds, 64);
  if (options.multiprecision_certificate && a.pattern.packing.size() >= 2)
    if (std::string reason = precise_reason(a, options); !reason.empty())
      precise_stage(a, start, options, std::move(reason));
  Packing& pk = a.pattern.packing;
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
  const auto start = Clock::now();
  PointsFile file = read_packing_file(request.file);
  return analyze_points(std::move(file), request, seconds_since(start));
}

FileAnalysis analyze_points(PointsFile file, const AnalyzeRequest& request, double read_seconds) {
  FileAnalysis result;
  result.file = request.file;
  result.digits = request.digits;
  const auto start = Clock::now();
  result.layout = file.layout;
  PointsReading reading = packing_from_points(
      std::move(file), request.convention,
      request.expected_n ? std::optional<long long>(request.expected_n) : std::nullopt);
  // As read: the file's declared convention, radius for an x y r file.
  result.convention = reading.convention;
  result.label = reading.label;
  result.warnings = std::move(reading.warnings);
  result.read_seconds = read_seconds + seconds_since(start);
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
