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

// A start moved to the local maximum of d near it: the interior-point relax, then the LP relax
// (which ends the interior relax's last 1e-13 and loads the contacts), then the bonds identified
// and polished (analysis/bonds.hpp). Deterministic.
Pattern relax_to_pattern(const Packing& start);

// The densest of the relaxed lattices Delta(rows) minus one straight segment of `vacancies`
// sites, over every segment up to symmetry (ties: the first in straight_segments' order).
struct SegmentChoice {
  Pattern pattern;
  std::vector<Site> vacancies;  // the winning segment
  std::size_t segments = 0;     // how many were relaxed
};
SegmentChoice best_vacancy_segment(long rows, long vacancies);

}  // namespace tripack::patterns
