// The catalogue of classes, read from classes.yaml (the single source of truth, docs/classes.md).
#pragma once

#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/expression.hpp"

namespace tripack {

struct CatalogueError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// A member the catalogue does not have (an unknown class; k, p or a variant outside the class's
// range): the request's fault, not the catalogue's (the Python module raises ValueError for it).
struct MemberError : CatalogueError {
  using CatalogueError::CatalogueError;
};

struct VariantInfo {
  std::string id;  // "rattler", "full", or a family "cavity-m" with m in [m_min, m_max]
  bool is_family = false;
  std::string prefix;  // "cavity-" for a family
  Expression m_min, m_max;
  Expression bonds, rattlers;
  bool is_default = false;
  long k_min = 0;  // 0: the class's; else the variant exists from this k on (odd-ripple's depressed
                   // cage needs k >= 3, its other modification exists from k = 2)
};

struct ReferenceValue {
  long k = 0, p = 0;
  long long n = 0;
  std::string variant, label, source;
  std::optional<std::string> d;  // as printed in the source
  std::optional<long long> bonds, rattlers;
};

struct ClosedFormL {
  long k = 0, p = 0;  // 0 = "any"
  Expression L;
  std::string source;
};

struct ClassInfo {
  std::string id, display;
  Expression n;
  bool has_p = false;
  long k_min = 1, k_max = 0, p_min = 1;  // k_max = 0: unbounded
  std::string k_min_reason, k_max_reason;
  std::string builder;
  std::map<std::string, Expression> builder_args;
  Expression L;                // may be empty
  bool closed_form = false;    // L is closed-form for every k (no chain functions)
  Expression bonds, rattlers;  // may be empty (then per variant)
  bool rigid = true;
  std::vector<VariantInfo> variants;
  std::vector<ClosedFormL> closed_form_L;
  std::string note, claim_status, claim_best, claim_tight, claim_source;
  std::vector<ReferenceValue> references;
};

// One member of a class: (class, k[, p][, variant]).
struct Member {
  const ClassInfo* cls = nullptr;
  long k = 0, p = 0;
  long long n = 0;
};

class Catalogue {
 public:
  static Catalogue load(const std::string& path);        // throws CatalogueError
  static Catalogue parse(const std::string& yaml_text);  // throws CatalogueError
  static std::string default_path();  // $TRIPACK_CATALOGUE, else the installed classes.yaml

  const std::vector<ClassInfo>& classes() const { return classes_; }
  const ClassInfo& find(const std::string& id) const;  // throws CatalogueError listing the ids

  // n(k[, p]) in integers. Throws CatalogueError for parameters outside the class's range.
  long long n_of(const ClassInfo& c, long k, long p) const;
  void check_parameters(const ClassInfo& c, long k, long p) const;
  // Every (class, k[, p]) whose n equals N, in catalogue order. Throws CatalogueError for a class
  // whose n breaks check_scan_step.
  std::vector<Member> classify(long long N) const;
  // The scans over a class's members (classify; pipeline::class_members_up_to) stop once n passes
  // a bound, so they need n >= 1 growing strictly with k (and, at k_min, with p). Throws
  // CatalogueError naming the class when `n` (at var = at) breaks that, `previous` being n at
  // var = at - 1 (nullopt at the scan's start): a malformed catalogue (fuzzing: a mutated hexagonal
  // class with n = "Delta(p)", the same for every k) would otherwise be scanned forever.
  static void check_scan_step(const ClassInfo& c, char var, long at,
                              std::optional<long long> previous, long long n);
  // The variant id to use ("" when the class has none) after validating `requested`.
  std::string resolve_variant(const ClassInfo& c, long k, const std::string& requested) const;
  // All variant ids valid at this k (families expanded).
  std::vector<std::string> variants_at(const ClassInfo& c, long k) const;
  // Bond and rattler counts the catalogue predicts (nullopt when it has no formula).
  std::optional<long long> bonds_of(const ClassInfo& c, long k, long p,
                                    const std::string& variant) const;
  std::optional<long long> rattlers_of(const ClassInfo& c, long k, long p,
                                       const std::string& variant) const;
  // L from the catalogue formula (chain functions evaluated by the chain solver), if any.
  std::optional<long double> L_of(const ClassInfo& c, long k, long p) const;
  // An exact closed form for L at (k, p), if the catalogue has one.
  const Expression* closed_form_L_of(const ClassInfo& c, long k, long p) const;

 private:
  std::vector<ClassInfo> classes_;
  const VariantInfo* variant_info(const ClassInfo& c, long k, const std::string& variant) const;
};

// Evaluation environments for catalogue formulas.
ExpressionEnv<long long> integer_env(long k, long p, long m = 0);
ExpressionEnv<long double> real_env(long k, long p);

}  // namespace tripack
