// The one record of a packing, from a billiards run to the atlas: its pattern, the precision its
// value is known to, its certificate, where it came from, its identity and its rank. Every
// command, the store, the atlas and the explorer pass PackingRecords; a layer adds what it knows
// (analysis: certificate and identity; ranking: label and rank; the store: sources).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "core/packing.hpp"
#include "core/precision.hpp"

namespace tripack {

// Where a packing came from. A record found several ways keeps every source.
struct PackingSource {
  // Table: read back from a table that keeps the sources as text (the atlas); name is that text.
  enum class Kind { Builder, Billiards, Import, Table };
  Kind kind = Kind::Billiards;
  std::string name;        // builder: its member ("matrix k=2 p=7"); import: the file's name
  std::uint64_t seed = 0;  // billiards: the smallest seed that ended in it
  long long runs = 0;      // billiards: how many runs ended in it; table: its confirmations
  // Billiards: of `runs`, those that started from nothing stored (a billiards run, a search
  // chain from random starts); a search continued from stored packings does not confirm.
  long long independent_runs = 0;
  // "builder NAME", "billiards seed S (R runs)", "import FILE".
  std::string describe() const;
};

// What "the same packing" means everywhere (docs/certified.md, "Identity"): the same n, the same
// contact graph up to the triangle's 6 symmetries and relabelling (a colour-refinement hash,
// analysis/compare.hpp identify) and d to kIdentityDigits significant digits.
inline constexpr int kIdentityDigits = 12;
// d agreeing to this relative tolerance is "the same d" (identity and ranking).
inline constexpr long double kSameDTolerance = 1e-12L;
// Two polished d (>= 19 digits) this close are one value (the atlas's confirmations): a long
// double's rounding is 1.1e-19, and two distinct values of one n never came within 1e-12.
inline constexpr long double kSameValueTolerance = 1e-17L;
struct PackingKey {
  long long n = 0;
  std::string graph_hash;
  std::string d_key;  // d with kIdentityDigits significant digits
  auto operator<=>(const PackingKey&) const = default;
};
std::string identity_d_key(long double d);

struct PackingRecord {
  Pattern pattern;  // polished; bonds and rattlers from the geometry once analysed
  PreciseReal d, L;
  PrecisePoints precise_points;  // the coordinates to d.digits() (MPFR polish), else empty
  bool certified = false;
  std::string verdict;              // the certificate's one-line verdict
  std::vector<long double> forces;  // the stress certificate's, per bond
  // The margins the certificate resolved (docs/certified.md): the smallest non-bond gap between
  // held disks in units of d (+inf when there is none) and the smallest bond force (pair forces
  // summing to 1). certificate_digits: 0 for the double-precision certificate, else the MPFR
  // digits of the multiprecision one that decided.
  long double smallest_gap = std::numeric_limits<long double>::infinity();
  long double min_force = 0;
  int certificate_digits = 0;
  std::string graph_hash;  // identity (analysis/compare.hpp identify fills it)
  std::vector<PackingSource> sources;
  std::string label;     // among the packings of its n (core/ranking.hpp): t22a, t17a40, ...
  std::size_t rank = 0;  // 1 = the best of its n in its list
  double seconds = 0;    // what finding and certifying it cost
  // The best of its n where the optimum is proven (Delta(k) by Oler's bound, n <= 15 by GL1995
  // sec. 1): set by whoever knows the best of n.
  bool proven_optimal = false;
  std::string file;  // where its coordinates were written or read, when they were

  static PackingRecord of(Pattern pattern);  // d and L from its long double d
  long long n() const { return static_cast<long long>(pattern.packing.size()); }
  std::size_t bonds() const { return pattern.bonds.size(); }
  std::size_t rattlers() const { return pattern.rattlers.size(); }
  PackingKey key() const { return {n(), graph_hash, identity_d_key(d.value())}; }
  // The smallest billiards seed among the sources (max when no run found it): ties in d are
  // broken by it, so an order never depends on which thread finished first.
  std::uint64_t first_seed() const;
  bool has_seed() const { return first_seed() != std::numeric_limits<std::uint64_t>::max(); }
  long long runs() const;  // billiards runs over every source
  // The independent searches that reached it: independent billiards runs and search
  // chains, plus one when a builder gives it; a table's count as read back.
  long long own_confirmations() const;
  // d_confirmations when the atlas has set it, else own_confirmations().
  long long confirmations() const {
    return d_confirmations >= 0 ? d_confirmations : own_confirmations();
  }
  // The atlas's count: the confirmations of every packing of this n whose d agrees
  // with this one's (kSameValueTolerance), summed. It confirms the value d(n), which distinct
  // packings often share (Delta(k) - 1 with its vacancy anywhere, or a loose contact made or
  // not). -1: not set.
  long long d_confirmations = -1;
  bool from_builder() const {
    return !sources.empty() && sources.front().kind == PackingSource::Kind::Builder;
  }
  // The first source's kind: "builder", "billiards" or "import" ("" when it has none).
  std::string origin() const;
  std::string source_text() const;  // every source described, "; " between them
  // Folds another record of the same packing in: its sources (billiards seeds and runs summed).
  void merge_sources(const PackingRecord& other);
};

// The same packing: the same n and contact graph (graph_hash, set by analysis/compare.hpp identify)
// and d within kSameDTolerance, or the same PackingKey (d equal to kIdentityDigits digits).
bool same_packing(const PackingRecord& a, const PackingRecord& b);
// The rule itself, on what it reads (for a store that keeps rows, not records).
struct IdentityFields {
  long long n = 0;
  std::string_view graph_hash;
  long double d = 0;
};
bool same_packing(const IdentityFields& a, const IdentityFields& b);

// One record per packing: each record is folded into the first earlier one it is the same
// packing as (merge_sources); first appearance order. group[i] (when asked for) is the index in
// the result that record i went to.
std::vector<PackingRecord> merge_same_packings(std::vector<PackingRecord> records,
                                               std::vector<std::size_t>* group = nullptr);

}  // namespace tripack
