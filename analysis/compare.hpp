// Contact-graph comparison (docs/certified.md): are two packings of n disks "the same packing"?
//
// Two packings are the same when their d agree to a relative tolerance and, after removing the
// rattlers, one symmetry g of the triangle maps the first onto the second both geometrically
// (every non-rattler of g(a) lies within a tolerance of a distinct non-rattler of b) and
// combinatorially (that point matching maps the bonds of a, walls included with their sides
// permuted by g, onto the bonds of b). Disk indices are irrelevant; rattler positions too.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/packing.hpp"
#include "core/record.hpp"
#include "core/symmetry.hpp"

namespace tripack {

struct Comparison {
  bool same = false;        // same_d, and one symmetry makes the graphs and the points match
  bool same_n = false;      // same number of disks
  bool same_d = false;      // |d_a - d_b| <= d_relative_tolerance * max(d_a, d_b)
  bool isomorphic = false;  // contact graphs (rattlers removed) isomorphic, walls onto walls
  bool geometric = false;   // some symmetry matches the non-rattler points within tolerance
  std::optional<Symmetry> symmetry;  // g with transformed(a, g) ~ b, when same
  std::string reason;                // one line: why they differ, or which symmetry matches
};

// Rattlers are the listed ones plus any disk without bonds. Bonds are taken from the patterns
// (they are not recomputed from the points). position_tolerance is in units of the mean d.
// Cost: O(n) per symmetry when the points propose the vertex matching; Boost's VF2 (with
// colour-refinement invariants) decides isomorphism only when no symmetry proposes one.
Comparison compare_packings(const Pattern& a, const Pattern& b,
                            long double d_relative_tolerance = 1e-12L,
                            long double position_tolerance = 1e-9L);

// A hash of the contact graph (rattlers removed, the three walls as vertices of one kind) by
// colour refinement, the same for every relabelling of the disks and every symmetry of the
// triangle; 16 hex digits (FNV-1a 64 over the refined colours, so equal on every machine).
// Different graphs can share it (refinement does not separate every pair), so stores key a
// packing by (n, this hash, d) and compare_packings decides when it matters.
std::string contact_graph_hash(const Pattern& pattern);

// A record's identity (core/record.hpp): its graph_hash from its pattern.
void identify(PackingRecord& record);

// Groups patterns into classes of "the same packing" (compare_packings(...).same, default
// position tolerance); returns a class id per input, ids 0, 1, ... in first-seen order.
std::vector<int> distinct_packings(const std::vector<Pattern>& patterns,
                                   long double d_relative_tolerance = 1e-12L);

}  // namespace tripack
