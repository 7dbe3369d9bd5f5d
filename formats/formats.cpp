#include "formats/formats.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "polish/polish_mp.hpp"

namespace tripack {

PrecisePoints coordinates_beyond_long_double(const PackingRecord& record, int digits) {
  if (digits <= kLongDoubleRoundTripDigits ||
      record.precise_points.size() != record.pattern.packing.size())
    return {};
  PrecisePoints points;
  points.reserve(record.precise_points.size());
  for (const auto& p : record.precise_points) {
    const int known = std::max(significant_digits(p[0]), significant_digits(p[1]));
    points.push_back(
        {PreciseReal(0, p[0], known).str(digits), PreciseReal(0, p[1], known).str(digits)});
  }
  return points;
}

namespace {

// The options with the record's digits beyond long double filled in (unit-triangle text only).
WriteOptions with_record_digits(const PackingRecord& record, const WriteOptions& options,
                                const PrecisePoints& precise) {
  WriteOptions o = options;
  if (o.label.empty()) o.label = record.label;
  if (record.d.multiprecision() && o.d_digits > kLongDoubleRoundTripDigits)
    o.precise_d = record.d.str(o.d_digits);
  if (!precise.empty()) o.precise_points = &precise;
  o.digits = std::min(o.digits, kLongDoubleRoundTripDigits);
  o.d_digits = std::min(o.d_digits, kLongDoubleRoundTripDigits);
  return o;
}

void text_writer(std::ostream& out, const PackingRecord& r, const WriteOptions& options) {
  const PrecisePoints precise = coordinates_beyond_long_double(r, options.digits);
  write_text(out, r.pattern, with_record_digits(r, options, precise));
}
void csv_writer(std::ostream& out, const PackingRecord& r, const WriteOptions& options) {
  write_csv(out, r.pattern, with_record_digits(r, options, {}));
}
void json_writer(std::ostream& out, const PackingRecord& r, const WriteOptions& options) {
  write_json(out, r.pattern, with_record_digits(r, options, {}));
}
void records_writer(std::ostream& out, const PackingRecord& r, const WriteOptions& options) {
  RecordsTable table = records_table(
      r.pattern, std::min(options.digits, kLongDoubleRoundTripDigits), options.convention);
  table.label = options.label.empty() ? r.label : options.label;
  table.d = r.d.str(options.d_digits);
  table.L = r.L.str(options.d_digits);
  if (r.d.multiprecision() && options.d_digits > kLongDoubleDigits) {  // MPFR: every digit
    table.r = radius_or_side_from_d(table.d, true, options.d_digits);
    table.S = radius_or_side_from_d(table.d, false, options.d_digits);
  } else {
    table.r = format_significant(radius_from_d(r.d.value()),
                                 std::min(options.d_digits, kLongDoubleDigits));
    table.S =
        format_significant(side_from_d(r.d.value()), std::min(options.d_digits, kLongDoubleDigits));
  }
  const PrecisePoints precise = coordinates_beyond_long_double(r, options.digits);
  if (options.convention == Convention::UnitTriangle)
    for (std::size_t i = 0; i < precise.size() && i < table.points.size(); ++i)
      table.points[i] = {precise[i][0], precise[i][1]};
  write_records(out, table);
}

}  // namespace

// Formats in files of their own.
void write_extended_xyz(std::ostream& out, const PackingRecord& record,
                        const WriteOptions& options);  // formats/format_xyz.cpp

const std::vector<PackingFormat>& packing_formats() {
  static const std::vector<PackingFormat> formats{
      {"txt", {".txt"}, read_text_points, text_writer, "x y lines under a # header"},
      {"csv", {".csv"}, read_csv_points, csv_writer, "index,x,y,rattler"},
      {"json", {".json"}, read_json_points, json_writer, "{\"points\": ..., \"d\": ...}"},
      {"records",
       {".pck", ".records"},
       read_records_points,
       records_writer,
       "i x y lines with d, r, S, L in the header"},
      {"xyz", {".xyz"}, nullptr, write_extended_xyz, "extended XYZ (OVITO, VMD, ASE)"},
  };
  return formats;
}

const PackingFormat* find_format(const std::string& name) {
  for (const auto& f : packing_formats())
    if (f.name == name || (name == "pck" && f.name == "records")) return &f;
  return nullptr;
}

const PackingFormat& format_of_path(const std::string& path) {
  const PackingFormat* f = format_of_extension(path);
  return f ? *f : packing_formats().front();
}

const PackingFormat& format_named(const std::string& name, const std::string& option) {
  if (const PackingFormat* f = find_format(name)) return *f;
  throw std::invalid_argument(option + " must be one of " + format_names() + ", not '" + name +
                              "'");
}

const PackingFormat* format_of_extension(const std::string& path) {
  for (const auto& f : packing_formats())
    for (const auto& ext : f.extensions)
      if (path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0)
        return &f;
  return nullptr;
}

PointsFile read_packing_file(const std::string& path) {
  const PackingFormat& format = format_of_path(path);
  if (!format.read)
    throw InputError(path + ": tripack writes " + format.name + " files but does not read them");
  std::ifstream in(path);
  if (!in) throw InputError("cannot read '" + path + "'");
  try {
    return format.read(in);
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

std::string format_names() {
  std::string names;
  for (const auto& f : packing_formats()) names += (names.empty() ? "" : ", ") + f.name;
  return names;
}

void write_packing_file(const std::string& path, const PackingRecord& record,
                        const WriteOptions& options) {
  std::ostringstream bytes;
  format_of_path(path).write(bytes, record, options);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError("cannot open '" + path + "' for writing");
  out << bytes.str();
  out.close();
  if (!out) throw InputError("failed writing '" + path + "'");
}

}  // namespace tripack
