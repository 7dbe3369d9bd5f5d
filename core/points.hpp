// Points as people's files give them -> a Packing in the unit triangle (docs/conventions.md). Files
// come in three conventions and with the slips of hand-made data: coordinates rounded to a few
// digits (a wall disk a hair outside), or a container drawn upside down or with x and y swapped.
// Each slip that can be undone safely is undone with one warning line; the others are one-line
// InputErrors.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "core/packing.hpp"

namespace tripack {

struct PointsReading {
  Packing packing;                    // points in the unit triangle, d their minimum distance
  std::vector<std::string> warnings;  // one line each: what was repaired or looks suspicious
  Convention convention = Convention::UnitTriangle;  // how the coordinates were read
  // The disks' diameter the file itself states, in the unit triangle: its "# d:" header (JSON
  // "d"), else 2r of an "x y r" file scaled like the points. packing.d below it means the
  // file's disks overlap (db import refuses that; analyze warns).
  std::optional<long double> stated_d;
  // The header's d is farther than 2 rounding_tolerance from the points' d (a warning above;
  // db import refuses such a file unless asked).
  bool header_d_differs = false;
  std::string label;  // the file's "# label:" (JSON "label"), empty when it has none
};

// `convention`: how the coordinates are meant; nullopt = the file's own "# convention:" line
// (JSON "convention"), else unit-triangle, or radius when the file carries r (an "x y r" file,
// where any other explicit convention is an InputError). An explicit convention other than the
// one the file declares is an InputError.
//  * unit-triangle: the points must lie in the unit triangle; those outside by at most
//    `rounding_tolerance` (a length in units of the side) are moved onto it (one warning), any
//    farther out is an InputError.
//  * radius / unit-disk-side: the container is inferred from the points: of the triangle's four
//    orientations (upright, turned 30, 60, 90 degrees) the one whose bounding triangle is
//    smallest is the container's; a non-upright one is turned upright (one warning), two within a
//    relative 1e-6 of each other are an InputError. The bounding triangle maps onto the unit one.
//  * an "x y r" file whose closest centres are not 2r apart (relative 1e-6), or a "# d:" header
//    farther than 2 rounding_tolerance from the points' d, gives a warning.
// Also InputErrors: fewer than 2 points, a count other than `expected_n` or than the file's own
// "# n:" (JSON "n"), coinciding points.
PointsReading packing_from_points(PointsFile file, std::optional<Convention> convention,
                                  std::optional<long long> expected_n,
                                  long double rounding_tolerance = 1e-6L);

}  // namespace tripack
