// Whole-catalogue checks: built d against the closed forms (check-formula) and the first terms of
// every class built, polished and certified (the table). Results only; progress by callback.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/build.hpp"

namespace tripack::pipeline {

// `tripack classify N`: every member of the catalogue with n = N.
struct Classification {
  long long n = 0;
  std::vector<Member> members;
};
// Throws std::runtime_error when no class contains n.
Classification classify(const Catalogue& catalogue, long long n);

struct FormulaCheckRow {
  std::string class_id;
  long k = 0, p = 0;
  std::string variant;
  long long n = 0;
  long double d_built = 0;
  std::optional<long double> d_formula;  // none: the catalogue has no formula for L
  long double relative_difference = 0;
  std::size_t bonds = 0;
  std::optional<long long> bonds_expected;
  std::string source;  // "closed form ..." or "chain formula ..."
  std::optional<bool> sqrt3_ok;
  std::string sqrt3_failure;
  bool ok = false;
};
struct FormulaCheck {
  std::vector<FormulaCheckRow> rows;
  bool all_ok = true;
  double seconds = 0;
};
// A double-rounded closed form and a polished bond system agree to a few ulps of L; 1e-14
// relative leaves room for the long double chain functions and rounding of d.
inline constexpr long double kFormulaTolerance = 1e-14L;

FormulaCheck check_formula(const Catalogue& catalogue, const std::string& class_id, long k_first,
                           long k_last, long p,
                           const std::function<void(const FormulaCheckRow&)>& on_row = {});

struct CatalogueTableRow {
  Provenance member;
  long long n = 0;
  long double d = 0;
  std::size_t bonds = 0, rattlers = 0;
  bool counts_match = false;    // bond count equals the catalogue's
  bool geometry_match = false;  // bonds and rattlers from the geometry equal the builder's
  bool certified = false;
  std::optional<bool> sqrt3_ok;
  bool ok = false;
  double seconds = 0;
};
struct CatalogueTable {
  std::vector<CatalogueTableRow> rows;
  bool all_ok = true;
  double seconds = 0;
};
// k = k_min .. k_min + k_count - 1 of every class (p = p_min .. p_min + 2 for the matrix).
CatalogueTable catalogue_table(const Catalogue& catalogue, long k_count,
                               const std::function<void(const CatalogueTableRow&)>& on_row = {});

// Every (class, k, p, variant) of the catalogue with n <= max_n, in catalogue order.
std::vector<BuildRequest> class_members_up_to(const Catalogue& catalogue, long long max_n);

}  // namespace tripack::pipeline
