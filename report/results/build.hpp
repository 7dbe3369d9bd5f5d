// A build (`tripack build`): the packing of a class member or the best member for n, its polish,
// its certificate; the candidates of `build --n`.
#pragma once

#include <string>
#include <vector>

#include "pipeline/build.hpp"
#include "report/results/analysis.hpp"

namespace tripack::report::results {

// The top-level fields the build's text view prints in its own words.
inline const std::vector<std::string> kBuildShown{"class",
                                                  "k",
                                                  "p",
                                                  "variant",
                                                  "n",
                                                  "d",
                                                  "L",
                                                  "delta",
                                                  "bonds",
                                                  "rattlers",
                                                  "rattler_indices",
                                                  "bonds_expected",
                                                  "rattlers_expected",
                                                  "seconds",
                                                  "stage_seconds",
                                                  "certificate",
                                                  "certify_skipped",
                                                  "certify_error",
                                                  "sqrt3_check",
                                                  "polish_residual",
                                                  "points",
                                                  "candidates"};

inline Tree build_tree(const BuildResult& b, const DescribeOptions& o) {
  const auto& pk = b.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  const long double L = 1.0L / pk.d;
  Tree j = member_tree(b.pattern.provenance);
  j["n"] = n;
  j["d"] = b.digits > kLongDoubleDigits ? b.d_string(b.digits) : decimal17(pk.d);
  // L to the digits of d (the MPFR polish's L); delta stays a number (a double's digits).
  j["L"] = b.digits > kLongDoubleDigits && b.record.L.multiprecision() ? b.record.L.str(b.digits)
                                                                       : decimal17(L);
  j["delta"] = static_cast<double>(oler_delta(n, L));
  add_counts(j, b.record.pattern);  // the certified geometry's where certified (BuildResult)
  j["bonds_expected"] = b.bonds_expected ? Tree(*b.bonds_expected) : Tree(nullptr);
  j["rattlers_expected"] = b.rattlers_expected ? Tree(*b.rattlers_expected) : Tree(nullptr);
  j["seconds"] = b.seconds();
  j["stage_seconds"] = {{"construct", b.times.construct},
                        {"polish", b.polish_seconds},
                        {"sqrt3_check", b.times.sqrt3}};
  if (b.analysis) {
    j["stage_seconds"].update(analysis_stage_seconds(*b.analysis));
    j["certificate"] = certificate_tree(*b.analysis);
    j["certificate"]["bonds_match_builder"] = b.bonds_match();
    j["certificate"]["rattlers_match_builder"] = b.rattlers_match();
  } else {
    j["stage_seconds"]["multiprecision"] = b.times.multiprecision;
    j["certificate"] = nullptr;
    j["certify_skipped"] = b.certify_skipped;
    if (!b.certify_error.empty()) j["certify_error"] = b.certify_error;
  }
  if (b.sqrt3) j["sqrt3_check"] = b.sqrt3->ok;
  if (b.polished) j["polish_residual"] = static_cast<double>(b.polish.max_residual);
  j["verified"] = b.verified();  // counts, geometry, certificate and exact check all hold
  if (o.points) j["points"] = points_tree(pk);
  return j;
}

inline void build_lines(std::ostream& out, const BuildResult& b) {
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
  if (b.sqrt3)
    line(out, "Q(sqrt3)",
         fmt::format("{} ({} bonds exactly at d, {} gaps exactly positive, in Q(sqrt3))",
                     b.sqrt3->ok ? "verified" : "FAILED: " + b.sqrt3->failure,
                     b.sqrt3->bonds_checked, b.sqrt3->gaps_checked));
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
  if (b.sqrt3) times += ", Q(sqrt3) " + ms(b.times.sqrt3);
  if (a)
    times += fmt::format(", relax {}, bonds {}, certify {}", ms(a->times.relax), ms(a->times.bonds),
                         ms(a->times.rigidity + a->times.stress));
  if (a && a->multiprecision) times += ", mpfr " + ms(a->times.multiprecision);
  if (b.multiprecision) times += ", mpfr " + ms(b.times.multiprecision);
  line(out, "time", times);
}

}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<pipeline::BestBuild> {
  static Description describe(const pipeline::BestBuild& b, const DescribeOptions& o) {
    using namespace results;
    Tree j = build_tree(b.best, o);
    if (!b.candidates.empty()) {
      j["candidates"] = Tree::array();
      for (const auto& c : b.candidates) {
        Tree x = member_tree(c.member);
        if (c.error.empty())
          x["d"] = decimal17(c.d);
        else
          x["error"] = c.error;
        j["candidates"].push_back(x);
      }
    }
    return {j, "", kBuildShown};
  }

  static void text(std::ostream& out, const pipeline::BestBuild& b) {
    using namespace results;
    for (const auto& c : b.candidates)
      line(out, "candidate",
           c.error.empty()
               ? fmt::format("{:<40} d = {}", member_name(c.member), format_significant(c.d, 15))
               : fmt::format("{:<40} not built: {}", member_name(c.member), c.error));
    build_lines(out, b.best);
  }
};

}  // namespace tripack::report
