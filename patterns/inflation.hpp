// The Delta(2)-inflation (docs/findings.md §3): the best packings found at n = Delta(2k+3) - 3
// are inflations of the best ones at Delta(k+2) - 2, with L(inflated) = L(base) + k + 1.
//
// A base packing near the K-row triangular lattice (each disk rounds to its own site) is mapped
// disk by disk, in diameter units, to P + q (P its centre, q its site at spacing 1): the
// Minkowski sum of the base triangle (side L) and the lattice triangle (side K - 1), so the
// slips of the base's rows are kept at full size while the lattice doubles. Every lattice edge
// but those between two vacancies gets a disk one spacing from one of its ends (the end nearer
// its lattice site, or the occupied one): the base contact along the edge is kept whole on that
// side. A base with vacancy set V thus gives Delta(2K - 1) - |V| - |edges inside V| disks:
// Delta(k+2) - 2 with adjacent vacancies gives Delta(2k+3) - 3. Where the base is far from the
// lattice (which end owns an edge is then a guess) disks can overlap: the returned d is the
// true minimum distance, and the result is a start to analyse (relax, polish, certify).
#pragma once

#include <optional>

#include "core/packing.hpp"

namespace tripack::patterns {

// The inflation of `base`, or none when base is not near a lattice Delta(K) (two disks round
// to one site, or one falls outside) or has fewer than 3 disks. The inflation of an atlas best
// is exact where the inflated n's best is one (the returned d is its d to 1e-18).
std::optional<Packing> inflate_by_two(const Packing& base);

// The base n whose inflation has n disks: n = Delta(2K - 1) - (2m - 1) (the smallest triangle
// holding n has an odd number of rows 2K - 1 and an odd number 2m - 1 >= 3 of vacancies) comes
// from Delta(K) - m with its m vacancies on one lattice line. m = 2 is findings §3's
// Delta(2k+3) - 3 from Delta(k+2) - 2 (12, 25, 42, 63, 88, 117, 150, 187, ...); the atlas's best
// is the inflation of the base's best there, and also at 40, 86, 148 (m = 3), 84, 183 (m = 4)
// and 144 (m = 5) (docs/findings.md §3). None for other n.
std::optional<long long> inflation_base(long long n);

}  // namespace tripack::patterns
