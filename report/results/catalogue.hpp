// The catalogue (`tripack classes`), the members containing n (`tripack classify`), and the
// catalogue's checks (`tripack check-formulas`, `tripack table`).
#pragma once

#include <optional>

#include "constructors/catalogue.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/results/common.hpp"

namespace tripack::report::results {}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<Catalogue> {
  static Description describe(const Catalogue& catalogue, const DescribeOptions&) {
    using namespace results;
    Tree classes = Tree::array();
    for (const auto& c : catalogue.classes()) {
      Tree j{{"id", c.id},
             {"display", c.display},
             {"n", c.n.text()},
             {"k_min", c.k_min},
             {"k_max", c.k_max ? Tree(c.k_max) : Tree(nullptr)},
             {"p_min", c.has_p ? Tree(c.p_min) : Tree(nullptr)},
             {"L", c.L.empty() ? Tree(nullptr) : Tree(c.L.text())},
             {"bonds", c.bonds.empty() ? Tree(nullptr) : Tree(c.bonds.text())},
             {"rattlers", c.rattlers.empty() ? Tree(nullptr) : Tree(c.rattlers.text())},
             {"builder", c.builder}};
      Tree variants = Tree::array();
      for (const auto& v : c.variants) variants.push_back(v.id);
      j["variants"] = variants;
      j["claim"] = {{"status", c.claim_status},
                    {"best", c.claim_best},
                    {"tight", c.claim_tight},
                    {"source", c.claim_source}};
      classes.push_back(j);
    }
    return {Tree({{"classes", classes}, {"seconds", 0.0}}), "classes", {"classes", "seconds"}};
  }

  static void text(std::ostream& out, const Catalogue& catalogue) {
    using namespace results;
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
};

template <>
struct View<pipeline::Classification> {
  static Description describe(const pipeline::Classification& c, const DescribeOptions&) {
    using namespace results;
    Tree members = Tree::array();
    for (const auto& m : c.members)
      members.push_back({{"class", m.cls->id},
                         {"k", m.k},
                         {"p", m.cls->has_p ? Tree(m.p) : Tree(nullptr)},
                         {"display", m.cls->display}});
    return {Tree({{"n", c.n}, {"members", members}, {"seconds", 0.0}}),
            "members",
            {"n", "members", "seconds"}};
  }

  static void text(std::ostream& out, const pipeline::Classification& c) {
    using namespace results;
    for (const auto& m : c.members)
      out << m.cls->id << (m.cls->has_p ? " p=" + std::to_string(m.p) : "") << " k=" << m.k
          << "   (" << m.cls->display << ")\n";
  }
};

template <>
struct View<pipeline::FormulaCheck> {
  static Description describe(const pipeline::FormulaCheck& c, const DescribeOptions&) {
    using namespace results;
    Tree rows = Tree::array();
    for (const auto& r : c.rows)
      rows.push_back(
          {{"class", r.class_id},
           {"k", r.k},
           {"p", r.p ? Tree(r.p) : Tree(nullptr)},
           {"variant", optional_string(r.variant)},
           {"n", r.n},
           {"d_built", decimal17(r.d_built)},
           {"d_formula", r.d_formula ? Tree(decimal17(*r.d_formula)) : Tree(nullptr)},
           {"relative_difference",
            r.d_formula ? Tree(static_cast<double>(r.relative_difference)) : Tree(nullptr)},
           {"bonds", r.bonds},
           {"bonds_expected", r.bonds_expected ? Tree(*r.bonds_expected) : Tree(nullptr)},
           {"sqrt3_check", r.sqrt3_ok ? Tree(*r.sqrt3_ok) : Tree(nullptr)},
           {"source", r.source},
           {"ok", r.ok}});
    return {Tree({{"rows", rows}, {"all_ok", c.all_ok}, {"seconds", c.seconds}}),
            "rows",
            {"rows", "all_ok", "seconds"}};
  }

  static void text(std::ostream& out, const pipeline::FormulaCheck& c) {
    using namespace results;
    out << fmt::format("{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}\n", "k", "n", "variant",
                       "d built", "d formula", "rel.diff", "bonds", "source");
    for (const auto& r : c.rows) {
      // Closed forms are also checked exactly: every bond exactly at d, every gap exactly > 0.
      const std::string sqrt3_note =
          r.sqrt3_ok
              ? (*r.sqrt3_ok ? "; exact in Q(sqrt3): ok" : "; exact: FAILED " + r.sqrt3_failure)
              : "";
      out << fmt::format(
          "{:>4} {:>8} {:<10} {:>22} {:>22} {:>10} {:>10} {}{}\n", r.k, r.n, r.variant,
          format_significant(r.d_built, 17),
          r.d_formula ? format_significant(*r.d_formula, 17) : "-",
          r.d_formula ? fmt::format("{:.2e}", static_cast<double>(r.relative_difference)) : "-",
          count_vs(r.bonds, r.bonds_expected),
          (r.d_formula ? r.source : "no formula for L in the catalogue") + sqrt3_note,
          r.ok ? "" : "  FAIL");
    }
  }
};

template <>
struct View<pipeline::CatalogueTable> {
  static Description describe(const pipeline::CatalogueTable& t, const DescribeOptions&) {
    using namespace results;
    Tree rows = Tree::array();
    for (const auto& r : t.rows) {
      Tree x = member_tree(r.member);
      x.update({{"n", r.n},
                {"d", decimal17(r.d)},
                {"L", decimal17(1 / r.d)},
                {"delta", static_cast<double>(oler_delta(r.n, 1 / r.d))},
                {"bonds", r.bonds},
                {"rattlers", r.rattlers},
                {"counts_match_catalogue", r.counts_match},
                {"geometry_matches_builder", r.geometry_match},
                {"certified", r.certified},
                {"sqrt3_check", r.sqrt3_ok ? Tree(*r.sqrt3_ok) : Tree(nullptr)},
                {"ok", r.ok},
                {"seconds", r.seconds}});
      rows.push_back(x);
    }
    return {Tree({{"rows", rows}, {"all_ok", t.all_ok}, {"seconds", t.seconds}}),
            "rows",
            {"rows", "all_ok", "seconds"}};
  }

  static void text(std::ostream& out, const pipeline::CatalogueTable& t) {
    using namespace results;
    out << fmt::format(
        "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9} {:>5} {:>4} {:>6} {:>9} {:>8}\n",
        "class", "p", "k", "variant", "n", "d", "L", "delta", "bonds", "ratt", "match", "certified",
        "ms");
    for (const auto& r : t.rows)
      out << fmt::format(
          "{:<20} {:>3} {:>3} {:<9} {:>5} {:>19} {:>18} {:>9.6f} {:>5} {:>4} {:>6} {:>9} "
          "{:>8.2f}{}\n",
          r.member.class_id, r.member.p ? std::to_string(r.member.p) : "", r.member.k,
          r.member.variant, r.n, format_significant(r.d, 15), format_significant(1 / r.d, 15),
          static_cast<double>(oler_delta(r.n, 1 / r.d)), r.bonds, r.rattlers,
          r.geometry_match ? "yes" : "NO", r.certified ? (r.sqrt3_ok ? "yes+exact" : "yes") : "NO",
          r.seconds * 1e3, r.counts_match ? "" : "  bond count differs from the catalogue");
    out << "match: bonds and rattlers found from the geometry alone equal the builder's; "
           "certified: rigid (LP) with a strictly positive stress; exact: every bond and gap "
           "verified in Q(sqrt3).\n";
  }
};

}  // namespace tripack::report
