// Renderers of `tripack exact` (report/render.hpp).
#include <fmt/format.h>

#include <nlohmann/json.hpp>
#include <ostream>

#include "jobs/exact_atlas.hpp"
#include "report/render.hpp"

namespace tripack::report {

namespace {

double seconds_of(const pipeline::ExactResult& r) {
  return r.seconds_polish + r.seconds_polynomial + r.seconds_existence;
}

}  // namespace

void render_csv(std::ostream& out, const pipeline::ExactRun& run, const RenderOptions&) {
  out << jobs::exact_csv_header() << "\n";
  for (const auto& r : run.packings) out << jobs::exact_csv_row(r) << "\n";
}

void render_text(std::ostream& out, const pipeline::ExactRun& run, const RenderOptions&) {
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
    out << fmt::format("  {:.2f} s (polish {:.2f}, polynomial {:.2f}, existence {:.2f})\n",
                       seconds_of(r), r.seconds_polish, r.seconds_polynomial, r.seconds_existence);
  }
}

void render_json(std::ostream& out, const pipeline::ExactRun& run, const RenderOptions&) {
  nlohmann::json packings = nlohmann::json::array();
  for (const auto& r : run.packings) {
    nlohmann::json j;
    j["file"] = r.file;
    j["n"] = r.n;
    j["label"] = r.label;
    j["proof"] = r.proof;
    j["reason"] = r.reason;
    j["seconds"] = seconds_of(r);
    if (r.polynomial.found) {
      j["polynomial"] = r.polynomial.polynomial.pari("x");
      j["degree"] = r.polynomial.polynomial.degree();
      j["root_low"] = r.polynomial.root.low;
      j["root_high"] = r.polynomial.root.high;
      j["digits"] = r.polynomial.digits;
      j["confirmed_digits"] = r.polynomial.confirmed_digits;
      j["d"] = r.d;
    }
    if (r.configuration && r.configuration->proven) {
      j["field"] = r.configuration->field.pari("t");
      j["field_degree"] = r.configuration->field.degree();
      j["largest_offset"] = r.configuration->largest_offset;
      j["smallest_margin"] = r.configuration->smallest_margin;
    }
    if (r.optimality) {
      j["rank"] = r.optimality->rank;
      j["columns"] = r.optimality->columns;
      j["self_stresses"] = r.optimality->stresses;
      j["strict_local_optimum"] = r.optimality->proven;
    }
    packings.push_back(j);
  }
  out << nlohmann::json{{"packings", packings}}.dump(2) << "\n";
}

}  // namespace tripack::report
