// Extended XYZ: the disks as particles of radius d/2 in the plane z = 0, with a rattler flag, in
// the unit-triangle convention. OVITO, VMD and ASE read it ("Properties=" names the columns; the
// triangle's corners are in the comment line, since the container is not periodic). Every disk's
// species is X, ASE's dummy element (ASE refuses names that are not elements); the rattler
// column tells rattlers apart.
#include <fmt/format.h>

#include <algorithm>
#include <ostream>

#include "formats/formats.hpp"

namespace tripack {

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
      "Properties=species:S:1:pos:R:3:radius:R:1:rattler:I:1 pbc=\"F F F\" d={} label=\"{}\" "
      "bonds={} triangle=\"0 0 1 0 0.5 0.866025403784438646763723170752936\"\n",
      record.d.str(options.d_digits), options.label.empty() ? record.label : options.label,
      record.bonds());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string x = precise.empty() ? format_significant(points[i].x, digits) : precise[i][0];
    const std::string y = precise.empty() ? format_significant(points[i].y, digits) : precise[i][1];
    out << "X " << x << ' ' << y << " 0 " << radius << ' ' << int(rattler[i]) << "\n";
  }
}

}  // namespace tripack
