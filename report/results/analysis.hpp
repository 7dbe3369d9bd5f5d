// The analysis of a packing (`tripack analyze`), and the certificate's fields and lines that every
// result carrying an analysis shares (build, billiards, compare).
#pragma once

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <utility>

#include "pipeline/analyze.hpp"
#include "polish/polish_mp.hpp"
#include "report/results/common.hpp"

namespace tripack::report::results {

using namespace pipeline;

// The multiprecision certificate's object (docs/certified.md): null when it did not run.
inline Tree precise_tree(const Analysis& a) {
  if (!a.precise) return nullptr;
  const auto& p = *a.precise;
  const auto& id = p.identification;
  const auto& c = p.certificate;
  auto number = [](long double v) {
    return std::isfinite(v) ? Tree(static_cast<double>(v)) : Tree(nullptr);
  };
  return {{"certified", p.certified},
          {"reason", p.reason},
          {"declined", optional_string(p.declined)},
          {"digits", p.digits},
          {"deep_relax_steps", p.deep_relaxed ? Tree(p.deep_relax.iterations) : Tree(nullptr)},
          {"deep_relax_d", p.deep_relaxed ? Tree(decimal17(p.deep_relax.d_end)) : Tree(nullptr)},
          {"bonds", id.found ? Tree(id.bonds.size()) : Tree(nullptr)},
          {"rattlers", id.found ? Tree(id.rattlers.size()) : Tree(nullptr)},
          {"contacts", p.contacts > 0 ? Tree(p.contacts) : Tree(nullptr)},
          {"next_gap", p.contacts > 0 ? number(p.next_gap) : Tree(nullptr)},
          {"candidates", id.candidates},
          {"dropped", id.dropped},
          {"implied", id.implied},
          {"smallest_gap", id.found ? number(p.smallest_gap) : Tree(nullptr)},
          {"gap_floor", id.found ? number(p.gap_floor) : Tree(nullptr)},
          {"min_force", c.stress.exists ? number(c.stress.min_force) : Tree(nullptr)},
          {"force_error", c.stress.exists ? number(c.force_error) : Tree(nullptr)},
          {"balance_residual", c.stress.exists ? number(c.stress.residual) : Tree(nullptr)},
          {"min_eigenvalue", id.found ? number(c.min_eigenvalue) : Tree(nullptr)},
          {"eigenvalue_error", id.found ? number(c.eigenvalue_error) : Tree(nullptr)},
          {"reference_open", p.reference_open >= 0 ? Tree(p.reference_open) : Tree(nullptr)},
          {"seconds", p.seconds}};
}

inline Tree certificate_tree(const Analysis& a) {
  long double smallest_gap = std::numeric_limits<long double>::infinity();
  for (const auto& g : a.gaps)
    if (!g.rattler) {
      smallest_gap = g.gap;
      break;
    }
  return {{"rigid", a.rigidity.rigid},
          {"smallest_gap",
           std::isfinite(smallest_gap) ? Tree(static_cast<double>(smallest_gap)) : Tree(nullptr)},
          {"multiprecision", precise_tree(a)},
          {"stress_exists", a.stress.exists},
          {"stress_strictly_positive", a.stress.strictly_positive},
          {"min_force", static_cast<double>(a.stress.min_force)},
          {"balance_residual", static_cast<double>(a.stress.residual)},
          {"certified", a.certified()},
          {"verdict", a.status()},
          {"relax_iterations", a.relax.iterations},
          {"relax_method", a.relax.interior || a.lps_skipped ? "interior point"
                           : a.relax.fast_path               ? "start certified"
                                                             : "linear programs"},
          {"lps_skipped", a.lps_skipped},
          {"interior_d", a.interior ? Tree(decimal17(a.interior->d_end)) : Tree(nullptr)}};
}

// An analysis as a packing-carrying object: d, the counts, the certificate.
inline Tree analysis_tree(const Analysis& a) {
  Tree j;
  j["d"] = decimal17(a.pattern.packing.d);
  add_counts(j, a.pattern);
  j["certificate"] = certificate_tree(a);
  return j;
}

inline Tree analysis_stage_seconds(const Analysis& a) {
  return {{"relax", a.times.relax},
          {"bonds", a.times.bonds},
          {"rigidity", a.times.rigidity},
          {"stress", a.times.stress},
          {"multiprecision", a.times.multiprecision},
          {"multiprecision_certificate", a.times.certificate_mp}};
}

// L and delta(n) = L - t(n) beside a d of `digits` significant digits. After an MPFR polish (L
// holds its digits), L to `digits` and delta in MPFR from that L, t(n) = (-3 + sqrt(8n+1))/2
// computed at its precision, to L's decimals: delta is known to L's absolute accuracy (so to one
// digit fewer than L where L >= 1 > delta). Else both from long double: L to min(digits, 18),
// delta to min(digits, 15) significant digits.
inline std::pair<std::string, std::string> L_and_delta(const PreciseReal& L, long long n,
                                                       int digits) {
  if (digits > kLongDoubleDigits && L.multiprecision()) {
    std::string text = L.str(digits);
    std::string delta = oler_delta_from_L(text, n);
    return {std::move(text), std::move(delta)};
  }
  return {format_significant(L.value(), std::min(digits, kLongDoubleDigits)),
          format_significant(oler_delta(n, L.value()), std::min(digits, 15))};
}

// Near contacts (non-bonds between held disks) are what a referee checks; rattlers' play apart.
inline void near_contacts(std::ostream& out, const Analysis& a) {
  std::string gaps;
  int shown = 0;
  const Gap* play = nullptr;
  for (const auto& g : a.gaps) {
    if (g.rattler) {
      if (!play) play = &g;
      continue;
    }
    if (shown++ >= 5) continue;
    const std::string where = g.contact.is_wall()
                                  ? fmt::format("{}-{}", g.contact.a, side_name(g.contact.side()))
                                  : fmt::format("{}-{}", g.contact.a, g.contact.b);
    gaps += fmt::format("{}{} {:.6Lg}", gaps.empty() ? "" : ", ", where, g.gap);
  }
  line(out, "near/d", gaps.empty() ? "-" : gaps);
  if (play) line(out, "play", fmt::format("smallest rattler gap {:.6Lg} d", play->gap));
}

inline std::string contact_name(const Bond& b) {
  return b.is_wall() ? fmt::format("{}-{}", b.a, side_name(b.side()))
                     : fmt::format("{}-{}", b.a, b.b);
}

// The multiprecision certificate (docs/certified.md): why it ran, the bonds it identified, and
// the margins it resolved, each beside the error it was measured against.
inline void precise_lines(std::ostream& out, const PreciseStage& p) {
  const auto& id = p.identification;
  line(out, "mp why", p.reason);
  if (p.deep_relaxed)
    line(out, "mp relax",
         fmt::format(
             "deep relax: {} LP steps to a gain below 1e-18, d {:.19Lg} -> {:.19Lg} ({:.3f} s)",
             p.deep_relax.iterations, p.deep_relax.d_start, p.deep_relax.d_end,
             p.deep_relax_seconds));
  line(out, "mp bonds",
       id.found ? fmt::format("{} digits: {} bonds, {} rattlers ({} candidates within 1e-6 d, {} "
                              "dropped, {} implied contacts added, {} polishes)",
                              p.digits, id.bonds.size(), id.rattlers.size(), id.candidates,
                              id.dropped, id.implied, id.polishes)
                : fmt::format("{} digits: none identified ({})", p.digits, id.failure));
  if (id.found) {
    const auto& c = p.certificate;
    line(out, "mp gap",
         std::isfinite(p.smallest_gap)
             ? fmt::format("smallest non-bond gap {:.6Lg} d ({}), precision floor {:.2Lg} d",
                           p.smallest_gap, contact_name(p.smallest_gap_contact), p.gap_floor)
             : fmt::format("no non-bond gap between held disks; precision floor {:.2Lg} d",
                           p.gap_floor));
    line(out, "mp rigid",
         c.eigenvalue_estimate > 0
             ? fmt::format("lambda_min(G^T G) >= {:.3Lg} (estimate {:.3Lg}, error {:.2Lg}){}",
                           c.min_eigenvalue, c.eigenvalue_estimate, c.eigenvalue_error,
                           c.rigid ? "" : ": not resolved")
             : c.declined);
    if (c.stress.exists)
      line(out, "mp stress",
           fmt::format("min force {:.6Lg} (pairs {:.6Lg}, walls {:.6Lg}), error <= {:.2Lg}, "
                       "balance residual {:.2Lg} ({}{}, {} sweeps)",
                       c.stress.min_force, c.stress.min_pair_force,
                       std::isfinite(c.stress.min_wall_force) ? c.stress.min_wall_force : 0.0L,
                       c.force_error, c.stress.residual, c.stress_start,
                       c.weighted ? ", weighted" : "", c.balance_sweeps));
  }
  line(out, "mp time",
       fmt::format("{:.3f} s{}", p.seconds,
                   p.attempts > 1 ? ", second attempt at twice the digits" : ""));
}

inline void analysis_lines(std::ostream& out, const Analysis& a, bool stage_times) {
  line(out, "analysis",
       fmt::format(
           "relax: {}; polish residual {:.2g}, {} candidates, {} rejected",
           a.relax.interior
               ? fmt::format("interior point, {} Newton steps, no LP (its result certified)",
                             a.relax.newton_steps)
           : a.lps_skipped
               ? fmt::format("interior point, {} Newton steps, no LP", a.relax.newton_steps)
           : a.relax.fast_path
               ? "no LP (the start certified as a strict local optimum)"
               : fmt::format("{} LP steps, {}", a.relax.iterations,
                             a.relax.converged ? "stationary" : "stopped at the trust floor"),
           static_cast<double>(a.identification.polish.max_residual), a.identification.candidates,
           a.identification.rejected));
  if (a.interior && !a.relax.interior)
    line(out, "interior",
         fmt::format("the interior-point relax reached d = {:.17Lg} ({} Newton steps{}), which did "
                     "not certify; {}",
                     a.interior->d_end, a.interior->newton_steps,
                     a.interior->converged ? "" : ", not converged",
                     a.lps_skipped ? "this is its result (no LPs above " +
                                         std::to_string(a.lp_limit) + " disks)"
                                   : "the LP relax decided"));
  line(out, "rigidity",
       a.lps_skipped && !a.fast.accepted
           ? "not decided: the LP-free certificate declined (" + a.fast.declined +
                 "); no LPs above " + std::to_string(a.lp_limit) + " disks"
       : a.rigidity.rigid
           ? fmt::format("jammed (no first-order motion of the non-rattlers); {}",
                         a.fast.accepted ? "LP-free certificate"
                                         : "LPs (fast path declined: " + a.fast.declined + ")")
           : fmt::format("NOT rigid: motion of {} disks opens {} bonds (LP {:.3g}, {:.3g})",
                         a.rigidity.moving_disks, a.rigidity.opening_bonds, a.rigidity.opening,
                         a.rigidity.floppy));
  if (a.stress.exists)
    line(out, "stress",
         fmt::format("min force {:.6Lg} (pairs {:.6Lg}, walls {:.6Lg}), balance residual {:.2Lg}",
                     a.stress.min_force, a.stress.min_pair_force,
                     std::isfinite(a.stress.min_wall_force) ? a.stress.min_wall_force : 0.0L,
                     a.stress.residual));
  else
    line(out, "stress", "none");
  line(out, "verdict", a.status());
  if (a.precise) precise_lines(out, *a.precise);
  near_contacts(out, a);
  if (a.multiprecision)
    line(out, "mpfr",
         fmt::format("{} digits: {} MPFR iterations, log10 residual {:.1f}{}",
                     a.multiprecision->digits, a.multiprecision->iterations,
                     a.multiprecision->log10_max_residual,
                     a.multiprecision->converged ? "" : " (NOT converged)"));
  if (stage_times)
    line(out, "time",
         fmt::format("relax {}, bonds+polish {}, rigidity {}, stress {}{}", ms(a.times.relax),
                     ms(a.times.bonds), ms(a.times.rigidity), ms(a.times.stress),
                     a.multiprecision ? ", mpfr " + ms(a.times.multiprecision) : ""));
}

}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<pipeline::FileAnalysis> {
  static Description describe(const pipeline::FileAnalysis& f, const DescribeOptions& o) {
    using namespace pipeline;
    using namespace results;
    const Analysis& a = f.analysis;
    const auto& pk = a.pattern.packing;
    const long long n = static_cast<long long>(pk.size());
    Tree j;
    j["file"] = f.file;
    j["layout"] = f.layout;
    if (!f.label.empty()) j["label"] = f.label;
    j["n"] = n;
    const int digits = std::max(f.digits, 17);
    j["d"] = f.d_string(digits);
    j["L"] = f.L_string(digits);
    j["delta"] = static_cast<double>(oler_delta(n, 1 / pk.d));
    j["convention"] = convention_name(f.convention);
    j["value_in_convention"] = f.value_string(digits);
    if (f.convention == Convention::Radius) j["r"] = f.value_string(digits);
    if (f.convention == Convention::UnitDiskSide) j["S"] = f.value_string(digits);
    j["d_start"] = decimal17(a.relax.d_start);
    add_counts(j, a.pattern);
    j["certificate"] = certificate_tree(a);
    j["warnings"] = f.warnings;
    j["seconds"] = f.seconds();
    j["stage_seconds"] = analysis_stage_seconds(a);
    j["stage_seconds"]["read"] = f.read_seconds;
    if (o.points) j["points"] = points_tree(pk);
    return {j,
            "",
            {"file",
             "layout",
             "label",
             "n",
             "d",
             "L",
             "delta",
             "convention",
             "value_in_convention",
             "r",
             "S",
             "d_start",
             "bonds",
             "rattlers",
             "rattler_indices",
             "certificate",
             "warnings",
             "seconds",
             "stage_seconds",
             "points"}};
  }

  static void text(std::ostream& out, const pipeline::FileAnalysis& f) {
    using namespace pipeline;
    using namespace results;
    const Analysis& a = f.analysis;
    const auto& pk = a.pattern.packing;
    const long long n = static_cast<long long>(pk.size());
    line(out, "file", fmt::format("{} ({})", f.file, f.layout));
    line(out, "n", std::to_string(n));
    line(out, "d",
         fmt::format("{} (start {})", f.d_string(f.digits),
                     format_significant(a.relax.d_start, 15)));
    if (f.convention != Convention::UnitTriangle)
      line(out, f.convention == Convention::Radius ? "r" : "S", f.value_string(f.digits));
    const auto& mp = a.multiprecision;
    const auto [L, delta] = L_and_delta(
        mp && mp->converged ? PreciseReal(1 / pk.d, mp->L, mp->digits) : PreciseReal(1 / pk.d), n,
        f.digits);
    line(out, "L", L);
    line(out, "delta(n)", delta);
    line(out, "bonds", std::to_string(a.pattern.bonds.size()));
    // The first 40 rattlers by index (--json lists them all in rattler_indices).
    const auto& rattlers = a.pattern.rattlers;
    const std::size_t shown = std::min<std::size_t>(rattlers.size(), 40);
    line(out, "rattlers",
         fmt::format("{}{}{}{}", rattlers.size(), rattlers.empty() ? "" : " : ",
                     fmt::join(rattlers.begin(), rattlers.begin() + static_cast<long>(shown), " "),
                     shown < rattlers.size() ? " ..." : ""));
    analysis_lines(out, a, true);
  }
};

}  // namespace tripack::report
