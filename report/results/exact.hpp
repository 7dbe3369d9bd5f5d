// Algebraic d(n) (`tripack exact`): per packing, the minimal polynomial P of d, the proof and its
// statements. Each row's first columns are data/atlas-exact.csv's (docs/exact.md).
#pragma once

#include <fmt/format.h>

#include "pipeline/exact.hpp"
#include "report/results/common.hpp"

namespace tripack::report::results {

// atlas-exact.csv's columns (n, label, degree, polynomial, root_low, root_high, proof, reason,
// seconds) first, then what the table does not keep.
inline Tree exact_row(const pipeline::ExactResult& r) {
  const auto& p = r.polynomial;
  const auto& c = r.configuration;
  const bool proven = c && c->proven;
  Tree j;
  j["n"] = r.n;
  j["label"] = r.label;
  j["degree"] = p.found ? Tree(p.polynomial.degree()) : Tree(nullptr);
  j["polynomial"] = p.found ? Tree(p.polynomial.pari("x")) : Tree(nullptr);
  j["root_low"] = p.found ? Tree(p.root.low) : Tree(nullptr);
  j["root_high"] = p.found ? Tree(p.root.high) : Tree(nullptr);
  j["proof"] = r.proof;
  j["reason"] = r.reason;
  j["seconds"] = std::round(r.seconds() * 100) / 100;
  j["file"] = r.file;
  j["digits"] = p.found ? Tree(p.digits) : Tree(nullptr);
  j["confirmed_digits"] = p.found ? Tree(p.confirmed_digits) : Tree(nullptr);
  j["d"] = p.found ? Tree(r.d) : Tree(nullptr);
  j["field"] = proven ? Tree(c->field.pari("t")) : Tree(nullptr);
  j["field_degree"] = proven ? Tree(c->field.degree()) : Tree(nullptr);
  j["largest_offset"] = proven ? Tree(c->largest_offset) : Tree(nullptr);
  j["smallest_margin"] = proven ? Tree(c->smallest_margin) : Tree(nullptr);
  const auto& o = r.optimality;
  j["rank"] = o ? Tree(o->rank) : Tree(nullptr);
  j["columns"] = o ? Tree(o->columns) : Tree(nullptr);
  j["self_stresses"] = o ? Tree(o->stresses) : Tree(nullptr);
  j["strict_local_optimum"] = o ? Tree(o->proven) : Tree(nullptr);
  return j;
}

}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<pipeline::ExactRun> {
  static Description describe(const pipeline::ExactRun& run, const DescribeOptions&) {
    Tree packings = Tree::array();
    for (const auto& r : run.packings) packings.push_back(results::exact_row(r));
    return {Tree{{"packings", packings}}, "packings", {"packings"}};
  }

  static void text(std::ostream& out, const pipeline::ExactRun& run) {
    using namespace results;
    for (const auto& r : run.packings) {
      out << fmt::format("{} (n = {}): proof {}\n", r.label, r.n, r.proof);
      const auto& p = r.polynomial;
      if (p.found) {
        out << fmt::format("  P = {}\n", p.polynomial.pari("x"));
        out << fmt::format(
            "  degree {}, coefficients up to {} digits; irreducible over Q; found from {} digits, "
            "confirmed from {}\n",
            p.polynomial.degree(), p.polynomial.height_digits(), p.digits, p.confirmed_digits);
        out << fmt::format("  d is its only root in [{}, {}]\n", p.root.low, p.root.high);
        out << fmt::format("  d = {}\n", r.d.substr(0, 62));
      }
      if (r.configuration && r.configuration->proven)
        out << fmt::format(
            "  statement (I): the exact configuration exists in a field of degree {}; "
            "given points within {:.1g}; smallest non-bond margin {:.3g} d\n",
            r.configuration->field.degree(), r.configuration->largest_offset,
            r.configuration->smallest_margin);
      if (r.optimality && r.optimality->proven)
        out << fmt::format(
            "  statement (II): G has full rank {} over K; a strictly positive exact stress "
            "({} self-stresses; smallest/largest force {:.3g}): a strict local optimum\n",
            r.optimality->rank, r.optimality->stresses, r.optimality->smallest_stress_ratio);
      if (!r.reason.empty()) out << "  " << r.reason << "\n";
      out << fmt::format(
          "  {:.2f} s (polish {:.2f}, polynomial {:.2f}, existence {:.2f}, optimality {:.2f})\n",
          r.seconds(), r.seconds_polish, r.seconds_polynomial, r.seconds_existence,
          r.seconds_optimality);
    }
  }
};

}  // namespace tripack::report
