// Reading and writing packings: plain "x y" text, CSV and JSON.
// Coordinates are written with 21 significant digits (round-trip exact for long double) in text
// and CSV; JSON numbers are doubles (17 digits), so JSON also carries them as strings.
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/packing.hpp"

namespace tripack {

enum class FileFormat { Text, Csv, Json };

// Chosen by extension: .csv -> CSV, .json -> JSON, anything else -> text.
FileFormat format_from_path(const std::string& path);

// Thrown on unreadable or malformed input; the message is one line naming the place.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Text: comment lines "# key: value" (n, d, class, k, p, variant), then one "x y" per line.
void write_text(std::ostream& out, const Pattern& pattern);
// CSV: header "index,x,y,rattler", one row per disk.
void write_csv(std::ostream& out, const Pattern& pattern);
// JSON: {"n", "d" (string, 21 digits), "L", "class", "k", "p", "variant", "convention",
//        "points": [[x, y], ...] (numbers), "points_exact": [["x", "y"], ...] (21-digit strings),
//        "rattlers": [...], "bonds": [[i, j] or [i, "left"], ...]}.
void write_json(std::ostream& out, const Pattern& pattern);
void write_pattern(const std::string& path, const Pattern& pattern);

// Reads points (any of the three formats; JSON needs a "points" array). No validation beyond
// syntax and finiteness: geometry checks belong to the caller.
// JSON prefers "points_exact" when present.
std::vector<Vec2L> read_points(std::istream& in, FileFormat format);
std::vector<Vec2L> read_points_file(const std::string& path);

// Decimal string of a long double with `digits` significant digits.
std::string format_significant(long double value, int digits);

}  // namespace tripack
