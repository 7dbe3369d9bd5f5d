// libFuzzer target: the point-file readers (every layout) chained into packing_from_points.
// The first byte picks the reader (text, CSV, JSON, records) and the convention; the rest is the
// file's content. InputError and other std::exceptions are expected; only crashes, hangs, leaks
// and sanitizer reports are findings.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/io.hpp"
#include "core/points.hpp"
#include "formats/formats.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tripack;
  if (size < 1) return 0;
  const std::uint8_t sel = data[0];
  // The readable formats of the table (txt, csv, json, records), in its order.
  static const auto readers = [] {
    std::vector<PointsFile (*)(std::istream&)> r;
    for (const auto& f : packing_formats())
      if (f.read) r.push_back(f.read);
    return r;
  }();
  const auto read = readers[(sel & 3) % readers.size()];
  std::optional<Convention> convention;
  switch ((sel >> 2) & 3) {
    case 1:
      convention = Convention::UnitTriangle;
      break;
    case 2:
      convention = Convention::Radius;
      break;
    case 3:
      convention = Convention::UnitDiskSide;
      break;
    default:
      break;
  }
  std::istringstream in(std::string(reinterpret_cast<const char*>(data + 1), size - 1));
  PointsFile file;
  try {
    file = read(in);
  } catch (const std::exception&) {
    return 0;
  }
  try {
    (void)packing_from_points(std::move(file), convention, std::nullopt);
  } catch (const std::exception&) {
  }
  return 0;
}
