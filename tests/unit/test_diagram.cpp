// report/diagram: packing diagrams as SVG, PNG and PDF, checked on t22a (GL1995: 47 bonds, 2
// rattlers) and on the matrix member with n = 254. The SVG is counted by fill colour, the PNG is
// decoded with Cairo and read pixel by pixel.
#include <cairo.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <numbers>
#include <ostream>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "constructors/registry.hpp"
#include "one_line_error.hpp"
#include "pipeline/analyze.hpp"
#include "report/diagram.hpp"

namespace tripack::report {
namespace {

const Catalogue& catalogue() {
  static const Catalogue c = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  return c;
}

// t22a as `build` certifies it: the analysed pattern and its stress forces.
const Diagram& t22a() {
  static const Diagram diagram = [] {
    const Pattern built = build_pattern(catalogue(), {"even-ripple", 3, 0, ""});
    const pipeline::Analysis a = pipeline::analyze_packing(built.packing, {});
    return Diagram{a.pattern, "t22a", a.d_string(15), a.stress.forces};
  }();
  return diagram;
}

const Diagram& t254() {
  static const Diagram diagram{build_pattern(catalogue(), {"matrix", 1, 11, ""}), "t254", "", {}};
  return diagram;
}

class DiagramTest : public testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = testing::TempDir() + "tripack_diagram_XXXXXX";
    ASSERT_NE(mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The SVG's filled <path> elements by colour: Cairo writes one per fill (a disk's fill and
// outline in one element), with its colour in the style; glyph outlines carry no fill colour.
struct SvgFills {
  int white = 0, grey = 0, black = 0, other = 0;
  int coloured_strokes = 0;  // unfilled paths stroked in a colour that is not grey: force lines
};
SvgFills count_svg_fills(const std::string& svg) {
  SvgFills c;
  const std::regex path_style(R"re(<path style="([^"]*)")re");
  const std::regex fill(R"(fill:rgb\(([0-9.]+)%,([0-9.]+)%,([0-9.]+)%\))");
  const std::regex stroke(R"(fill:none;.*stroke:rgb\(([0-9.]+)%,([0-9.]+)%,([0-9.]+)%\))");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path_style);
       it != std::sregex_iterator(); ++it) {
    const std::string style = (*it)[1];
    std::smatch m;
    if (std::regex_search(style, m, stroke)) {
      c.coloured_strokes += !(m[1] == m[2] && m[2] == m[3]);
      continue;
    }
    if (!std::regex_search(style, m, fill)) continue;
    if (m[1] != m[2] || m[2] != m[3]) {
      ++c.other;
    } else {
      const double v = std::stod(m[1]);
      (v == 100 ? c.white : v == 0 ? c.black : c.grey) += 1;
    }
  }
  return c;
}

struct Rgb {
  int r, g, b;
  bool white() const { return r == 255 && g == 255 && b == 255; }
  bool black() const { return r < 16 && g < 16 && b < 16; }
  bool grey() const { return r == g && g == b && r > 100 && r < 230; }
  bool red() const { return r > 150 && g < 80 && b < 80; }
};
std::ostream& operator<<(std::ostream& out, const Rgb& c) {
  return out << "rgb(" << c.r << ", " << c.g << ", " << c.b << ")";
}

// A PNG decoded by Cairo, read at device coordinates.
class Image {
 public:
  explicit Image(const std::string& path)
      : surface_(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Image() { cairo_surface_destroy(surface_); }
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  Rgb at(const Vec2& p) const {
    const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
    if (x < 0 || y < 0 || x >= width() || y >= height()) return {-1, -1, -1};
    const unsigned char* row =
        cairo_image_surface_get_data(surface_) + y * cairo_image_surface_get_stride(surface_);
    std::uint32_t v;  // native-endian 0xAARRGGBB
    std::memcpy(&v, row + 4 * x, 4);
    return {static_cast<int>(v >> 16 & 255), static_cast<int>(v >> 8 & 255),
            static_cast<int>(v & 255)};
  }

 private:
  cairo_surface_t* surface_;
};

// The diagram drawn as a PNG at `path` and decoded.
std::unique_ptr<Image> drawn_png(const Diagram& diagram, const std::string& path,
                                 const DiagramOptions& o) {
  draw_packing(diagram, path, o);
  return std::make_unique<Image>(path);
}

Vec2L contact_point(const Pattern& p, const Bond& b) {
  const Vec2L& a = p.packing.points[b.a];
  if (b.is_wall()) return a - wall_normal<long double>(b.side()) * (p.packing.d / 2);
  return (a + p.packing.points[b.b]) / 2.0L;
}

bool is_rattler(const Pattern& p, std::size_t i) {
  return std::find(p.rattlers.begin(), p.rattlers.end(), static_cast<int>(i)) != p.rattlers.end();
}

// A point 0.3 d from disk i's centre in the direction farthest from its bonds' dots, clear of
// the label (at most ~0.23 d wide each side) and of the dots and outline (0.45 d and beyond).
Vec2L beside_label(const Pattern& p, std::size_t i) {
  std::vector<double> bond_angles;
  for (const Bond& b : p.bonds)
    if (b.a == static_cast<int>(i) || b.b == static_cast<int>(i)) {
      const Vec2L v = contact_point(p, b) - p.packing.points[i];
      bond_angles.push_back(std::atan2(static_cast<double>(v.y), static_cast<double>(v.x)));
    }
  double best = 0, best_gap = -1;
  for (int k = 0; k < 24; ++k) {
    const double a = k * std::numbers::pi / 12;
    double gap = 10;
    for (double b : bond_angles)
      gap = std::min(gap, std::abs(std::remainder(a - b, 2 * std::numbers::pi)));
    if (gap > best_gap) best_gap = gap, best = a;
  }
  return p.packing.points[i] + Vec2L{std::cos(best), std::sin(best)} * (0.3L * p.packing.d);
}

TEST(Diagram, T22aHasTheBondsAndRattlersOfThePaper) {
  ASSERT_EQ(t22a().pattern.packing.size(), 22u);
  EXPECT_EQ(t22a().pattern.bonds.size(), 47u);
  EXPECT_EQ(t22a().pattern.rattlers.size(), 2u);
  EXPECT_EQ(t22a().forces.size(), 47u);
  EXPECT_EQ(t22a().d_text, "0.179396908611866");
}

TEST_F(DiagramTest, EachFormatHasItsMagicBytesAndTheSameBytesWhenDrawnAgain) {
  const std::vector<std::pair<std::string, std::string>> magic{
      {"svg", "<?xml"}, {"png", "\x89PNG\r\n\x1a\n"}, {"pdf", "%PDF-"}};
  for (bool forces : {false, true}) {
    for (const auto& [ext, start] : magic) {
      const DiagramOptions o{900, true, forces};
      draw_packing(t22a(), path("a." + ext), o);
      draw_packing(t22a(), path("b." + ext), o);
      const std::string a = read_bytes(path("a." + ext)), b = read_bytes(path("b." + ext));
      ASSERT_GT(a.size(), 1000u) << ext;
      EXPECT_EQ(a.substr(0, start.size()), start) << ext;
      EXPECT_TRUE(a == b) << ext << " forces " << forces << ": two drawings differ";
    }
  }
  // The forces change the picture; the PDF's creation date is the fixed one.
  draw_packing(t22a(), path("plain.svg"));
  draw_packing(t22a(), path("forces.svg"), {900, true, true});
  EXPECT_NE(read_bytes(path("plain.svg")), read_bytes(path("forces.svg")));
  EXPECT_NE(read_bytes(path("a.pdf")).find("/CreationDate (20000101000000Z)"), std::string::npos);
  // Upper-case extensions are the same formats.
  draw_packing(t22a(), path("c.PNG"));
  EXPECT_EQ(read_bytes(path("c.PNG")).substr(0, 4), "\x89PNG");
}

TEST_F(DiagramTest, SvgHasAShadedDiskPerNonRattlerAWhiteOnePerRattlerAndADotPerBond) {
  draw_packing(t22a(), path("t22a.svg"));
  const SvgFills c = count_svg_fills(read_bytes(path("t22a.svg")));
  EXPECT_EQ(c.grey, 20);
  EXPECT_EQ(c.white, 2);
  EXPECT_EQ(c.black, 47);
  EXPECT_EQ(c.other, 0);
  EXPECT_EQ(c.coloured_strokes, 0);

  // With forces: one coloured line per bond that carries a force (t22a's stress is strictly
  // positive: all 47).
  draw_packing(t22a(), path("forces.svg"), {900, true, true});
  EXPECT_EQ(count_svg_fills(read_bytes(path("forces.svg"))).coloured_strokes, 47);

  draw_packing(t254(), path("t254.svg"));
  const SvgFills big = count_svg_fills(read_bytes(path("t254.svg")));
  EXPECT_EQ(big.grey, 254 - static_cast<int>(t254().pattern.rattlers.size()));
  EXPECT_EQ(big.white, static_cast<int>(t254().pattern.rattlers.size()));
  EXPECT_EQ(big.black, static_cast<int>(t254().pattern.bonds.size()));
}

TEST_F(DiagramTest, PngPixelsAreWhiteAtRattlersGreyAtDisksAndBlackAtContacts) {
  const Pattern& p = t22a().pattern;
  for (bool labels : {false, true}) {
    const DiagramOptions o{900, labels, false};
    const auto image = drawn_png(t22a(), path("t22a.png"), o);
    ASSERT_TRUE(image->ok());
    EXPECT_EQ(image->width(), 900);
    EXPECT_GT(image->height(), 780);  // the triangle (height ~0.87 of the width) and the caption
    auto at = [&](const Vec2L& u) { return image->at(diagram_position(p.packing.d, u, o)); };
    for (std::size_t i = 0; i < p.packing.size(); ++i) {
      const Vec2L where = labels ? beside_label(p, i) : p.packing.points[i];
      if (is_rattler(p, i))
        EXPECT_TRUE(at(where).white()) << "rattler " << i << ": " << at(where);
      else
        EXPECT_TRUE(at(where).grey()) << "disk " << i << ": " << at(where);
    }
    for (const Bond& b : p.bonds) {
      EXPECT_TRUE(at(contact_point(p, b)).black())
          << "bond " << b.a << "-" << b.b << ": " << at(contact_point(p, b));
      // Outside the container, 0.1 d beyond a wall contact, the paper is white.
      if (b.is_wall()) {
        const Vec2L outside =
            contact_point(p, b) - wall_normal<long double>(b.side()) * (0.1L * p.packing.d);
        EXPECT_TRUE(at(outside).white()) << "outside wall bond of " << b.a;
      }
    }
    // The labels are drawn (dark pixels near every centre) only when asked for. The box,
    // 0.2 d by 0.12 d each side, holds the strokes of "11" and stays clear of the dots.
    const long double d = p.packing.d;
    const double disk = diagram_position(d, {d, 0}, o).x - diagram_position(d, {0, 0}, o).x;
    const int wide = static_cast<int>(0.2 * disk), high = static_cast<int>(0.12 * disk);
    for (std::size_t i = 0; i < p.packing.size(); ++i) {
      int dark = 0;
      for (int dx = -wide; dx <= wide; ++dx)
        for (int dy = -high; dy <= high; ++dy)
          dark += image
                      ->at(diagram_position(p.packing.d, p.packing.points[i], o) +
                           Vec2{1.0 * dx, 1.0 * dy})
                      .black();
      if (labels)
        EXPECT_GT(dark, 10) << "no label on disk " << i;
      else
        EXPECT_EQ(dark, 0) << "something drawn at the centre of disk " << i;
    }
  }
}

TEST_F(DiagramTest, PngForcesAreLinesAlongTheBonds) {
  const Pattern& p = t22a().pattern;
  const DiagramOptions o{900, true, true};
  const auto image = drawn_png(t22a(), path("forces.png"), o);
  ASSERT_TRUE(image->ok());
  long double largest = 0;
  for (long double f : t22a().forces) largest = std::max(largest, f);
  int checked = 0;
  for (std::size_t k = 0; k < p.bonds.size(); ++k) {
    // Lines at least 0.05 d (~6 px) wide cover the pixel 0.4 d from the centre towards the
    // contact: past the label and its halo (within ~0.27 d), short of the dot (from 0.45 d).
    if (t22a().forces[k] < 0.2L * largest) continue;
    const Vec2L a = p.packing.points[p.bonds[k].a], towards = contact_point(p, p.bonds[k]) - a;
    const Vec2L probe = a + towards * (0.4L * p.packing.d / norm(towards));
    const Rgb c = image->at(diagram_position(p.packing.d, probe, o));
    EXPECT_TRUE(c.red()) << "bond " << k << ": " << c;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST_F(DiagramTest, LargePackingStaysReadableAndSmallPicturesDropTheLabels) {
  // n = 254 at 900 px: disks ~37 px, labels drawn; at 200 px (disks ~8 px) labels could not be
  // read and are left out, so the picture is the one without labels.
  const Pattern& p = t254().pattern;
  const DiagramOptions o{900, false, false};
  const auto image = drawn_png(t254(), path("t254.png"), o);
  ASSERT_TRUE(image->ok());
  for (std::size_t i = 0; i < p.packing.size(); ++i) {
    const Rgb c = image->at(diagram_position(p.packing.d, p.packing.points[i], o));
    EXPECT_TRUE(is_rattler(p, i) ? c.white() : c.grey()) << "disk " << i << ": " << c;
  }
  draw_packing(t254(), path("labels.svg"), {900, true, false});
  draw_packing(t254(), path("none.svg"), {900, false, false});
  EXPECT_NE(read_bytes(path("labels.svg")), read_bytes(path("none.svg")));
  draw_packing(t254(), path("small-labels.svg"), {200, true, false});
  draw_packing(t254(), path("small-none.svg"), {200, false, false});
  EXPECT_EQ(read_bytes(path("small-labels.svg")), read_bytes(path("small-none.svg")));
}

TEST_F(DiagramTest, BadExtensionsUnwritablePathsAndMissingForcesAreOneLineErrors) {
  expect_one_line_error([&] { draw_packing(t22a(), path("t22a.jpg")); }, {"'.jpg'"});
  expect_one_line_error([&] { draw_packing(t22a(), path("t22a")); }, {".svg, .png or .pdf"});
  expect_one_line_error([&] { draw_packing(t22a(), path("x.svg/t22a")); }, {".svg, .png or .pdf"});
  for (const std::string ext : {"svg", "png", "pdf"}) {
    const std::string bad = path("no-such-dir/t22a." + ext);
    expect_one_line_error([&] { draw_packing(t22a(), bad); }, {bad});
    EXPECT_FALSE(std::filesystem::exists(bad));
  }
  Diagram no_forces = t22a();
  no_forces.forces.clear();
  expect_one_line_error(
      [&] {
        draw_packing(no_forces, path("f.png"), {900, true, true});
      },
      {"0 forces for 47 bonds"});
  expect_one_line_error([&] { draw_packing(t22a(), path("w.png"), {10, true, false}); }, {"width"});
}

}  // namespace
}  // namespace tripack::report
