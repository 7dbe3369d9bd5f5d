// Bonds and rattlers of a configuration (docs/conventions.md-§2): which near contacts are real,
// which disks are held, and how small the remaining gaps are.
#pragma once

#include <cstdint>
#include <vector>

#include "core/packing.hpp"
#include "polish/polish.hpp"

namespace tripack {

// Rattlers, found iteratively: a disk is held only if it has >= 3 bonds whose contact directions
// surround its centre strictly (the paper's necessary condition); otherwise it is a rattler, its
// bonds are removed and its neighbours are re-examined. Removes the rattlers' bonds from `bonds`
// and returns the rattlers, sorted.
std::vector<int> find_rattlers(const Packing& packing, std::vector<Bond>& bonds);

// A non-bond near contact and its gap in units of d (pair: |xi - xj|/d - 1; wall: distance/d).
struct Gap {
  Bond contact;
  long double gap = 0;
  bool rattler = false;  // involves a rattler (a cage's play)
};
// The `count` smallest non-bond gaps, smallest first.
std::vector<Gap> smallest_gaps(const Packing& packing, const std::vector<Bond>& bonds,
                               std::size_t count);

struct BondIdentification {
  std::vector<Bond> bonds;  // after rattler removal
  std::vector<int> rattlers;
  PolishReport polish;
  int candidates = 0;  // contacts considered
  int rejected = 0;    // gap-only candidates dropped because the bond system had no solution
};

// From a relaxed configuration: bonds = contacts the relax LP loaded (`loaded`, its positive
// duals) plus every contact closer than `gap_threshold` * d (duals miss redundant contacts of
// over-determined systems); rattlers are removed; the bond system is polished; a gap-only
// candidate that makes the system inconsistent is dropped (largest gap first) and the polish
// repeated. Polishes `packing` in place.
// The threshold: relax fixes d to ~1e-14 but positions along near-degenerate directions only to
// ~1e-7 d (sparse-rows k = 9), so true contacts can be that far open; real near contacts start
// at ~4e-6 d there (1.7e-3 d in t33a), and false candidates fail the consistency test.
// At most `max_rejections` candidates are dropped (each costs a polish): a caller that only
// wants the contacts as they are passes 0 and gets the failed polish at once.
BondIdentification identify_bonds(Packing& packing, const std::vector<Bond>& loaded,
                                  long double gap_threshold = 1e-6L,
                                  std::size_t max_rejections = SIZE_MAX);

}  // namespace tripack
