#include "app/commands.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <thread>

#include "analysis/compare.hpp"
#include "analysis/exact_check.hpp"
#include "analysis/polish.hpp"
#include "analysis/polish_mp.hpp"
#include "app/pipeline.hpp"
#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "core/conventions.hpp"
#include "core/io.hpp"
#include "sim/billiards.hpp"
#include "sim/scene.hpp"

namespace tripack::app {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

Catalogue load_catalogue(const GlobalOptions& g) {
  return Catalogue::load(g.catalogue.empty() ? Catalogue::default_path() : g.catalogue);
}

// The whole pipeline on a class member: construct, polish the builder's bond system, verify
// closed forms exactly, then certify from the geometry alone (relax, bonds, rattlers, rigidity,
// stress) and compare with what the builder intended.
struct Built {
  Pattern pattern;  // as constructed, polished with the builder's bonds
  PolishReport polish;
  bool polished = false;
  std::optional<ExactCheckReport> exact;
  std::optional<Analysis> analysis;
  std::optional<MultiprecisionPolish> multiprecision;  // of the builder's bond system
  StageTimes times;
  double t_polish = 0;
  std::optional<long long> bonds_expected, rattlers_expected;
  bool certify_skipped = false;
  bool bonds_match() const { return analysis && analysis->pattern.bonds == pattern.bonds; }
  bool rattlers_match() const { return analysis && analysis->pattern.rattlers == pattern.rattlers; }
  std::string d_string(int digits) const {
    if (multiprecision && multiprecision->converged) return multiprecision->d;
    if (analysis && digits > 18) return analysis->d_string(digits);
    return format_significant(pattern.packing.d, std::min(digits, 18));
  }
};

Built run_build(const Catalogue& cat, const BuildRequest& req, const BuildOptions& o) {
  Built b;
  auto t0 = Clock::now();
  b.pattern = build_pattern(cat, req);
  b.times.construct = seconds_since(t0);
  if (o.polish) {
    t0 = Clock::now();
    b.polish = polish_bond_system(b.pattern.packing, b.pattern.bonds, b.pattern.rattlers);
    b.t_polish = seconds_since(t0);
    b.polished = true;
    if (!b.polish.converged)
      throw std::runtime_error(
          fmt::format("polish did not converge (residual {:.3g} after {} iterations)",
                      static_cast<double>(b.polish.max_residual), b.polish.iterations));
  }
  if (b.pattern.exact) {
    t0 = Clock::now();
    b.exact = exact_check(b.pattern);
    b.times.exact = seconds_since(t0);
  }
  const bool certify = o.certify && o.polish && b.pattern.packing.size() <= kCertifyLimit;
  b.certify_skipped = o.certify && !certify;
  if (certify) {
    b.analysis = analyze_packing(b.pattern.packing, {o.digits});
  } else if (o.digits > 18) {
    t0 = Clock::now();
    b.multiprecision =
        polish_multiprecision(b.pattern.packing, b.pattern.bonds, b.pattern.rattlers, o.digits);
    b.times.multiprecision = seconds_since(t0);
  }
  const auto& c = cat.find(b.pattern.provenance.class_id);
  const auto& pv = b.pattern.provenance;
  b.bonds_expected = c.rigid ? cat.bonds_of(c, pv.k, pv.p, pv.variant) : std::nullopt;
  b.rattlers_expected = cat.rattlers_of(c, pv.k, pv.p, pv.variant);
  return b;
}

std::string member_name(const Provenance& pv) {
  std::string s = pv.class_id + " k=" + std::to_string(pv.k);
  if (pv.p) s += " p=" + std::to_string(pv.p);
  if (!pv.variant.empty()) s += " variant=" + pv.variant;
  return s;
}

std::string count_vs(std::size_t got, const std::optional<long long>& expected) {
  if (!expected) return std::to_string(got);
  return fmt::format("{} (catalogue: {}{})", got, *expected,
                     static_cast<long long>(got) == *expected ? "" : ", MISMATCH");
}

void print_analysis(const Analysis& a, bool show_stage_times) {
  std::cout << fmt::format(
      "{:<10} relax: {} LP steps, {}; polish residual {:.2g}, {} candidates, {} rejected\n",
      "analysis", a.relax.iterations,
      a.relax.converged ? "stationary" : "stopped at the trust floor",
      static_cast<double>(a.identification.polish.max_residual), a.identification.candidates,
      a.identification.rejected);
  std::cout << fmt::format(
      "{:<10} {}\n", "rigidity",
      a.rigidity.rigid
          ? "jammed (no first-order motion of the non-rattlers)"
          : fmt::format("NOT rigid: motion of {} disks opens {} bonds (LP {:.3g}, {:.3g})",
                        a.rigidity.moving_disks, a.rigidity.opening_bonds, a.rigidity.opening,
                        a.rigidity.floppy));
  if (a.stress.exists)
    std::cout << fmt::format(
        "{:<10} min force {:.6Lg} (pairs {:.6Lg}, walls {:.6Lg}), balance residual {:.2Lg}\n",
        "stress", a.stress.min_force, a.stress.min_pair_force,
        std::isfinite(a.stress.min_wall_force) ? a.stress.min_wall_force : 0.0L, a.stress.residual);
  else
    std::cout << fmt::format("{:<10} none\n", "stress");
  std::cout << fmt::format("{:<10} {}\n", "verdict", a.status());
  // Near contacts (non-bonds between held disks) are what a referee checks; rattlers' play apart.
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
  std::cout << fmt::format("{:<10} {}\n", "near/d", gaps.empty() ? "-" : gaps);
  if (play) std::cout << fmt::format("{:<10} smallest rattler gap {:.6Lg} d\n", "play", play->gap);
  if (a.multiprecision)
    std::cout << fmt::format("{:<10} {} digits: {} MPFR iterations, log10 residual {:.1f}{}\n",
                             "mpfr", a.multiprecision->digits, a.multiprecision->iterations,
                             a.multiprecision->log10_max_residual,
                             a.multiprecision->converged ? "" : " (NOT converged)");
  if (show_stage_times)
    std::cout << fmt::format(
        "{:<10} relax {:.3f} ms, bonds+polish {:.3f} ms, rigidity {:.3f} ms, stress {:.3f} ms{}\n",
        "time", a.times.relax * 1e3, a.times.bonds * 1e3, a.times.rigidity * 1e3,
        a.times.stress * 1e3,
        a.multiprecision ? fmt::format(", mpfr {:.3f} ms", a.times.multiprecision * 1e3) : "");
}

void print_build(const Built& b, int digits) {
  const auto& pk = b.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  const long double L = 1.0L / pk.d;
  std::cout << fmt::format("{:<10} {}\n", "class", member_name(b.pattern.provenance));
  std::cout << fmt::format("{:<10} {}\n", "n", n);
  std::cout << fmt::format("{:<10} {}\n", "d", b.d_string(digits));
  std::cout << fmt::format("{:<10} {}\n", "L", format_significant(L, std::min(digits, 18)));
  std::cout << fmt::format("{:<10} {}\n", "delta(n)", format_significant(oler_delta(n, L), 15));
  std::cout << fmt::format("{:<10} {}\n", "bonds",
                           count_vs(b.pattern.bonds.size(), b.bonds_expected));
  std::cout << fmt::format("{:<10} {}\n", "rattlers",
                           count_vs(b.pattern.rattlers.size(), b.rattlers_expected));
  if (b.polished) {
    const std::string rank = b.polish.rank < 0
                                 ? std::string("not needed")
                                 : fmt::format("{}/{}", b.polish.rank, b.polish.unknowns);
    std::cout << fmt::format(
        "{:<10} max residual {:.2g} (disk units), {} iterations, {} equations, rank {}\n", "polish",
        static_cast<double>(b.polish.max_residual), b.polish.iterations, b.polish.equations, rank);
  }
  if (b.exact)
    std::cout << fmt::format(
        "{:<10} {} ({} bonds exactly at d, {} gaps exactly positive, in Q(sqrt3))\n", "exact",
        b.exact->ok ? "verified" : "FAILED: " + b.exact->failure, b.exact->bonds_checked,
        b.exact->gaps_checked);
  if (b.analysis) {
    std::cout << fmt::format("{:<10} bonds from geometry {} the builder's, rattlers {}\n",
                             "certify", b.bonds_match() ? "equal" : "DIFFER from",
                             b.rattlers_match() ? "equal" : "DIFFER");
    print_analysis(*b.analysis, false);
  } else if (b.certify_skipped) {
    std::cout << fmt::format(
        "{:<10} skipped for n > {} (LP certification; use --no-certify to silence)\n", "certify",
        kCertifyLimit);
  }
  if (b.multiprecision)
    std::cout << fmt::format("{:<10} {} digits: {} MPFR iterations{}\n", "mpfr",
                             b.multiprecision->digits, b.multiprecision->iterations,
                             b.multiprecision->converged ? "" : " (NOT converged)");
  const auto* a = b.analysis ? &*b.analysis : nullptr;
  std::cout << fmt::format(
      "{:<10} construct {:.3f} ms, polish {:.3f} ms{}{}{}\n", "time", b.times.construct * 1e3,
      b.t_polish * 1e3, b.exact ? fmt::format(", exact {:.3f} ms", b.times.exact * 1e3) : "",
      a ? fmt::format(", relax {:.3f} ms, bonds {:.3f} ms, certify {:.3f} ms", a->times.relax * 1e3,
                      a->times.bonds * 1e3, (a->times.rigidity + a->times.stress) * 1e3)
        : "",
      a && a->multiprecision ? fmt::format(", mpfr {:.3f} ms", a->times.multiprecision * 1e3)
      : b.multiprecision     ? fmt::format(", mpfr {:.3f} ms", b.times.multiprecision * 1e3)
                             : "");
}

nlohmann::json certificate_json(const Analysis& a) {
  return {{"rigid", a.rigidity.rigid},
          {"stress_exists", a.stress.exists},
          {"stress_strictly_positive", a.stress.strictly_positive},
          {"min_force", static_cast<double>(a.stress.min_force)},
          {"balance_residual", static_cast<double>(a.stress.residual)},
          {"certified", a.certified()},
          {"verdict", a.status()},
          {"bonds", a.pattern.bonds.size()},
          {"rattlers", a.pattern.rattlers},
          {"relax_iterations", a.relax.iterations}};
}

nlohmann::json build_json(const Built& b, int digits) {
  const auto& pk = b.pattern.packing;
  const auto& pv = b.pattern.provenance;
  const long long n = static_cast<long long>(pk.size());
  const long double L = 1.0L / pk.d;
  nlohmann::json j;
  j["class"] = pv.class_id;
  j["k"] = pv.k;
  j["p"] = pv.p ? nlohmann::json(pv.p) : nlohmann::json(nullptr);
  j["variant"] = pv.variant.empty() ? nlohmann::json(nullptr) : nlohmann::json(pv.variant);
  j["n"] = n;
  j["d"] = digits > 18 ? b.d_string(digits) : format_significant(pk.d, 17);
  j["L"] = format_significant(L, 17);
  j["delta"] = static_cast<double>(oler_delta(n, L));
  j["bonds"] = b.pattern.bonds.size();
  j["rattlers"] = b.pattern.rattlers.size();
  const auto* a = b.analysis ? &*b.analysis : nullptr;
  j["seconds"] = b.times.construct + b.t_polish + b.times.exact + b.times.multiprecision +
                 (a ? a->times.total() : 0.0);
  j["stage_seconds"] = {
      {"construct", b.times.construct}, {"polish", b.t_polish}, {"exact", b.times.exact}};
  if (a) {
    j["stage_seconds"]["relax"] = a->times.relax;
    j["stage_seconds"]["bonds"] = a->times.bonds;
    j["stage_seconds"]["rigidity"] = a->times.rigidity;
    j["stage_seconds"]["stress"] = a->times.stress;
    j["stage_seconds"]["multiprecision"] = a->times.multiprecision;
    j["certificate"] = certificate_json(*a);
    j["certificate"]["bonds_match_builder"] = b.bonds_match();
    j["certificate"]["rattlers_match_builder"] = b.rattlers_match();
  }
  if (b.exact) j["exact_check"] = b.exact->ok;
  if (b.polished) j["polish_residual"] = static_cast<double>(b.polish.max_residual);
  return j;
}

std::pair<long, long> parse_range(const std::string& s) {
  auto to_long = [&](const std::string& t) {
    std::size_t used = 0;
    long v = 0;
    try {
      v = std::stol(t, &used);
    } catch (...) {
      used = 0;
    }
    if (used == 0 || used != t.size())
      throw std::invalid_argument("--k expects K or A..B, got '" + s + "'");
    return v;
  };
  const auto dots = s.find("..");
  if (dots == std::string::npos) {
    const long k = to_long(s);
    return {k, k};
  }
  const long a = to_long(s.substr(0, dots)), b = to_long(s.substr(dots + 2));
  if (b < a) throw std::invalid_argument("--k range " + s + " is empty");
  return {a, b};
}

}  // namespace

int cmd_classes(const GlobalOptions& g, bool json) {
  const Catalogue cat = load_catalogue(g);
  if (json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& c : cat.classes()) {
      nlohmann::json j{{"id", c.id},
                       {"display", c.display},
                       {"n", c.n.text()},
                       {"k_min", c.k_min},
                       {"builder", c.builder}};
      if (c.k_max) j["k_max"] = c.k_max;
      if (c.has_p) j["p_min"] = c.p_min;
      if (!c.L.empty()) j["L"] = c.L.text();
      if (!c.bonds.empty()) j["bonds"] = c.bonds.text();
      if (!c.rattlers.empty()) j["rattlers"] = c.rattlers.text();
      nlohmann::json vs = nlohmann::json::array();
      for (const auto& v : c.variants) vs.push_back(v.id);
      j["variants"] = vs;
      j["claim"] = {{"status", c.claim_status},
                    {"best", c.claim_best},
                    {"tight", c.claim_tight},
                    {"source", c.claim_source}};
      arr.push_back(j);
    }
    std::cout << arr.dump(1) << "\n";
    return 0;
  }
  std::cout << fmt::format("{:<20} {:<42} {:<8} {:<28} {}\n", "id", "n", "k", "L", "claim");
  for (const auto& c : cat.classes()) {
    std::string kr =
        (c.has_p ? "p>=" + std::to_string(c.p_min) + "," : "") + "k>=" + std::to_string(c.k_min);
    if (c.k_max) kr = std::to_string(c.k_min) + ".." + std::to_string(c.k_max);
    std::string claim = c.claim_status;
    if (!c.claim_best.empty() && c.claim_best != "true") claim += ", best " + c.claim_best;
    std::cout << fmt::format("{:<20} {:<42} {:<8} {:<28} {}\n", c.id, c.display, kr,
                             c.L.empty() ? "(contact system)" : c.L.text(), claim);
    if (!c.variants.empty()) {
      std::string vs;
      for (const auto& v : c.variants) vs += (vs.empty() ? "" : ", ") + v.id;
      std::cout << fmt::format("{:<20}   variants: {}\n", "", vs);
    }
  }
  return 0;
}

int cmd_classify(const GlobalOptions& g, long long n, bool json) {
  const Catalogue cat = load_catalogue(g);
  const auto members = cat.classify(n);
  if (members.empty())
    throw std::runtime_error("no class of the catalogue contains n = " + std::to_string(n));
  if (json) {
    nlohmann::json arr = nlohmann::json::array();
    for (const auto& m : members) {
      nlohmann::json j{{"class", m.cls->id}, {"k", m.k}};
      if (m.cls->has_p) j["p"] = m.p;
      arr.push_back(j);
    }
    std::cout << arr.dump() << "\n";
    return 0;
  }
  for (const auto& m : members) {
    std::cout << m.cls->id;
    if (m.cls->has_p) std::cout << " p=" << m.p;
    std::cout << " k=" << m.k << "   (" << m.cls->display << ")\n";
  }
  return 0;
}

int cmd_build(const GlobalOptions& g, const BuildOptions& o) {
  const Catalogue cat = load_catalogue(g);
  Built best;
  if (o.n) {
    if (!o.class_id.empty() || o.k != kUnsetK || o.p)
      throw std::invalid_argument("build --n N takes no class, --k or --p");
    const auto members = cat.classify(o.n);
    if (members.empty())
      throw std::runtime_error("no class of the catalogue contains n = " + std::to_string(o.n));
    bool have = false;
    for (const auto& m : members) {
      BuildOptions quick = o;
      quick.certify = false;  // rank the candidates first, certify only the winner
      quick.digits = 15;
      Built b = run_build(cat, {m.cls->id, m.k, m.p, ""}, quick);
      if (!o.json)
        std::cerr << fmt::format("candidate {:<40} d = {}\n", member_name(b.pattern.provenance),
                                 format_significant(b.pattern.packing.d, 15));
      if (!have || b.pattern.packing.d > best.pattern.packing.d) {
        best = std::move(b);
        have = true;
      }
    }
    const Provenance win = best.pattern.provenance;
    best = run_build(cat, {win.class_id, win.k, win.p, win.variant}, o);
  } else {
    if (o.class_id.empty()) throw std::invalid_argument("build needs a class (or --n N)");
    if (o.k == kUnsetK) throw std::invalid_argument("build needs --k K");
    best = run_build(cat, {o.class_id, o.k, o.p, o.variant}, o);
  }
  if (!o.output.empty()) write_pattern(o.output, best.pattern);
  if (o.json)
    std::cout << build_json(best, o.digits).dump() << "\n";
  else
    print_build(best, o.digits);
  return 0;
}

int cmd_check_formula(const GlobalOptions& g, const CheckFormulaOptions& o) {
  const Catalogue cat = load_catalogue(g);
  const ClassInfo& c = cat.find(o.class_id);
  const auto [k0, k1] = parse_range(o.k_range);
  // A double-rounded closed form and a polished bond system agree to a few ulps of L; 1e-14
  // relative leaves room for the long double chain functions and rounding of d.
  constexpr long double kTol = 1e-14L;
  bool all_ok = true;
  if (!o.json)
    std::cout << fmt::format("{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}\n", "k", "n",
                             "variant", "d built", "d formula", "rel.diff", "bonds", "source");
  for (long k = k0; k <= k1; ++k) {
    cat.check_parameters(c, k, o.p);
    std::vector<std::string> variants = cat.variants_at(c, k);
    if (variants.empty()) variants.push_back("");
    for (const auto& v : variants) {
      BuildOptions bo;
      bo.certify = false;
      const Built b = run_build(cat, {c.id, k, o.p, v}, bo);
      const Expression* exact = cat.exact_L_of(c, k, o.p);
      std::optional<long double> L;
      std::string source;
      if (exact) {
        L = exact->eval<long double>(real_env(k, o.p));
        source = "closed form " + exact->text();
      } else if (auto lf = cat.L_of(c, k, o.p)) {
        L = lf;
        source = "chain formula " + c.L.text();
      }
      const long double d = b.pattern.packing.d;
      const long double rel = L ? std::fabs(d * *L - 1) : NAN;
      const bool bonds_ok =
          !b.bonds_expected || static_cast<long long>(b.pattern.bonds.size()) == *b.bonds_expected;
      const bool exact_ok = !b.exact || b.exact->ok;
      const bool ok = (!L || rel <= kTol) && bonds_ok && exact_ok;
      all_ok = all_ok && ok;
      // Closed forms are also checked exactly: every bond exactly at d, every gap exactly > 0.
      const std::string exact_note = b.exact ? (b.exact->ok ? "; exact in Q(sqrt3): ok"
                                                            : "; exact: FAILED " + b.exact->failure)
                                             : "";
      if (o.json) {
        nlohmann::json j{{"class", c.id},
                         {"k", k},
                         {"n", b.pattern.packing.size()},
                         {"d_built", format_significant(d, 17)},
                         {"d_formula", L ? format_significant(1 / *L, 17) : ""},
                         {"relative_difference", L ? static_cast<double>(rel) : -1.0},
                         {"bonds", b.pattern.bonds.size()},
                         {"ok", ok},
                         {"source", source}};
        if (b.exact) j["exact_check"] = b.exact->ok;
        if (o.p) j["p"] = o.p;
        if (!v.empty()) j["variant"] = v;
        std::cout << j.dump() << "\n";
      } else {
        std::cout << fmt::format(
            "{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}{}\n", k, b.pattern.packing.size(), v,
            format_significant(d, 17), L ? format_significant(1 / *L, 17) : "-",
            L ? fmt::format("{:.2e}", static_cast<double>(rel)) : "-",
            count_vs(b.pattern.bonds.size(), b.bonds_expected),
            (L ? source : "no formula for L in the catalogue") + exact_note, ok ? "" : "  FAIL");
      }
    }
  }
  if (!all_ok) {
    std::cerr << "tripack: error: check-formula found mismatches\n";
    return 1;
  }
  return 0;
}

int cmd_table(const GlobalOptions& g, long k_max) {
  const Catalogue cat = load_catalogue(g);
  std::cout << fmt::format(
      "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9} {:>5} {:>4} {:>6} {:>9} {:>8}\n", "class",
      "p", "k", "variant", "n", "d", "L", "delta", "bonds", "ratt", "match", "certified", "ms");
  bool all_ok = true;
  for (const auto& c : cat.classes()) {
    const long p_count = c.has_p ? 3 : 1;
    for (long pi = 0; pi < p_count; ++pi) {
      const long p = c.has_p ? c.p_min + pi : 0;
      for (long k = c.k_min; k < c.k_min + k_max && (!c.k_max || k <= c.k_max); ++k) {
        std::vector<std::string> variants = cat.variants_at(c, k);
        if (variants.empty()) variants.push_back("");
        for (const auto& v : variants) {
          const auto t0 = Clock::now();
          const Built b = run_build(cat, {c.id, k, p, v}, BuildOptions{});
          const double ms = seconds_since(t0) * 1e3;
          const auto& pk = b.pattern.packing;
          const long long n = static_cast<long long>(pk.size());
          const bool counts_ok =
              !b.bonds_expected ||
              static_cast<long long>(b.pattern.bonds.size()) == *b.bonds_expected;
          const bool match = b.bonds_match() && b.rattlers_match();
          const bool ok =
              counts_ok && match && b.analysis->certified() && (!b.exact || b.exact->ok);
          all_ok = all_ok && ok;
          std::cout << fmt::format(
              "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9.6f} {:>5} {:>4} {:>6} {:>9} "
              "{:>8.2f}{}\n",
              c.id, p ? std::to_string(p) : "", k, v, n, format_significant(pk.d, 15),
              format_significant(1 / pk.d, 15), static_cast<double>(oler_delta(n, 1 / pk.d)),
              b.pattern.bonds.size(), b.pattern.rattlers.size(), match ? "yes" : "NO",
              b.analysis->certified() ? (b.exact ? "yes+exact" : "yes") : "NO", ms,
              counts_ok ? "" : "  bond count differs from the catalogue");
        }
      }
    }
  }
  std::cout
      << "match: bonds and rattlers found from the geometry alone equal the builder's; certified: "
         "rigid "
         "(LP) with a strictly positive stress; exact: every bond and gap verified in Q(sqrt3).\n";
  return all_ok ? 0 : 1;
}

int cmd_analyze(const AnalyzeOptions& o) {
  const auto convention = parse_convention(o.convention);
  if (!convention)
    throw std::invalid_argument("unknown convention '" + o.convention +
                                "' (unit-triangle, radius, unit-disk-side)");
  Packing start = packing_from_points(read_points_file(o.file).points, *convention,
                                      o.n ? std::optional<long long>(o.n) : std::nullopt);
  const Analysis a = analyze_packing(start, {o.digits});
  if (!o.output.empty()) write_pattern(o.output, a.pattern);
  const auto& pk = a.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  const long double L = 1 / pk.d;
  if (o.json) {
    nlohmann::json j = certificate_json(a);
    j["n"] = n;
    j["d"] = a.d_string(o.digits > 18 ? o.digits : 17);
    j["L"] = format_significant(L, 17);
    j["delta"] = static_cast<double>(oler_delta(n, L));
    j["convention"] = o.convention;
    j["value_in_convention"] = format_significant(from_d(pk.d, *convention), 17);
    j["d_start"] = format_significant(a.relax.d_start, 17);
    j["stage_seconds"] = {{"relax", a.times.relax},
                          {"bonds", a.times.bonds},
                          {"rigidity", a.times.rigidity},
                          {"stress", a.times.stress},
                          {"multiprecision", a.times.multiprecision}};
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << fmt::format("{:<10} {}\n", "file", o.file);
  std::cout << fmt::format("{:<10} {}\n", "n", n);
  std::cout << fmt::format("{:<10} {} (start {})\n", "d", a.d_string(o.digits),
                           format_significant(a.relax.d_start, 15));
  if (*convention != Convention::UnitTriangle)
    std::cout << fmt::format("{:<10} {}\n", o.convention == "radius" ? "r" : "S",
                             format_significant(from_d(pk.d, *convention), std::min(o.digits, 18)));
  std::cout << fmt::format("{:<10} {}\n", "L", format_significant(L, std::min(o.digits, 18)));
  std::cout << fmt::format("{:<10} {}\n", "delta(n)", format_significant(oler_delta(n, L), 15));
  std::cout << fmt::format("{:<10} {}\n", "bonds", a.pattern.bonds.size());
  std::cout << fmt::format("{:<10} {}{}{}\n", "rattlers", a.pattern.rattlers.size(),
                           a.pattern.rattlers.empty() ? "" : " : ",
                           fmt::join(a.pattern.rattlers, " "));
  print_analysis(a, true);
  return 0;
}

// A scene whose initial state names a built pattern: build it (as `tripack build` does, without
// the analysis) and start from its points at its d.
void resolve_scene_pattern(const GlobalOptions& g, Scene& scene) {
  if (!scene.pattern) return;
  const auto& req = *scene.pattern;
  BuildRequest b;
  b.class_id = req.class_name;
  b.k = static_cast<long>(req.k);
  b.p = req.p ? static_cast<long>(*req.p) : 0;
  b.variant = req.variant;
  const Pattern built = build_pattern(load_catalogue(g), b);
  if (scene.n && scene.n != static_cast<int>(built.packing.size()))
    throw std::invalid_argument(fmt::format("the scene has n = {} but pattern {} k={} has {} disks",
                                            scene.n, req.class_name, req.k, built.packing.size()));
  scene.n = static_cast<int>(built.packing.size());
  scene.points = built.packing.points;
  scene.start_d = built.packing.d;
}

int cmd_billiards(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  Scene scene = o.scene.empty() ? default_scene(static_cast<int>(o.n)) : load_scene(o.scene);
  resolve_scene_pattern(g, scene);
  if (o.n && scene.n != o.n)
    throw std::invalid_argument(
        fmt::format("the scene has n = {} but {} was asked for", scene.n, o.n));
  validate_scene(scene);
  if (o.runs < 1) throw std::invalid_argument("--runs must be at least 1");
  struct Run {
    std::uint64_t seed = 0;
    BilliardsResult sim;
    std::optional<Analysis> analysis;
    std::string error;
  };
  std::vector<Run> runs(static_cast<std::size_t>(o.runs));
  std::atomic<int> next{0}, done{0};
  std::mutex report;
  const bool progress = !o.json && isatty(fileno(stderr));
  const auto t0 = Clock::now();
  auto worker = [&] {
    for (int r; (r = next.fetch_add(1)) < o.runs;) {
      Run& run = runs[static_cast<std::size_t>(r)];
      run.seed = o.seed + static_cast<std::uint64_t>(r);  // run r is reproducible on its own
      std::mt19937_64 rng(run.seed);
      BilliardsOptions sim_options;
      if (progress)  // a live line for long runs; nothing at all when not a terminal
        sim_options.progress = [&, r](const BilliardsProgress& p) {
          std::lock_guard<std::mutex> lock(report);
          std::cerr
              << fmt::format(
                     "\rbilliards n={}: {}/{} runs done; run {}: {:.3g} events, {:.2f} M events/s, "
                     "d = {:.10Lg}, gap ~{:.1e}      ",
                     scene.n, done.load(), o.runs, r, static_cast<double>(p.events),
                     p.seconds > 0 ? static_cast<double>(p.events) / p.seconds / 1e6 : 0.0,
                     d_from_diameter(p.diameter), p.relative_gap)
              << std::flush;
        };
      try {
        run.sim = run_billiards(scene, rng, sim_options);
        if (scene.n >= 2 && o.certify) run.analysis = analyze_packing(run.sim.packing, {});
      } catch (const std::exception& e) {
        run.error = e.what();
      }
      const int finished = ++done;
      if (progress) {
        std::lock_guard<std::mutex> lock(report);
        std::cerr << fmt::format(
                         "\rbilliards n={}: {}/{} runs, last d = {:.12Lg}, {:.2f} M events/s      ",
                         scene.n, finished, o.runs, run.sim.packing.d,
                         run.sim.seconds > 0 ? run.sim.events / run.sim.seconds / 1e6 : 0.0)
                  << std::flush;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < std::max(1, o.threads); ++t) pool.emplace_back(worker);
  worker();
  for (auto& t : pool) t.join();
  if (progress) std::cerr << "\n";

  // Distinct certified packings, best first, labelled like the paper: tNa, tNb, ... with the bond
  // count appended where several packings share d.
  std::vector<int> usable;
  std::vector<Pattern> patterns;
  for (std::size_t r = 0; r < runs.size(); ++r)
    if (runs[r].analysis && runs[r].analysis->identification.polish.converged) {
      usable.push_back(static_cast<int>(r));
      patterns.push_back(runs[r].analysis->pattern);
    }
  const std::vector<int> cls = distinct_packings(patterns);
  struct Distinct {
    int cls = -1;
    int first_run = -1, count = 0;
    long double d = 0;
    std::size_t bonds = 0, rattlers = 0;
    bool certified = false;
    std::string label;
  };
  std::vector<Distinct> distinct;
  for (std::size_t u = 0; u < usable.size(); ++u) {
    const auto c = static_cast<std::size_t>(cls[u]);
    if (distinct.size() <= c) distinct.resize(c + 1);
    auto& x = distinct[c];
    if (x.count++ == 0) {
      const auto& a = *runs[static_cast<std::size_t>(usable[u])].analysis;
      x = {static_cast<int>(c),       usable[u],     1, a.pattern.packing.d, a.pattern.bonds.size(),
           a.pattern.rattlers.size(), a.certified(), ""};
    }
  }
  std::sort(distinct.begin(), distinct.end(),
            [](const Distinct& a, const Distinct& b) { return a.d > b.d; });
  char rank = 'a';
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    if (i > 0 && std::fabs(distinct[i].d / distinct[i - 1].d - 1) > 1e-12L) ++rank;
    const bool shared =
        (i > 0 && std::fabs(distinct[i].d / distinct[i - 1].d - 1) <= 1e-12L) ||
        (i + 1 < distinct.size() && std::fabs(distinct[i].d / distinct[i + 1].d - 1) <= 1e-12L);
    distinct[i].label = fmt::format("t{}{}{}", scene.n, rank <= 'z' ? std::string(1, rank) : "?",
                                    shared ? std::to_string(distinct[i].bonds) : "");
  }
  // Distinct packings sharing d and the bond count too: .1, .2, ... (as the paper's t31a81.1,
  // t31a81.2).
  std::map<std::string, int> uses, seen;
  for (const auto& x : distinct) ++uses[x.label];
  for (auto& x : distinct)
    if (uses[x.label] > 1) x.label += fmt::format(".{}", ++seen[x.label]);
  std::vector<std::string> run_label(runs.size(), "-");
  for (std::size_t u = 0; u < usable.size(); ++u)
    for (const auto& x : distinct)
      if (x.cls == cls[u]) run_label[static_cast<std::size_t>(usable[u])] = x.label;
  auto label_of = [&](int r) { return run_label[static_cast<std::size_t>(r)]; };
  const double wall = seconds_since(t0);
  if (o.json) {
    nlohmann::json j;
    j["n"] = scene.n;
    j["seconds"] = wall;
    j["runs"] = nlohmann::json::array();
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const auto& run = runs[r];
      nlohmann::json x{{"seed", run.seed},
                       {"events", run.sim.events},
                       {"collisions", run.sim.collisions},
                       {"seconds", run.sim.seconds},
                       {"d_billiards", format_significant(run.sim.packing.d, 17)},
                       {"stop", run.sim.stop_reason},
                       {"label", label_of(static_cast<int>(r))}};
      if (run.analysis) {
        x["d"] = format_significant(run.analysis->pattern.packing.d, 17);
        x["certificate"] = certificate_json(*run.analysis);
      }
      if (scene.shake)
        x["shake"] = {{"collisions", run.sim.shake_collisions},
                      {"seconds", run.sim.shake_seconds},
                      {"rattlers", run.sim.shake_rattlers}};
      if (!run.error.empty()) x["error"] = run.error;
      j["runs"].push_back(x);
    }
    j["packings"] = nlohmann::json::array();
    for (const auto& x : distinct)
      j["packings"].push_back({{"label", x.label},
                               {"d", format_significant(x.d, 17)},
                               {"bonds", x.bonds},
                               {"rattlers", x.rattlers},
                               {"certified", x.certified},
                               {"runs", x.count},
                               {"first_seed", runs[static_cast<std::size_t>(x.first_run)].seed}});
    std::cout << j.dump() << "\n";
    return 0;
  }
  std::cout << fmt::format("{:>6} {:>12} {:>12} {:>9} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n", "seed",
                           "events", "collisions", "seconds", "d (billiards)", "d (polished)",
                           "bonds", "ratt", "certified", "packing");
  for (std::size_t r = 0; r < runs.size(); ++r) {
    const auto& run = runs[r];
    if (!run.error.empty()) {
      std::cout << fmt::format("{:>6} error: {}\n", run.seed, run.error);
      continue;
    }
    const auto* a = run.analysis ? &*run.analysis : nullptr;
    std::cout << fmt::format("{:>6} {:>12} {:>12} {:>9.3f} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n",
                             run.seed, run.sim.events, run.sim.collisions, run.sim.seconds,
                             format_significant(run.sim.packing.d, 15),
                             a ? format_significant(a->pattern.packing.d, 15) : "-",
                             a ? std::to_string(a->pattern.bonds.size()) : "-",
                             a ? std::to_string(a->pattern.rattlers.size()) : "-",
                             a ? (a->certified() ? "yes" : "no") : "-",
                             label_of(static_cast<int>(r)));
  }
  if (scene.shake) {
    std::cout << fmt::format(
        "shaking at fixed size ({} collisions per disk): rattlers = disks "
        "colliding {}x less often than the median\n",
        scene.shake->per_disk, scene.shake->rattler_factor);
    for (const auto& run : runs)
      if (run.error.empty())
        std::cout << fmt::format(
            "{:>6} shake: {} collisions in {:.3f} s, rattlers [{}]{}\n", run.seed,
            run.sim.shake_collisions, run.sim.shake_seconds, fmt::join(run.sim.shake_rattlers, " "),
            run.analysis ? fmt::format("; analysis rattlers [{}]",
                                       fmt::join(run.analysis->pattern.rattlers, " "))
                         : "");
  }
  std::cout << fmt::format("distinct packings ({} runs, {:.2f} s):\n", o.runs, wall);
  for (const auto& x : distinct)
    std::cout << fmt::format(
        "  {:<10} d = {}  bonds {}  rattlers {}  {}  ({} of {} runs, first seed {})\n", x.label,
        format_significant(x.d, 15), x.bonds, x.rattlers,
        x.certified ? "certified" : "NOT certified", x.count, o.runs,
        runs[static_cast<std::size_t>(x.first_run)].seed);
  return 0;
}

}  // namespace tripack::app
