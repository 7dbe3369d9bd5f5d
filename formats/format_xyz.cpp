// Extended XYZ: the disks as particles of radius d/2 in the plane z = 0, with a rattler flag, in
// the unit-triangle convention. OVITO, VMD and ASE read it ("Properties=" names the columns; the
// triangle's corners are in the comment line, since the container is not periodic). Every disk's
// species is X, ASE's dummy element (ASE refuses names that are not elements); the rattler
// column tells rattlers apart.
//
// The comment line's key=value pairs are read by ASE's extxyz parser (ase/io/extxyz.py,
// key_val_str_to_dict), character by character: a backslash escapes the next character anywhere,
// a double quote opens a value that runs to the next unescaped double quote. An empty quoted
// value ("") ends nothing there, so the next key is swallowed into it (label="" bonds=47 reads as
// label = "bonds=47"): an empty value is never written, the key is left out.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>
#include <string>

#include "formats/formats.hpp"

namespace tripack {

namespace {

// ` key="value"` with the value's backslashes and double quotes escaped and its line breaks and
// other control characters (which would end the comment line) as spaces; nothing when the value
// is empty.
std::string quoted_pair(const std::string& key, const std::string& value) {
  if (value.empty()) return {};
  std::string quoted;
  for (const char c : value) {
    if (c == '\\' || c == '"') quoted += '\\';
    quoted += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? ' ' : c;
  }
  return " " + key + "=\"" + quoted + "\"";
}

}  // namespace

void write_extended_xyz(std::ostream& out, const PackingRecord& record,
                        const WriteOptions& options) {
  const auto& points = record.pattern.packing.points;
  const PrecisePoints precise = coordinates_beyond_long_double(record, options.digits);
  const int digits = std::min(options.digits, kLongDoubleRoundTripDigits);
  const std::string radius = PreciseReal(record.d.value() / 2).str(options.d_digits);
  std::vector<char> rattler(points.size(), 0);
  for (int r : record.pattern.rattlers) rattler[static_cast<std::size_t>(r)] = 1;
  out << points.size() << "\n";
  out << fmt::format(
      "Properties=species:S:1:pos:R:3:radius:R:1:rattler:I:1 pbc=\"F F F\" d={}{} bonds={} "
      "triangle=\"0 0 1 0 0.5 0.866025403784438646763723170752936\"\n",
      record.d.str(options.d_digits),
      quoted_pair("label", options.label.empty() ? record.label : options.label), record.bonds());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string x = precise.empty() ? format_significant(points[i].x, digits) : precise[i][0];
    const std::string y = precise.empty() ? format_significant(points[i].y, digits) : precise[i][1];
    out << "X " << x << ' ' << y << " 0 " << radius << ' ' << int(rattler[i]) << "\n";
  }
}

}  // namespace tripack
