// Plain-text renderers: aligned "key value" lines and tables for people.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "polish/polish_mp.hpp"
#include "report/render.hpp"

namespace tripack::report {

using namespace pipeline;
using namespace jobs;
using namespace search;

namespace {

void line(std::ostream& out, std::string_view key, const std::string& value) {
  out << fmt::format("{:<10} {}\n", key, value);
}

// Rows of cells as columns, each column as wide as its widest cell (in characters, UTF-8
// aware), two spaces between columns, every line starting with `indent`: a long label or a d
// with more digits widens its column instead of shifting the rest of its row.
void aligned_rows(std::ostream& out, std::string_view indent,
                  const std::vector<std::vector<std::string>>& rows) {
  const auto width = [](const std::string& s) {
    return static_cast<std::size_t>(
        std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::vector<std::size_t> widths;
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], width(row[c]));
    }
  for (const auto& row : rows) {
    std::string text(indent);
    for (std::size_t c = 0; c < row.size(); ++c) {
      text += row[c];
      if (c + 1 < row.size()) text += std::string(widths[c] - width(row[c]) + 2, ' ');
    }
    out << text << "\n";
  }
}

// The table of distinct packings of billiards and search: label, d, bonds, rattlers, verdict and
// `found` (where each was found), aligned.
void packing_rows(std::ostream& out, const std::vector<PackingRecord>& packings,
                  const std::function<std::string(const PackingRecord&)>& found) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& x : packings)
    rows.push_back({x.label, "d = " + x.d.str(15), fmt::format("bonds {}", x.bonds()),
                    fmt::format("rattlers {}", x.rattlers()),
                    x.certified ? "certified" : "NOT certified", found(x)});
  aligned_rows(out, "  ", rows);
}

// L and delta(n) = L - t(n) beside a d of `digits` significant digits. After an MPFR polish (L
// holds its digits), L to `digits` and delta in MPFR from that L, t(n) = (-3 + sqrt(8n+1))/2
// computed at its precision, to L's decimals: delta is known to L's absolute accuracy (so to one
// digit fewer than L where L >= 1 > delta). Else both from long double: L to min(digits, 18),
// delta to min(digits, 15) significant digits.
std::pair<std::string, std::string> L_and_delta(const PreciseReal& L, long long n, int digits) {
  if (digits > kLongDoubleDigits && L.multiprecision()) {
    std::string text = L.str(digits);
    std::string delta = oler_delta_from_L(text, n);
    return {std::move(text), std::move(delta)};
  }
  return {format_significant(L.value(), std::min(digits, kLongDoubleDigits)),
          format_significant(oler_delta(n, L.value()), std::min(digits, 15))};
}

std::string count_vs(std::size_t got, const std::optional<long long>& expected) {
  if (!expected) return std::to_string(got);
  return fmt::format("{} (catalogue: {}{})", got, *expected,
                     static_cast<long long>(got) == *expected ? "" : ", MISMATCH");
}

std::string ms(double seconds) {
  return fmt::format("{:.3f} ms", seconds * 1e3);
}

// Near contacts (non-bonds between held disks) are what a referee checks; rattlers' play apart.
void near_contacts(std::ostream& out, const Analysis& a) {
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

std::string contact_name(const Bond& b) {
  return b.is_wall() ? fmt::format("{}-{}", b.a, side_name(b.side()))
                     : fmt::format("{}-{}", b.a, b.b);
}

// The multiprecision certificate (docs/certified.md): why it ran, the bonds it identified, and
// the margins it resolved, each beside the error it was measured against.
void precise_lines(std::ostream& out, const PreciseStage& p) {
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

void analysis_lines(std::ostream& out, const Analysis& a, bool stage_times) {
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

void build_lines(std::ostream& out, const BuildResult& b) {
  const long long n = static_cast<long long>(b.pattern.packing.size());
  const auto [L, delta] = L_and_delta(b.record.L, n, b.digits);
  line(out, "class", member_name(b.pattern.provenance));
  line(out, "n", std::to_string(n));
  line(out, "d", b.d_string(b.digits));
  line(out, "L", L);
  line(out, "delta(n)", delta);
  // The build's result (the certified geometry's where certified), as the catalogue counts it.
  line(out, "bonds", count_vs(b.record.pattern.bonds.size(), b.bonds_expected));
  line(out, "rattlers", count_vs(b.record.pattern.rattlers.size(), b.rattlers_expected));
  if (b.polished) {
    const std::string rank = b.polish.rank < 0
                                 ? std::string("not needed")
                                 : fmt::format("{}/{}", b.polish.rank, b.polish.unknowns);
    line(out, "polish",
         fmt::format("max residual {:.2g} (disk units), {} iterations, {} equations, rank {}",
                     static_cast<double>(b.polish.max_residual), b.polish.iterations,
                     b.polish.equations, rank));
  }
  if (b.exact)
    line(out, "exact",
         fmt::format("{} ({} bonds exactly at d, {} gaps exactly positive, in Q(sqrt3))",
                     b.exact->ok ? "verified" : "FAILED: " + b.exact->failure,
                     b.exact->bonds_checked, b.exact->gaps_checked));
  if (b.analysis) {
    const auto& precise = b.analysis->precise;
    if (precise && precise->certified) {
      const auto& geometry = b.analysis->pattern.bonds;
      std::size_t beyond = 0;  // contacts of the certified configuration the builder did not list
      for (const Bond& g : geometry)
        beyond += !std::binary_search(b.pattern.bonds.begin(), b.pattern.bonds.end(), g);
      line(out, "certify",
           fmt::format("bonds from geometry (multiprecision, {} digits) {}: {} of the builder's "
                       "{} open, {} contacts beyond its list; rattlers {}",
                       precise->digits,
                       b.bonds_match() ? "equal the builder's" : "trusted over the builder's",
                       precise->reference_open, b.pattern.bonds.size(), beyond,
                       b.rattlers_match() ? "equal" : "DIFFER"));
    } else
      line(out, "certify",
           fmt::format("bonds from geometry {} the builder's, rattlers {}",
                       b.bonds_match() ? "equal" : "DIFFER from",
                       b.rattlers_match() ? "equal" : "DIFFER"));
    analysis_lines(out, *b.analysis, false);
  } else if (b.certify_skipped) {
    line(out, "certify",
         "skipped: it certifies the polished bond system, and --no-polish was given");
  } else if (!b.certify_error.empty()) {
    line(out, "certify", "FAILED: " + b.certify_error + " (the packing is built, not certified)");
  }
  if (b.multiprecision)
    line(out, "mpfr",
         fmt::format("{} digits: {} MPFR iterations{}", b.multiprecision->digits,
                     b.multiprecision->iterations,
                     b.multiprecision->converged ? "" : " (NOT converged)"));
  const auto* a = b.analysis ? &*b.analysis : nullptr;
  std::string times =
      fmt::format("construct {}, polish {}", ms(b.times.construct), ms(b.polish_seconds));
  if (b.exact) times += ", exact " + ms(b.times.exact);
  if (a)
    times += fmt::format(", relax {}, bonds {}, certify {}", ms(a->times.relax), ms(a->times.bonds),
                         ms(a->times.rigidity + a->times.stress));
  if (a && a->multiprecision) times += ", mpfr " + ms(a->times.multiprecision);
  if (b.multiprecision) times += ", mpfr " + ms(b.times.multiprecision);
  line(out, "time", times);
}

void billiards_lines(std::ostream& out, const BilliardsSearchResult& r) {
  out << fmt::format("{:>6} {:>12} {:>12} {:>9} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n", "seed",
                     "events", "collisions", "seconds", "d (billiards)", "d (polished)", "bonds",
                     "ratt", "certified", "packing");
  for (const auto& run : r.runs) {
    if (!run.error.empty()) {
      out << fmt::format("{:>6} error: {}\n", run.seed, run.error);
      continue;
    }
    const auto* a = run.analysis ? &*run.analysis : nullptr;
    out << fmt::format("{:>6} {:>12} {:>12} {:>9.3f} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n",
                       run.seed, run.sim.events, run.sim.collisions, run.sim.seconds,
                       format_significant(run.sim.packing.d, 15),
                       a ? format_significant(a->pattern.packing.d, 15) : "-",
                       a ? std::to_string(a->pattern.bonds.size()) : "-",
                       a ? std::to_string(a->pattern.rattlers.size()) : "-",
                       a ? (a->certified() ? "yes" : "no") : "-", run.label);
  }
  if (const auto effects = describe_effects(r.scene); !effects.empty())
    out << fmt::format("effects: {}\n", fmt::join(effects, "; "));
  if (r.scene.shake) {
    out << fmt::format(
        "shaking at fixed size ({} collisions per disk): rattlers = disks colliding {}x less "
        "often than the median\n",
        r.scene.shake->per_disk, r.scene.shake->rattler_factor);
    for (const auto& run : r.runs)
      if (run.error.empty())
        out << fmt::format(
            "{:>6} shake: {} collisions in {:.3f} s, rattlers [{}]{}\n", run.seed,
            run.sim.shake_collisions, run.sim.shake_seconds, fmt::join(run.sim.shake_rattlers, " "),
            run.analysis ? fmt::format("; analysis rattlers [{}]",
                                       fmt::join(run.analysis->pattern.rattlers, " "))
                         : "");
  }
  const std::size_t ran = r.runs.size();
  if (ran < static_cast<std::size_t>(r.runs_asked))
    out << fmt::format("distinct packings ({} of {} runs: interrupted, {:.2f} s):\n", ran,
                       r.runs_asked, r.seconds);
  else
    out << fmt::format("distinct packings ({} runs, {:.2f} s):\n", ran, r.seconds);
  packing_rows(out, r.packings, [&](const PackingRecord& x) {
    return fmt::format("({} of {} runs, first seed {})", x.runs(), ran, x.first_seed());
  });
}

}  // namespace

void render_text(std::ostream& out, const Catalogue& catalogue, const RenderOptions&) {
  out << fmt::format("{:<20} {:<42} {:<8} {:<28} {}\n", "id", "n", "k", "L", "claim");
  for (const auto& c : catalogue.classes()) {
    std::string k_range =
        (c.has_p ? "p>=" + std::to_string(c.p_min) + "," : "") + "k>=" + std::to_string(c.k_min);
    if (c.k_max) k_range = std::to_string(c.k_min) + ".." + std::to_string(c.k_max);
    std::string claim = c.claim_status;
    if (!c.claim_best.empty() && c.claim_best != "true") claim += ", best " + c.claim_best;
    out << fmt::format("{:<20} {:<42} {:<8} {:<28} {}\n", c.id, c.display, k_range,
                       c.L.empty() ? "(contact system)" : c.L.text(), claim);
    if (!c.variants.empty()) {
      std::string variants;
      for (const auto& v : c.variants) variants += (variants.empty() ? "" : ", ") + v.id;
      out << fmt::format("{:<20}   variants: {}\n", "", variants);
    }
  }
}

void render_text(std::ostream& out, const Classification& c, const RenderOptions&) {
  for (const auto& m : c.members)
    out << m.cls->id << (m.cls->has_p ? " p=" + std::to_string(m.p) : "") << " k=" << m.k << "   ("
        << m.cls->display << ")\n";
}

void render_text(std::ostream& out, const BestBuild& b, const RenderOptions&) {
  for (const auto& c : b.candidates)
    line(out, "candidate",
         c.error.empty()
             ? fmt::format("{:<40} d = {}", member_name(c.member), format_significant(c.d, 15))
             : fmt::format("{:<40} not built: {}", member_name(c.member), c.error));
  build_lines(out, b.best);
}

void render_text(std::ostream& out, const FormulaCheck& c, const RenderOptions&) {
  out << fmt::format("{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}\n", "k", "n", "variant",
                     "d built", "d formula", "rel.diff", "bonds", "source");
  for (const auto& r : c.rows) {
    // Closed forms are also checked exactly: every bond exactly at d, every gap exactly > 0.
    const std::string exact_note = r.exact_ok ? (*r.exact_ok ? "; exact in Q(sqrt3): ok"
                                                             : "; exact: FAILED " + r.exact_failure)
                                              : "";
    out << fmt::format(
        "{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}{}\n", r.k, r.n, r.variant,
        format_significant(r.d_built, 17), r.d_formula ? format_significant(*r.d_formula, 17) : "-",
        r.d_formula ? fmt::format("{:.2e}", static_cast<double>(r.relative_difference)) : "-",
        count_vs(r.bonds, r.bonds_expected),
        (r.d_formula ? r.source : "no formula for L in the catalogue") + exact_note,
        r.ok ? "" : "  FAIL");
  }
}

void render_text(std::ostream& out, const CatalogueTable& t, const RenderOptions&) {
  out << fmt::format(
      "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9} {:>5} {:>4} {:>6} {:>9} {:>8}\n", "class",
      "p", "k", "variant", "n", "d", "L", "delta", "bonds", "ratt", "match", "certified", "ms");
  for (const auto& r : t.rows)
    out << fmt::format(
        "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9.6f} {:>5} {:>4} {:>6} {:>9} "
        "{:>8.2f}{}\n",
        r.member.class_id, r.member.p ? std::to_string(r.member.p) : "", r.member.k,
        r.member.variant, r.n, format_significant(r.d, 15), format_significant(1 / r.d, 15),
        static_cast<double>(oler_delta(r.n, 1 / r.d)), r.bonds, r.rattlers,
        r.geometry_match ? "yes" : "NO", r.certified ? (r.exact_ok ? "yes+exact" : "yes") : "NO",
        r.seconds * 1e3, r.counts_match ? "" : "  bond count differs from the catalogue");
  out << "match: bonds and rattlers found from the geometry alone equal the builder's; "
         "certified: rigid (LP) with a strictly positive stress; exact: every bond and gap "
         "verified in Q(sqrt3).\n";
}

void render_text(std::ostream& out, const FileAnalysis& f, const RenderOptions&) {
  const Analysis& a = f.analysis;
  const auto& pk = a.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  line(out, "file", fmt::format("{} ({})", f.file, f.layout));
  line(out, "n", std::to_string(n));
  line(out, "d",
       fmt::format("{} (start {})", f.d_string(f.digits), format_significant(a.relax.d_start, 15)));
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

void render_text(std::ostream& out, const BilliardsSearchResult& r, const RenderOptions&) {
  billiards_lines(out, r);
}

void render_text(std::ostream& out, const SearchResult& r, const RenderOptions&) {
  out << fmt::format("search n = {} ({}, seed {}, {} chain{}): {} steps in {:.2f} s{}\n",
                     r.request.n, method_name(r.request.method), r.request.seed, r.request.threads,
                     r.request.threads == 1 ? "" : "s", r.steps(), r.seconds,
                     r.cancelled ? " (interrupted)" : "");
  if (r.builder)
    out << (r.builder->member.empty()
                ? fmt::format("started from no builder: {}\n", r.builder->error)
                : fmt::format("started from {} (d = {}, {}; {} candidate{}) built in {:.2f} s "
                              "({:.2f} CPU s)\n",
                              r.builder->member, r.builder->d,
                              r.builder->certified ? "certified" : "NOT certified",
                              r.builder->candidates, r.builder->candidates == 1 ? "" : "s",
                              r.builder->seconds, r.builder->cpu_seconds));
  if (r.packings.empty()) {
    out << "no certified packing found\n";
    return;
  }
  const auto& best = r.packings.front();
  out << fmt::format(
      "best: {} d = {}  bonds {}  rattlers {}  {}; first reached after {:.3f} s "
      "({:.3f} CPU s)\n",
      best.label, best.d.str(kLongDoubleDigits), best.bonds(), best.rattlers(),
      best.certified ? "certified" : "NOT certified", r.seconds_to_best, r.cpu_seconds_to_best);
  if (r.request.target)
    for (const auto& c : r.chains)
      out << fmt::format(
          "chain {}: target {} {}\n", c.seed, format_significant(*r.request.target, 18),
          c.target_reached ? fmt::format("reached after {:.3f} CPU s", c.cpu_seconds_to_target)
                           : "not reached");
  for (const auto& c : r.chains)
    if (c.base_n > 0)
      out << fmt::format("chain {}: {} of its {} steps searched n = {} (best d = {}) to inflate\n",
                         c.seed, c.base_steps, c.steps, c.base_n,
                         c.base_best_d.empty() ? "none" : c.base_best_d);
  out << fmt::format("distinct packings ({}):\n", r.packings.size());
  packing_rows(out, r.packings, [&](const PackingRecord& x) {
    return fmt::format("({} of {} chains)", x.runs(), r.chains.size());
  });
}

void render_text(std::ostream& out, const ConstructedVsBilliards& c, const RenderOptions&) {
  billiards_lines(out, c.billiards);
  if (c.constructed) {
    out << "constructed:\n";
    build_lines(out, c.constructed->best);
  } else {
    out << fmt::format("constructed: no class of the catalogue contains n = {}\n", c.n);
  }
  if (!c.comparison) {
    out << "comparison: -\n";
    return;
  }
  const auto& best = c.billiards.packings.front();
  line(out, "compare",
       fmt::format("{} vs {}: d relative difference {:.3g}; {}", best.label,
                   member_name(c.constructed->best.pattern.provenance),
                   static_cast<double>(c.d_relative_difference),
                   c.comparison->same ? "the same packing (" + c.comparison->reason + ")"
                                      : "different: " + c.comparison->reason));
}

}  // namespace tripack::report
