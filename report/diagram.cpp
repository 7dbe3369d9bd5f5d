#include "report/diagram.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "core/io.hpp"

namespace tripack::report {
namespace {

enum class Format { Svg, Png, Pdf };

Format format_of(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                        ? ""
                        : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".svg") return Format::Svg;
  if (ext == ".png") return Format::Png;
  if (ext == ".pdf") return Format::Pdf;
  throw std::runtime_error("diagram '" + path + "': unknown extension '" + ext +
                           "' (use .svg, .png or .pdf)");
}

struct SurfaceDeleter {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextDeleter {
  void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDeleter>;
using Context = std::unique_ptr<cairo_t, ContextDeleter>;

// Cairo writes into memory; the file is written once at the end, so a bad path gives one clear
// error and no half-written file.
cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// Cairo 1.16 names the SVG's group after the surface's process-wide serial number
// (id="surface225" on the 225th surface); renumbered in order of appearance, a drawing's bytes
// do not depend on what the process drew before.
std::string renumber_svg_surfaces(const std::string& svg) {
  static constexpr std::string_view kWord = "surface";
  std::vector<std::string> seen;
  std::string out;
  std::size_t from = 0;
  for (std::size_t at = svg.find(kWord); at != std::string::npos; at = svg.find(kWord, at)) {
    std::size_t end = at + kWord.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    const bool is_id =
        end > at + kWord.size() && at > 0 && (svg[at - 1] == '"' || svg[at - 1] == '#');
    if (!is_id) {
      at = end;
      continue;
    }
    const std::string number = svg.substr(at + kWord.size(), end - at - kWord.size());
    auto it = std::find(seen.begin(), seen.end(), number);
    if (it == seen.end()) it = seen.insert(seen.end(), number);
    out.append(svg, from, at - from);
    out += std::string(kWord) + std::to_string(it - seen.begin() + 1);
    from = at = end;
  }
  out.append(svg, from, std::string::npos);
  return out;
}

void check(cairo_status_t status, const std::string& what) {
  if (status != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("diagram: " + what + ": " + cairo_status_to_string(status));
}

struct Colour {
  double r, g, b;
};
constexpr Colour kBlack{0, 0, 0};
constexpr Colour kWhite{1, 1, 1};
constexpr Colour kDisk{0.75, 0.75, 0.75};  // light enough for black labels on it
constexpr Colour kForce{0.75, 0.1, 0.1};   // apart from the black dots and outlines

void set(cairo_t* cr, Colour c) {
  cairo_set_source_rgb(cr, c.r, c.g, c.b);
}

// Where things go on the page, in device units (pixels for PNG, points for SVG and PDF). The
// container triangle (side 1 + sqrt3 d: the centres' triangle pushed out by d/2) fills the width
// between the margins; the caption sits below it.
struct Layout {
  double width = 0, height = 0;
  double margin = 0;
  double scale = 0;          // device units per unit-triangle length
  double left = 0, top = 0;  // unit coordinates of the container's left edge and apex
  double disk = 0;           // disk diameter in device units
  double caption_size = 0, caption_baseline = 0;

  double x(long double ux) const { return margin + (static_cast<double>(ux) - left) * scale; }
  double y(long double uy) const { return margin + (top - static_cast<double>(uy)) * scale; }
};

Layout layout_for(double d, int width) {
  const double sqrt3 = std::sqrt(3.0);
  Layout l;
  l.width = width;
  l.margin = std::max(4.0, std::round(0.025 * width));
  l.left = -sqrt3 * d / 2;
  l.top = sqrt3 / 2 + d;
  const double side = 1 + sqrt3 * d;
  l.scale = (width - 2 * l.margin) / side;
  l.disk = d * l.scale;
  l.caption_size = std::max(7.0, width / 50.0);
  const double triangle_bottom = l.margin + sqrt3 / 2 * side * l.scale;
  l.caption_baseline = triangle_bottom + 0.6 * l.margin + l.caption_size;
  l.height = std::ceil(l.caption_baseline + 0.35 * l.caption_size + 0.6 * l.margin);
  return l;
}

std::string caption_of(const Diagram& diagram) {
  const Pattern& p = diagram.pattern;
  const std::string d =
      diagram.d_text.empty() ? format_significant(p.packing.d, 15) : diagram.d_text;
  const std::size_t r = p.rattlers.size();
  std::string text = diagram.label.empty() ? "" : diagram.label + "   ";
  text += "d = " + d + "   n = " + std::to_string(p.packing.size()) + ", " +
          std::to_string(p.bonds.size()) + " bonds, " + std::to_string(r) +
          (r == 1 ? " rattler" : " rattlers");
  return text;
}

// Toy text API with hinting off: glyph outlines and advances do not depend on the machine's
// fontconfig hinting settings, so the same input gives the same bytes elsewhere too.
void select_font(cairo_t* cr, double size) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_font_options_t* fo = cairo_font_options_create();
  cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
  cairo_font_options_set_antialias(fo, CAIRO_ANTIALIAS_GRAY);
  cairo_set_font_options(cr, fo);
  cairo_font_options_destroy(fo);
}

// Black text centred on (cx, cy); with a halo > 0, outlined first in `halo_colour`.
void show_centred(cairo_t* cr, const std::string& text, double cx, double cy, double halo = 0,
                  Colour halo_colour = kWhite) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, cx - (e.x_bearing + e.width / 2), cy - (e.y_bearing + e.height / 2));
  if (halo > 0) {
    cairo_text_path(cr, text.c_str());
    set(cr, halo_colour);
    cairo_set_line_width(cr, 2 * halo);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    cairo_stroke_preserve(cr);
    set(cr, kBlack);
    cairo_fill(cr);
    return;
  }
  set(cr, kBlack);
  cairo_show_text(cr, text.c_str());
}

Vec2L bond_end(const Pattern& p, const Bond& b) {
  const Vec2L& a = p.packing.points[b.a];
  if (b.is_wall()) return a - wall_normal<long double>(b.side()) * (p.packing.d / 2);
  return p.packing.points[b.b];
}

// The point a bond's dot marks: the contact point of the two disks, or where the disk touches
// the container side.
Vec2L contact_point(const Pattern& p, const Bond& b) {
  if (b.is_wall()) return bond_end(p, b);
  return (p.packing.points[b.a] + p.packing.points[b.b]) / 2.0L;
}

void validate(const Diagram& diagram, const DiagramOptions& options) {
  const Pattern& p = diagram.pattern;
  if (options.width_pixels < 100 || options.width_pixels > 16384)
    throw std::runtime_error("diagram: width " + std::to_string(options.width_pixels) +
                             " outside 100..16384 pixels");
  if (!(p.packing.d > 0) || !std::isfinite(p.packing.d))
    throw std::runtime_error("diagram: d must be positive and finite");
  const int n = static_cast<int>(p.packing.size());
  for (const Bond& b : p.bonds)
    if (b.a < 0 || b.a >= n || (!b.is_wall() && b.b >= n) ||
        (b.is_wall() && static_cast<int>(b.side()) > 2))
      throw std::runtime_error("diagram: bond (" + std::to_string(b.a) + ", " +
                               std::to_string(b.b) + ") names no disk of " + std::to_string(n));
  for (int r : p.rattlers)
    if (r < 0 || r >= n)
      throw std::runtime_error("diagram: rattler " + std::to_string(r) + " names no disk of " +
                               std::to_string(n));
  if (options.forces && diagram.forces.size() != p.bonds.size())
    throw std::runtime_error("diagram: forces asked for, but " +
                             std::to_string(diagram.forces.size()) + " forces for " +
                             std::to_string(p.bonds.size()) + " bonds");
}

void draw(cairo_t* cr, const Diagram& diagram, const DiagramOptions& options, const Layout& l) {
  const Pattern& p = diagram.pattern;
  const long double d = p.packing.d;
  const double sqrt3 = std::sqrt(3.0);

  set(cr, kWhite);
  cairo_paint(cr);

  // The container: the centres' triangle pushed out by d/2, so the disks touch its sides.
  const double dd = static_cast<double>(d);
  cairo_new_path(cr);
  cairo_move_to(cr, l.x(-sqrt3 * dd / 2), l.y(-dd / 2));
  cairo_line_to(cr, l.x(1 + sqrt3 * dd / 2), l.y(-dd / 2));
  cairo_line_to(cr, l.x(0.5), l.y(sqrt3 / 2 + dd));
  cairo_close_path(cr);
  set(cr, kBlack);
  cairo_set_line_width(cr, std::max(1.0, 0.002 * l.width));
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr);

  // Disks: shaded, rattlers unshaded (white, outline only).
  std::vector<bool> rattler(p.packing.size(), false);
  for (int r : p.rattlers) rattler[r] = true;
  const double radius = l.disk / 2;
  cairo_set_line_width(cr, std::clamp(0.012 * l.disk, 0.5, 2.0));
  for (std::size_t i = 0; i < p.packing.size(); ++i) {
    cairo_new_path(cr);
    cairo_arc(cr, l.x(p.packing.points[i].x), l.y(p.packing.points[i].y), radius, 0,
              2 * std::numbers::pi);
    set(cr, rattler[i] ? kWhite : kDisk);
    cairo_fill_preserve(cr);
    set(cr, kBlack);
    cairo_stroke(cr);
  }

  // Forces: a line per bond, its width proportional to the force (0.25 d at the largest).
  if (options.forces) {
    long double largest = 0;
    for (long double f : diagram.forces) largest = std::max(largest, f);
    set(cr, kForce);
    cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
    for (std::size_t k = 0; k < p.bonds.size() && largest > 0; ++k) {
      const double w = static_cast<double>(diagram.forces[k] / largest) * 0.25 * l.disk;
      if (!(w > 0)) continue;
      const Vec2L a = p.packing.points[p.bonds[k].a], b = bond_end(p, p.bonds[k]);
      cairo_new_path(cr);
      cairo_move_to(cr, l.x(a.x), l.y(a.y));
      cairo_line_to(cr, l.x(b.x), l.y(b.y));
      cairo_set_line_width(cr, w);
      cairo_stroke(cr);
    }
  }

  // A dot at every bond. At least 1.5 px, so a PNG's pixel under the contact point is black.
  set(cr, kBlack);
  const double dot = std::max(1.5, 0.05 * l.disk);
  for (const Bond& b : p.bonds) {
    const Vec2L c = contact_point(p, b);
    cairo_new_path(cr);
    cairo_arc(cr, l.x(c.x), l.y(c.y), dot, 0, 2 * std::numbers::pi);
    cairo_fill(cr);
  }

  // Disk indices: one font size for all, fitted to the widest index; none below ~6 px, where
  // they could not be read anyway.
  if (options.disk_labels && p.packing.size() > 0) {
    const double digits = std::to_string(p.packing.size() - 1).size();
    const double size = std::min(0.36 * l.disk, 0.6 * l.disk / (0.64 * digits));
    if (size >= 6) {
      select_font(cr, size);
      // Over the force lines a halo of the disk colour keeps the digits readable.
      const double halo = options.forces ? 0.12 * size : 0;
      for (std::size_t i = 0; i < p.packing.size(); ++i)
        show_centred(cr, std::to_string(i), l.x(p.packing.points[i].x), l.y(p.packing.points[i].y),
                     halo, rattler[i] ? kWhite : kDisk);
    }
  }

  // The caption on a fixed baseline (centring its ink would move it with the text), centred
  // across, shrunk to fit the width if it must.
  const std::string caption = caption_of(diagram);
  select_font(cr, l.caption_size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, caption.c_str(), &e);
  const double room = l.width - 2 * l.margin;
  if (e.x_advance > room) {
    select_font(cr, l.caption_size * room / e.x_advance);
    cairo_text_extents(cr, caption.c_str(), &e);
  }
  set(cr, kBlack);
  cairo_move_to(cr, (l.width - e.x_advance) / 2, l.caption_baseline);
  cairo_show_text(cr, caption.c_str());
}

}  // namespace

Vec2 diagram_position(long double d, const Vec2L& point, const DiagramOptions& options) {
  const Layout l = layout_for(static_cast<double>(d), options.width_pixels);
  return {l.x(point.x), l.y(point.y)};
}

namespace {

// The drawing's bytes in `format` (SVG with its surfaces renumbered: the same bytes every time).
std::string diagram_bytes(const Diagram& diagram, Format format, const DiagramOptions& options) {
  validate(diagram, options);
  const Layout l = layout_for(static_cast<double>(diagram.pattern.packing.d), options.width_pixels);

  std::string bytes;
  Surface surface;
  switch (format) {
    case Format::Svg:
      surface.reset(cairo_svg_surface_create_for_stream(append, &bytes, l.width, l.height));
      break;
    case Format::Pdf:
      surface.reset(cairo_pdf_surface_create_for_stream(append, &bytes, l.width, l.height));
      // Cairo stamps the current time otherwise; a fixed date keeps the bytes reproducible.
      cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_CREATE_DATE,
                                     "2000-01-01T00:00:00Z");
      if (!diagram.label.empty())
        cairo_pdf_surface_set_metadata(surface.get(), CAIRO_PDF_METADATA_TITLE,
                                       diagram.label.c_str());
      break;
    case Format::Png:
      // Opaque RGB: the background is painted white, and viewers with dark themes then show
      // the figure as drawn.
      surface.reset(cairo_image_surface_create(CAIRO_FORMAT_RGB24, static_cast<int>(l.width),
                                               static_cast<int>(l.height)));
      break;
  }
  check(cairo_surface_status(surface.get()), "cannot create the surface");
  {
    Context cr(cairo_create(surface.get()));
    draw(cr.get(), diagram, options, l);
    check(cairo_status(cr.get()), "drawing failed");
  }
  if (format == Format::Png)
    check(cairo_surface_write_to_png_stream(surface.get(), append, &bytes), "PNG encoding failed");
  cairo_surface_finish(surface.get());
  check(cairo_surface_status(surface.get()), "cannot finish the surface");
  return format == Format::Svg ? renumber_svg_surfaces(bytes) : bytes;
}

}  // namespace

void draw_packing(const Diagram& diagram, const std::string& path, const DiagramOptions& options) {
  write_whole_file(path, diagram_bytes(diagram, format_of(path), options));
}

std::string diagram_svg(const Diagram& diagram, const DiagramOptions& options) {
  return diagram_bytes(diagram, Format::Svg, options);
}

}  // namespace tripack::report
