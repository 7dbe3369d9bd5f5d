// The layouts of packing files, read and written: "x y" text, the record tables' "i x y", CSV and
// JSON. Which file is which (names, extensions) is the format table's (formats/formats.hpp).
// Coordinates are written with 21 significant digits (round-trip exact for long double) in text
// and CSV; JSON numbers are doubles (17 digits), so JSON also carries them as strings.
#pragma once

#include <array>
#include <filesystem>
#include <initializer_list>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/conventions.hpp"
#include "core/packing.hpp"
#include "core/precision.hpp"

namespace tripack {

// Thrown on unreadable or malformed input; the message is one line naming the place.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// How the writers below lay out the coordinates. The defaults give the unit-triangle files
// tripack always wrote. In another convention (docs/conventions.md) the coordinates are converted
// by point_in_convention and the file says so: a "# convention: NAME (...)" comment line (JSON:
// "convention"), which read_points reports and packing_from_points follows. d stays the
// unit-triangle d in every convention (r and S are given beside it).
struct WriteOptions {
  Convention convention = Convention::UnitTriangle;
  int digits = 21;    // significant digits of coordinates (21: a long double's round trip)
  int d_digits = 21;  // of d, L, r and S (fewer when d is known to fewer digits)
  std::string label;  // the packing's name (t22a), written in the header when given
  // Text in the unit-triangle convention: decimal strings beyond long double (an MPFR polish),
  // written in place of d and of the coordinates when given (precise_points: one per point).
  std::string precise_d;
  const std::vector<std::array<std::string, 2>>* precise_points = nullptr;
  std::vector<std::string> comments;  // extra "# ..." header lines (the text format only)
};

// Text: comment lines "# key: value" (n, d, class, k, p, variant), then one "x y" per line; in
// the radius convention "x y r" lines (the layout that implies it), in unit-disk-side "x y"
// lines with S in the header.
void write_text(std::ostream& out, const Pattern& pattern, const WriteOptions& options = {});
// CSV: header "index,x,y,rattler", one row per disk (another convention: a comment line first).
void write_csv(std::ostream& out, const Pattern& pattern, const WriteOptions& options = {});
// JSON: {"n", "d" (string, 21 digits), "L", "class", "k", "p", "variant", "convention",
//        "points": [[x, y], ...] (numbers), "points_decimal": [["x", "y"], ...] (21-digit strings),
//        "rattlers": [...], "bonds": [[i, j] or [i, "left"], ...]}; in another convention also
//        "r" (the circles' radius in the file's units) and "side" (the container's side).
void write_json(std::ostream& out, const Pattern& pattern, const WriteOptions& options = {});

// A record table: every real number is a decimal string formatted by the caller, so digits
// beyond long double (an MPFR polish) reach the file unchanged.
struct RecordsTable {
  std::string label;       // the packing's name (t22a); may be empty
  std::string class_name;  // e.g. "even-ripple k=3"; may be empty
  std::string d;           // minimum distance of the centres in the side-1 triangle
  std::string r;           // radius of n circles in the side-1 triangle
  std::string S;           // side of the smallest triangle holding n unit circles
  std::string L;           // 1 / d
  std::size_t bonds = 0;
  std::vector<int> rattlers;  // 0-based disk indices
  // Centres in the unit triangle, or in `convention` (see WriteOptions).
  std::vector<std::pair<std::string, std::string>> points;
  Convention convention = Convention::UnitTriangle;
};
// Formats a pattern's numbers from long double with `digits` significant digits (capped at 21,
// a long double's round trip), the points converted to `convention`. The label is left empty:
// ranking packings is the caller's job.
RecordsTable records_table(const Pattern& pattern, int digits,
                           Convention convention = Convention::UnitTriangle);
// "# key: value" header lines (n, label, class, d, r, S, L, bonds, rattlers, the convention and
// "# layout: i x y"), then one "i x y" line per disk, i 0-based.
void write_records(std::ostream& out, const RecordsTable& table);

// What a points file holds. No validation beyond syntax and finiteness: geometry belongs to
// packing_from_points (core/points.hpp).
struct PointsFile {
  std::vector<Vec2L> points;  // in file order, or ordered by index when the file has an index
  std::optional<long double> radius;      // an "x y r" file: circles of this radius (radius
                                          // convention implied)
  std::optional<long double> declared_d;  // a "# d: value" header line or JSON "d", if any
  std::string layout;  // "x y", "x y r", "i x y", "csv", "json points", "json list"
  // A "# convention: NAME ..." comment line or JSON "convention" naming one of the three
  // conventions (other words there are ignored).
  std::optional<Convention> declared_convention;
  // A "# n: N" line or JSON "n": the number of points the file says it holds
  // (packing_from_points refuses any other count: a truncated file is an error, not a packing).
  std::optional<long long> declared_n;
  // A "# label: t22a" line or JSON "label": the packing's name, carried to what is written.
  std::string declared_label;
};

// Layouts read:
//  * text: "x y"; "x y r" (r the same > 0 on every line); "i x y" (the indices a permutation of
//    0..n-1 or 1..n, in any order). Three columns read as "x y r" when the third is constant and
//    > 0, else as "i x y" when the first is a permutation, else an error naming both readings;
//    a comment line "# layout: x y r" (or "i x y", "x y") decides instead. "#" comments and
//    blank lines are skipped.
//  * records: text whose three columns are "i x y" (unless a layout comment says otherwise).
//  * CSV: a header naming the columns (x, y; optional index/i/id, r/radius, rattler; others
//    ignored; any order, any case) or none: then "x,y", three columns told apart as in text, or
//    "index,x,y,rattler". An index column orders the points; an r column gives the radius.
//  * JSON: {"points": [[x, y], ...]} (preferring "points_decimal", or "points_exact" from older
//  files, of the same length), or
//    {"points": [{"x": .., "y": ..}, ...]}, or a bare list of either; numbers or decimal
//    strings, read to long double.
// Text and CSV comment lines "# d: ...", "# convention: NAME ...", "# n: N" and "# label: L"
// (JSON: "d", "convention", "n", "label") fill the declared_ fields.
// Errors are InputError, one line naming the file line (JSON: the point's position).
// The readers of the format table (formats/formats.hpp), which chooses one by extension.
PointsFile read_text_points(std::istream& in);
PointsFile read_records_points(std::istream& in);  // text whose 3 columns are "i x y"
PointsFile read_csv_points(std::istream& in);
PointsFile read_json_points(std::istream& in);

// One CSV line of fields (csv_field each), commas between them.
void csv_row(std::ostream& out, const std::vector<std::string>& fields);

// The directory, created if needed, checked writable; throws "cannot write to directory 'NAME'".
// Called before any work, so a long run cannot end in an unwritable place.
std::filesystem::path writable_directory(const std::string& name);

// Writes `bytes` to `path` whole (replacing it); throws std::runtime_error "cannot write PATH:
// reason" on failure.
void write_whole_file(const std::filesystem::path& path, const std::string& bytes);

// A CSV field as is, or quoted (with doubled quotes) when it holds a comma, quote or line break
// (RFC 4180), so plain names stay plain.
inline std::string csv_field(const std::string& field) {
  if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace tripack
