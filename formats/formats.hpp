// The one table of packing-file formats (docs/formats.md): name, extensions, reader, writer. A
// new format is its file in formats/ (a writer, and a reader if it can be read) plus its line in
// packing_formats() (formats/formats.cpp); every reader and writer of packing files goes through
// this table, and the help lists the formats from it.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "core/io.hpp"
#include "core/record.hpp"

namespace tripack {

struct PackingFormat {
  std::string name;                     // on the command line (--format): txt, csv, ...
  std::vector<std::string> extensions;  // ".txt", ...; the first is the one written
  // Reads the points of a file (nullptr: the format is written only).
  PointsFile (*read)(std::istream& in) = nullptr;
  // Writes one packing with options.digits significant digits of the coordinates and
  // options.d_digits of d: beyond long double from the record's MPFR digits when it has them,
  // else at most kLongDoubleRoundTripDigits (what a long double holds).
  void (*write)(std::ostream& out, const PackingRecord& record,
                const WriteOptions& options) = nullptr;
  std::string description;
};

const std::vector<PackingFormat>& packing_formats();
// nullptr for a name no format has.
const PackingFormat* find_format(const std::string& name);
// By the path's extension; the text format for any other.
const PackingFormat& format_of_path(const std::string& path);
// By the path's extension; nullptr for an extension no format has.
const PackingFormat* format_of_extension(const std::string& path);
// The format called `name` given to `option`; throws "OPTION must be one of txt, csv, ...".
const PackingFormat& format_named(const std::string& name, const std::string& option);

// The points of a packing file, read by its format (by extension; text for any other). Errors
// are InputError, one line prefixed with the path.
PointsFile read_packing_file(const std::string& path);
// "txt, csv, json, records, xyz": for one-line errors.
std::string format_names();

// The writer of the path's format, the file written whole; throws InputError naming the path.
void write_packing_file(const std::string& path, const PackingRecord& record,
                        const WriteOptions& options);

// The record's coordinates as decimal strings with `digits` significant digits, in the unit
// triangle: its MPFR digits (rounded) when it has them and more than a long double's are asked
// for, else long double's. Empty when the request needs nothing beyond long double.
PrecisePoints coordinates_beyond_long_double(const PackingRecord& record, int digits);

}  // namespace tripack
