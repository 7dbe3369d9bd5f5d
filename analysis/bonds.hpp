// Bonds and rattlers of a configuration (docs/conventions.md-§2): which near contacts are real,
// which disks are held, and how small the remaining gaps are.
#pragma once

#include <cstdint>
#include <vector>

#include "core/packing.hpp"
#include "polish/polish.hpp"
#include "polish/polish_mp.hpp"

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

// Bonds and rattlers decided on a configuration polished in MPFR (docs/certified.md, "The
// multiprecision certificate"), where long double cannot tell a bond from a near contact (a gap
// of 1e-11 d when the long double polish places centres to 1e-12 d). Candidates are `hints`
// (earlier bonds, a builder's, the relax's loaded contacts) and every contact of `start` closer
// than `gap_threshold` d. Repeatedly: rattlers by the surround test; the bond system polished,
// in long double, then in MPFR to `digits`; when it has no solution, a candidate is dropped by
// `rule` (never one whose removal turns held disks into rattlers, if another will do); when it
// has one, every non-bond gap between held disks is evaluated in MPFR, and any within 10^6 x
// the precision's floor of zero (a contact the bond system implies, or an overlap) joins the
// bonds. It ends with a consistent bond set whose other gaps all stand clear of the floor.
// Neither rule is always right: a true contact can start wider open than a false one (n = 169:
// 1.9e-10 d against 8.9e-11 d), and the least-squares compromise spreads a false contact's
// stretch over its true neighbours (n = 188 from its analysed state); callers try both.
enum class DropRule {
  Widest,     // the candidate widest open at the start (the double-precision path's rule)
  Stretched,  // the one most stretched at the least-squares compromise: it most wants to open
};
struct PreciseIdentification {
  std::vector<Bond> bonds;  // sorted, rattlers' bonds removed
  std::vector<int> rattlers;
  MultiprecisionPolish polish;        // of `bonds` to `digits`, rattlers centred in their cages
  PreciseGaps gaps;                   // at that polish
  long double rattler_clearance = 0;  // smallest, in units of d (+inf without rattlers)
  int candidates = 0;                 // contacts considered
  DropRule rule = DropRule::Widest;
  int dropped = 0;      // candidates dropped because the bond system had no solution with them
  int implied = 0;      // contacts added because the polish closed them
  int polishes = 0;     // bond systems polished (long double and MPFR)
  bool found = false;   // a consistent bond set with held disks
  std::string failure;  // why not, when !found
};
PreciseIdentification identify_bonds_multiprecision(const Packing& start,
                                                    const std::vector<Bond>& hints,
                                                    long double gap_threshold, int digits,
                                                    DropRule rule, std::size_t max_drops = 100);

}  // namespace tripack
