#include "pipeline/catalogue_checks.hpp"

#include <cmath>
#include <stdexcept>

#include "core/timing.hpp"

namespace tripack::pipeline {

namespace {

std::vector<std::string> variants_or_default(const Catalogue& catalogue, const ClassInfo& c,
                                             long k) {
  std::vector<std::string> variants = catalogue.variants_at(c, k);
  if (variants.empty()) variants.push_back("");
  return variants;
}

}  // namespace

Classification classify(const Catalogue& catalogue, long long n) {
  Classification c{n, catalogue.classify(n)};
  if (c.members.empty())
    throw std::runtime_error("no class of the catalogue contains n = " + std::to_string(n));
  return c;
}

FormulaCheck check_formula(const Catalogue& catalogue, const std::string& class_id, long k_first,
                           long k_last, long p,
                           const std::function<void(const FormulaCheckRow&)>& on_row) {
  const auto start = Clock::now();
  const ClassInfo& c = catalogue.find(class_id);
  FormulaCheck check;
  for (long k = k_first; k <= k_last; ++k) {
    catalogue.check_parameters(c, k, p);
    for (const auto& v : variants_or_default(catalogue, c, k)) {
      BuildSettings settings;
      settings.certify = false;
      const BuildResult b = build_and_certify(catalogue, {c.id, k, p, v}, settings);
      FormulaCheckRow row;
      row.class_id = c.id;
      row.k = k;
      row.p = p;
      row.variant = v;
      row.n = static_cast<long long>(b.pattern.packing.size());
      row.d_built = b.pattern.packing.d;
      std::optional<long double> L;
      if (const Expression* closed_form = catalogue.closed_form_L_of(c, k, p)) {
        L = closed_form->eval<long double>(real_env(k, p));
        row.source = "closed form " + closed_form->text();
      } else if (auto chain = catalogue.L_of(c, k, p)) {
        L = chain;
        row.source = "chain formula " + c.L.text();
      }
      if (L) {
        row.d_formula = 1 / *L;
        row.relative_difference = std::fabs(row.d_built * *L - 1);
      }
      row.bonds = b.pattern.bonds.size();
      row.bonds_expected = b.bonds_expected;
      if (b.sqrt3) {
        row.sqrt3_ok = b.sqrt3->ok;
        row.sqrt3_failure = b.sqrt3->failure;
      }
      row.ok = (!L || row.relative_difference <= kFormulaTolerance) && b.counts_match() &&
               row.sqrt3_ok.value_or(true);
      check.all_ok = check.all_ok && row.ok;
      if (on_row) on_row(row);
      check.rows.push_back(std::move(row));
    }
  }
  check.seconds = seconds_since(start);
  return check;
}

CatalogueTable catalogue_table(const Catalogue& catalogue, long k_count,
                               const std::function<void(const CatalogueTableRow&)>& on_row) {
  const auto start = Clock::now();
  CatalogueTable table;
  for (const auto& c : catalogue.classes()) {
    const long p_count = c.has_p ? 3 : 1;
    for (long pi = 0; pi < p_count; ++pi) {
      const long p = c.has_p ? c.p_min + pi : 0;
      for (long k = c.k_min; k < c.k_min + k_count && (!c.k_max || k <= c.k_max); ++k) {
        for (const auto& v : variants_or_default(catalogue, c, k)) {
          const auto t0 = Clock::now();
          const BuildResult b = build_and_certify(catalogue, {c.id, k, p, v}, BuildSettings{});
          CatalogueTableRow row;
          row.member = b.pattern.provenance;
          row.n = static_cast<long long>(b.pattern.packing.size());
          row.d = b.pattern.packing.d;
          row.bonds = b.pattern.bonds.size();
          row.rattlers = b.pattern.rattlers.size();
          row.counts_match = b.counts_match();
          row.geometry_match = b.bonds_match() && b.rattlers_match();
          row.certified = b.analysis && b.analysis->certified();
          if (b.sqrt3) row.sqrt3_ok = b.sqrt3->ok;
          row.ok = b.analysis && b.verified();
          row.seconds = seconds_since(t0);
          table.all_ok = table.all_ok && row.ok;
          if (on_row) on_row(row);
          table.rows.push_back(std::move(row));
        }
      }
    }
  }
  table.seconds = seconds_since(start);
  return table;
}

std::vector<BuildRequest> class_members_up_to(const Catalogue& catalogue, long long max_n) {
  std::vector<BuildRequest> members;
  for (const auto& c : catalogue.classes()) {
    std::optional<long long> first_n;  // n(k_min, p - 1)
    for (long p = c.has_p ? c.p_min : 0;; ++p) {
      bool any = false;
      std::optional<long long> previous;
      for (long k = c.k_min; !c.k_max || k <= c.k_max; ++k) {
        const long long n = catalogue.n_of(c, k, p);
        // n >= 1 growing with k and p ends both loops (else a malformed catalogue never would).
        Catalogue::check_scan_step(c, 'k', k, previous, n);
        if (c.has_p && k == c.k_min) {
          Catalogue::check_scan_step(c, 'p', p, first_n, n);
          first_n = n;
        }
        previous = n;
        if (n > max_n) break;
        any = true;
        std::vector<std::string> variants = catalogue.variants_at(c, k);
        if (variants.empty()) variants.push_back("");
        for (const auto& v : variants) members.push_back({c.id, k, p, v});
      }
      if (!c.has_p || !any) break;
    }
  }
  return members;
}

}  // namespace tripack::pipeline
