// Lattices with vacancies, and the local optimum near them (docs/classes.md, "Vacancy segments").
//
// Most best packings found above n = 50 are the triangular lattice Delta(K) with its m = Delta(K)
// - n vacancies on one straight segment of a lattice line, along which the two sides of the
// packing slip against each other by a tiny amount (d/spacing - 1 is 4.6e-6 at 53). The lattice
// with the vacancies is a degenerate maximum of d that the LP relax cannot leave (no first-order
// gain); the interior-point relax (analysis/interior_relax.hpp) follows the second-order gain of
// the slip, and from the exact lattice, with no perturbation, it ends at the slipped packing.
// So a vacancy set is a deterministic rule for a packing: no random start, no stored packing.
#pragma once

#include <vector>

#include "core/packing.hpp"
#include "core/progress.hpp"

namespace tripack::patterns {

// Site (i, j) of the rows-row lattice: row j from the bottom (0 .. rows-1), i along it
// (0 .. rows-1-j).
struct Site {
  long i = 0, j = 0;
  auto operator<=>(const Site&) const = default;
};

// Delta(rows) at spacing 1/(rows-1) in the unit triangle, without the vacancies; d = 1/(rows-1).
// Throws std::invalid_argument for rows < 2 or a vacancy off the lattice.
Packing lattice_with_vacancies(long rows, const std::vector<Site>& vacancies);

// Every straight segment of `length` consecutive sites on a lattice line of Delta(rows), one per
// orbit of the triangle's 6 symmetries, in a fixed order (rows first, from the bottom, then
// along the row). There are about (rows - length + 1)(rows - length + 2)/4 of them.
std::vector<std::vector<Site>> straight_segments(long rows, long length);

// The vacancy set's orbit key under the 6 symmetries (for de-duplication and comparisons).
std::vector<Site> canonical_vacancies(long rows, std::vector<Site> vacancies);

// A start moved to the local maximum of d near it, and its bonds identified and polished
// (analysis/bonds.hpp). Deterministic. `exhaustive`: the interior-point relax (one call), then
// the LP relax below 1000 disks, as the exhaustive enumeration relaxes; otherwise the fast
// ranking's relax (the interior relax to the end, then the LP relax below 5000 disks, which
// from there takes 1 to 4 LP steps and loads the contacts the bonds are identified from).
Pattern relax_to_pattern(const Packing& start, bool exhaustive = false);

// The densest of the relaxed lattices Delta(rows) minus one straight segment of `vacancies`
// sites, over every segment up to symmetry. The relax from the exact lattice can end at a
// nearby lower maximum (t74a's segment: 8e-12 below it) or at the same d with a row hanging
// loose in its cage, so that the surround test calls every disk a rattler (t73a's d from a
// straight segment). So the `top_segments` densest segments are also relaxed from `restarts`
// jittered copies of their lattice (seeds 1, 2, ...), and the densest result wins; equal d
// (1e-15 relative) goes to more bonds, as the atlas ranks ties. A bounded enumeration:
// segments + top_segments * restarts relaxes, deterministic.
//
// The fast ranking (the default) relaxes every candidate by the interior-point relax first,
// with a first stage long enough for a long segment's disks to travel several spacings, and
// runs the LP relax, whose CLP simplex is the slow part from a start far from the maximum
// (1.3-4.8 s per segment at n = 600 against 0.1-0.3 s from the interior relax's end), after it.
// Above `all_segments_up_to` disks it keeps a budget of segments, runs the LP relax only on the
// `lp_finalists` densest, and on a restart only where its interior relax ends above the best.
// `exhaustive` relaxes every candidate by interior + LP as it stands (the check of the fast
// ranking: docs/classes.md §9, docs/performance.md "build --n"). Both use `threads` threads; the
// result does not depend on their number.
struct SegmentEnumeration {
  std::size_t top_segments = 3;
  int restarts = 8;
  long double jitter = 1e-4L;    // in lattice spacings (see jittered() in the .cpp)
  std::size_t lp_finalists = 8;  // fast ranking: segments ranked again after the LP relax
  // Fast ranking above `all_segments_up_to` disks: at most `segment_budget` segments, those
  // nearest a wall (the lattice line next to a wall, then the next, ...; ties in enumeration
  // order). The winners seen lie there: every p = 2 winner of k = 3..15 within 3 lines of a wall,
  // n = 168's within 4, and at n = 1820 (p = 10) the bottom row's segments gain 3e-6 to 5e-6
  // where 6 sampled further in gain 0 to 9e-7 (docs/classes.md §9). They are ranked by the
  // interior relax with its default stages (n = 1000, p = 35: 0.45 s per segment, in the same
  // order as the relax to the end, 1.2-10 s), and only the `lp_finalists` densest are relaxed to
  // the end.
  long all_segments_up_to = 300;
  std::size_t segment_budget = 64;
  // Above `few_restarts_from` disks: the restarts are those of the densest segment only, with
  // `few_restarts` seeds (each restart costs a whole relax: 2-10 s at n = 1000, 15 s at 10^4),
  // at most `few_segments` segments, ranked by the interior relax's first 80 Newton steps
  // (one Newton step costs 60 ms at n = 10^4).
  long few_restarts_from = 3000;
  int few_restarts = 4;
  std::size_t few_segments = 16;
  bool exhaustive = false;
  int threads = 1;
  // Stage "construct", one report per relax (segments, then restarts); the enumeration throws
  // Cancelled between relaxes once `cancel` is cancelled.
  ProgressFn progress;
  const CancelToken* cancel = nullptr;
};
struct SegmentChoice {
  Pattern pattern;
  std::vector<Site> vacancies;  // the winning segment (vacancy set)
  std::size_t segments = 0;     // how many were relaxed from the exact lattice
  std::size_t restarts = 0;     // how many jittered restarts were relaxed
};
SegmentChoice best_vacancy_segment(long rows, long vacancies,
                                   const SegmentEnumeration& search = {});

// The same enumeration over any list of vacancy sets of one size (relaxed in the list's order;
// the densest of its ranking wins, as above). Throws std::invalid_argument on an empty list.
SegmentChoice best_vacancy_set(long rows, std::vector<std::vector<Site>> sets,
                               const SegmentEnumeration& search = {});

// Jogged lines: the whole lattice line `distance` lines from a wall (rows - distance sites,
// from wall to wall), with one of its sites moved to a neighbouring site off the line, one set
// per orbit of the 6 symmetries (at most 4 (rows - distance) of them). Empty unless
// distance >= 1 and the line has 2 or more sites. The bests of n = 81, 94, 139 and 257..259 are
// such a set (docs/findings.md §11): the `distance` lines between the wall and the vacancies hold
// `distance` more disks than Delta(rows - 1) fits there, squeezed.
std::vector<std::vector<Site>> jogged_lines(long rows, long distance);
SegmentChoice best_jogged_line(long rows, long distance, const SegmentEnumeration& search = {});

}  // namespace tripack::patterns
