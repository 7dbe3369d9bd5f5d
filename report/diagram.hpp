// Packing diagrams drawn like Graham & Lubachevsky's figures (docs/formats.md): the container
// triangle, shaded disks, unshaded rattlers, a dot at every bond (disk-disk and disk-wall), disk
// indices, and a caption with the label and d. Optionally the stress certificate's bond forces as
// line widths, which shows why the packing is locally optimal.
#pragma once

#include <string>
#include <vector>

#include "core/packing.hpp"

namespace tripack::report {

struct DiagramOptions {
  int width_pixels = 900;   // PNG width; SVG/PDF use points at the same size
  bool disk_labels = true;  // disk indices (0-based) inside the disks
  bool forces = false;      // draw the stress certificate's bond forces as line widths
};

struct Diagram {
  Pattern pattern;                  // unit-triangle centres, d, bonds (walls too), rattlers
  std::string label;                // e.g. "t22a"; may be empty
  std::string d_text;               // d as printed (15+ digits), e.g. "0.179396908611866"
  std::vector<long double> forces;  // per bond (same order as pattern.bonds), or empty
};

// Writes .svg, .png or .pdf by extension; throws a one-line std::runtime_error on a bad
// extension or an unwritable path. Same input, same bytes (PDF creation date fixed).
void draw_packing(const Diagram& diagram, const std::string& path,
                  const DiagramOptions& options = {});
// The same drawing as SVG text, for a caller that shows it itself (a notebook's _repr_svg_).
std::string diagram_svg(const Diagram& diagram, const DiagramOptions& options = {});

// Where a unit-triangle point lands in the drawing of a packing with diameter d (pixels for
// PNG, points for SVG and PDF; y down): for checking a picture, or for image maps over it.
Vec2 diagram_position(long double d, const Vec2L& point, const DiagramOptions& options = {});

}  // namespace tripack::report
