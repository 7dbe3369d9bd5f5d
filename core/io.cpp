#include "core/io.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string_view>

#include "core/conventions.hpp"

namespace tripack {

namespace {

// What the header of a file in convention c says about its container and circles.
std::string convention_comment(Convention c, const std::string& r, const std::string& S) {
  switch (c) {
    case Convention::UnitTriangle:
      return "unit-triangle (centres in the triangle (0,0) (1,0) (1/2,sqrt3/2))";
    case Convention::Radius:
      return "radius (centres of circles of radius r = " + r +
             " in the triangle (0,0) (1,0) (1/2,sqrt3/2))";
    case Convention::UnitDiskSide:
      return "unit-disk-side (centres of circles of radius 1 in the triangle (0,0) (S,0) "
             "(S/2,S sqrt3/2), S = " +
             S + ")";
  }
  return "";
}

// The pattern's points in convention c.
std::vector<Vec2L> points_in(const Pattern& pattern, Convention c) {
  std::vector<Vec2L> pts;
  pts.reserve(pattern.packing.size());
  for (const auto& p : pattern.packing.points)
    pts.push_back(point_in_convention(p, pattern.packing.d, c));
  return pts;
}

std::vector<char> rattler_mask(const Pattern& p) {
  std::vector<char> m(p.packing.size(), 0);
  for (int r : p.rattlers) m[static_cast<std::size_t>(r)] = 1;
  return m;
}

}  // namespace

void write_text(std::ostream& out, const Pattern& pattern, const WriteOptions& options) {
  const auto& pk = pattern.packing;
  const auto& pv = pattern.provenance;
  const Convention c = options.convention;
  auto text = [&](long double v) { return format_significant(v, options.digits); };
  auto value = [&](long double v) { return format_significant(v, options.d_digits); };
  const std::string r = value(radius_from_d(pk.d)), S = value(side_from_d(pk.d));
  if (c == Convention::UnitTriangle) {
    out << "# tripack packing, unit-triangle convention: vertices (0,0) (1,0) (1/2,sqrt3/2)\n";
  } else {
    out << "# tripack packing; d is the minimum distance of the centres scaled to the unit "
           "triangle\n";
    out << "# convention: " << convention_comment(c, r, S) << "\n";
    out << "# layout: " << (c == Convention::Radius ? "x y r" : "x y") << "\n";
  }
  out << "# n: " << pk.size() << "\n";
  if (!options.label.empty()) out << "# label: " << options.label << "\n";
  out << "# d: " << (options.precise_d.empty() ? value(pk.d) : options.precise_d) << "\n";
  if (c == Convention::Radius) out << "# r: " << r << "\n";
  if (c == Convention::UnitDiskSide) out << "# S: " << S << "\n";
  if (!pv.class_id.empty()) {
    out << "# class: " << pv.class_id << "\n# k: " << pv.k << "\n";
    if (pv.p) out << "# p: " << pv.p << "\n";
    if (!pv.variant.empty()) out << "# variant: " << pv.variant << "\n";
  }
  out << "# bonds: " << pattern.bonds.size() << "\n# rattlers:";
  for (int r : pattern.rattlers) out << ' ' << r;
  out << "\n";
  for (const auto& line : options.comments) out << "# " << line << "\n";
  const bool precise = c == Convention::UnitTriangle && options.precise_points &&
                       options.precise_points->size() == pk.size();
  if (precise) {
    for (const auto& p : *options.precise_points) out << p[0] << ' ' << p[1] << "\n";
    return;
  }
  for (const auto& p : points_in(pattern, c)) {
    out << text(p.x) << ' ' << text(p.y);
    if (c == Convention::Radius) out << ' ' << r;
    out << "\n";
  }
}

void write_csv(std::ostream& out, const Pattern& pattern, const WriteOptions& options) {
  const auto mask = rattler_mask(pattern);
  const Convention c = options.convention;
  auto text = [&](long double v) { return format_significant(v, options.digits); };
  auto value = [&](long double v) { return format_significant(v, options.d_digits); };
  const long double d = pattern.packing.d;
  if (c != Convention::UnitTriangle)
    out << "# convention: " << convention_comment(c, value(radius_from_d(d)), value(side_from_d(d)))
        << "\n";
  if (!options.label.empty()) out << "# label: " << options.label << "\n";
  out << "index,x,y,rattler\n";
  const auto pts = points_in(pattern, c);
  for (std::size_t i = 0; i < pts.size(); ++i)
    out << i << ',' << text(pts[i].x) << ',' << text(pts[i].y) << ',' << int(mask[i]) << "\n";
}

void write_json(std::ostream& out, const Pattern& pattern, const WriteOptions& options) {
  using nlohmann::json;
  const auto& pk = pattern.packing;
  const Convention c = options.convention;
  auto text = [&](long double v) { return format_significant(v, options.digits); };
  auto value = [&](long double v) { return format_significant(v, options.d_digits); };
  json j;
  j["convention"] = std::string(convention_name(c));
  if (!options.label.empty()) j["label"] = options.label;
  if (c != Convention::UnitTriangle) {
    j["r"] = c == Convention::Radius ? value(radius_from_d(pk.d)) : std::string("1");
    j["side"] = c == Convention::Radius ? std::string("1") : value(side_from_d(pk.d));
  }
  j["n"] = pk.size();
  j["d"] = value(pk.d);
  j["L"] = value(1.0L / pk.d);
  j["class"] = pattern.provenance.class_id;
  j["k"] = pattern.provenance.k;
  j["p"] = pattern.provenance.p;
  j["variant"] = pattern.provenance.variant;
  json pts = json::array(), decimal = json::array();
  for (const auto& p : points_in(pattern, c)) {
    pts.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
    decimal.push_back({text(p.x), text(p.y)});
  }
  j["points"] = std::move(pts);
  j["points_decimal"] = std::move(decimal);
  j["rattlers"] = pattern.rattlers;
  json bonds = json::array();
  for (const auto& b : pattern.bonds) {
    if (b.is_wall())
      bonds.push_back({b.a, std::string(side_name(b.side()))});
    else
      bonds.push_back({b.a, b.b});
  }
  j["bonds"] = std::move(bonds);
  out << j.dump(1) << "\n";
}

RecordsTable records_table(const Pattern& pattern, int digits, Convention convention) {
  // 21 significant digits already round-trip a long double: more would print noise.
  digits = std::clamp(digits, 1, 21);
  auto text = [digits](long double v) { return format_significant(v, digits); };
  const auto& pk = pattern.packing;
  const auto& pv = pattern.provenance;
  RecordsTable t;
  if (!pv.class_id.empty()) {
    t.class_name = pv.class_id;
    if (pv.p) t.class_name += " p=" + std::to_string(pv.p);
    t.class_name += " k=" + std::to_string(pv.k);
    if (!pv.variant.empty()) t.class_name += " variant=" + pv.variant;
  }
  t.d = text(pk.d);
  t.r = text(radius_from_d(pk.d));
  t.S = text(side_from_d(pk.d));
  t.L = text(1 / pk.d);
  t.bonds = pattern.bonds.size();
  t.rattlers = pattern.rattlers;
  t.convention = convention;
  for (const auto& p : points_in(pattern, convention)) t.points.emplace_back(text(p.x), text(p.y));
  return t;
}

void write_records(std::ostream& out, const RecordsTable& table) {
  if (table.convention == Convention::UnitTriangle) {
    out << "# tripack record table: n equal disks, centres in the unit triangle "
           "(0,0) (1,0) (1/2,sqrt3/2)\n";
    out << "# i is 0-based; d = minimum distance of the centres; r = radius of n circles in the\n";
  } else {
    out << "# tripack record table: n equal disks, centres in the convention below\n";
    out << "# i is 0-based; d = minimum distance of the centres scaled to the unit triangle; r = "
           "radius of n circles in the\n";
  }
  out << "# side-1 triangle; S = side of the smallest triangle holding n circles of radius 1; "
         "L = 1/d\n";
  if (table.convention == Convention::UnitTriangle)
    out << "# convention: unit-triangle (centres)\n";
  else
    out << "# convention: " << convention_comment(table.convention, table.r, table.S) << "\n";
  out << "# layout: i x y\n";
  out << "# n: " << table.points.size() << "\n";
  if (!table.label.empty()) out << "# label: " << table.label << "\n";
  if (!table.class_name.empty()) out << "# class: " << table.class_name << "\n";
  out << "# d: " << table.d << "\n";
  out << "# r: " << table.r << "\n";
  out << "# S: " << table.S << "\n";
  out << "# L: " << table.L << "\n";
  out << "# bonds: " << table.bonds << "\n";
  out << "# rattlers:";
  for (int r : table.rattlers) out << ' ' << r;
  out << "\n";
  for (std::size_t i = 0; i < table.points.size(); ++i)
    out << i << ' ' << table.points[i].first << ' ' << table.points[i].second << "\n";
}

// ---------------------------------------------------------------------------------------------
// Reading

namespace {

// One data line of a text or CSV file: its 1-based line number and its fields, trimmed.
struct Row {
  int line = 0;
  std::vector<std::string> fields;
};

// The data rows of a text or CSV file and what its comment lines declare.
struct Scanned {
  std::vector<Row> rows;
  std::optional<std::string> layout;  // from "# layout: ..."
  int layout_line = 0;
  std::optional<long double> declared_d;          // from "# d: ..."
  std::optional<Convention> declared_convention;  // from "# convention: NAME ..."
  std::optional<long long> declared_n;            // from "# n: ..."
  std::string declared_label;                     // from "# label: ..."
};

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::string lowercase(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string at_line(int line) {
  return "line " + std::to_string(line);
}

// Strict: the whole field is one number (std::stold alone would accept "1.5abc").
bool parse_real(std::string_view field, long double& value) {
  const std::string s(trim(field));
  if (s.empty()) return false;
  std::size_t used = 0;
  try {
    value = std::stold(s, &used);
  } catch (...) {
    return false;
  }
  return used == s.size();
}

std::optional<long long> parse_integer(std::string_view field) {
  const auto s = trim(field);
  long long value = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

const std::vector<std::string> kTextLayouts = {"x y", "x y r", "i x y"};

// "# layout: i x y" names the columns of a text file; "# d: 0.17..." is checked against the
// points by packing_from_points. Other comments are ignored.
void read_comment(std::string_view body, int line, bool text_layouts, Scanned& s) {
  body = trim(body);
  const std::string lower = lowercase(body);
  if (text_layouts && lower.starts_with("layout:")) {
    std::istringstream words(lower.substr(7));
    std::string word, layout;
    while (words >> word) layout += (layout.empty() ? "" : " ") + word;
    if (std::find(kTextLayouts.begin(), kTextLayouts.end(), layout) == kTextLayouts.end())
      throw InputError(at_line(line) + ": unknown layout '" + layout +
                       "' (known: 'x y', 'x y r', 'i x y')");
    if (s.layout && *s.layout != layout)
      throw InputError(at_line(line) + ": layout '" + layout + "' contradicts " +
                       at_line(s.layout_line) + "'s '" + *s.layout + "'");
    s.layout = layout;
    s.layout_line = line;
  } else if (lower.starts_with("convention:")) {
    // The first word, when it names a convention (tripack's own headers add a description).
    std::istringstream words(lower.substr(11));
    std::string first;
    if (words >> first) {
      if (const auto c = parse_convention(first)) {
        if (s.declared_convention && *s.declared_convention != *c)
          throw InputError(at_line(line) + ": convention '" + first +
                           "' contradicts an earlier convention line");
        s.declared_convention = c;
      }
    }
  } else if (lower.starts_with("n:")) {
    std::istringstream words(std::string(body.substr(2)));
    std::string first;
    if (words >> first)
      if (const auto n = parse_integer(first)) s.declared_n = *n;
  } else if (lower.starts_with("label:")) {
    std::istringstream words(std::string(body.substr(6)));
    std::string first;
    if (words >> first) s.declared_label = first;
  } else if (lower.starts_with("d:")) {
    std::istringstream words(std::string(body.substr(2)));
    std::string first;
    long double d = 0;
    if (words >> first && parse_real(first, d) && std::isfinite(d) && d > 0) s.declared_d = d;
  }
}

// Splits every non-comment, non-blank line: on `separator`, or on whitespace when it is 0.
Scanned scan(std::istream& in, char separator) {
  Scanned s;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    const auto content = trim(line);
    if (content.empty()) continue;
    if (content.front() == '#') {
      read_comment(content.substr(1), lineno, separator == 0, s);
      continue;
    }
    Row row{lineno, {}};
    if (separator == 0) {
      std::istringstream words{std::string(content)};
      std::string f;
      while (words >> f) row.fields.push_back(f);
    } else {
      std::istringstream cells{std::string(content)};
      std::string f;
      while (std::getline(cells, f, separator)) {
        auto v = trim(f);
        // Quoted fields: high-precision numbers travel as strings in CSV (docs/formats.md).
        if (v.size() >= 2 && v.front() == '"' && v.back() == '"') v = v.substr(1, v.size() - 2);
        row.fields.emplace_back(v);
      }
      if (content.back() == separator) row.fields.emplace_back();  // "1,2," has 3 fields
    }
    s.rows.push_back(std::move(row));
  }
  if (in.bad()) throw InputError("read error");
  return s;
}

long double real_at(const Row& row, int column) {
  const std::string& f = row.fields[static_cast<std::size_t>(column)];
  long double v = 0;
  if (!parse_real(f, v)) throw InputError(at_line(row.line) + ": '" + f + "' is not a number");
  return v;
}

long double coordinate_at(const Row& row, int column) {
  const long double v = real_at(row, column);
  if (!std::isfinite(v))
    throw InputError(at_line(row.line) + ": coordinate '" +
                     row.fields[static_cast<std::size_t>(column)] + "' is not a finite number");
  return v;
}

// Why `column` is not one radius > 0 on every row, or nothing when it is.
std::optional<std::string> radius_problem(const std::vector<Row>& rows, int column) {
  const auto c = static_cast<std::size_t>(column);
  const Row& first = rows.front();
  const long double r = real_at(first, column);
  if (!(r > 0) || !std::isfinite(r))
    return at_line(first.line) + ": r = " + first.fields[c] + " is not a finite number > 0";
  for (const auto& row : rows)
    if (real_at(row, column) != r)
      return at_line(row.line) + ": r = " + row.fields[c] + " differs from " + at_line(first.line) +
             "'s r = " + first.fields[c];
  return std::nullopt;
}

// Why `column` is not a permutation of 0..n-1 or 1..n, or nothing when it is; `order` then gets
// the row of each index.
std::optional<std::string> index_problem(const std::vector<Row>& rows, int column,
                                         std::vector<std::size_t>* order = nullptr) {
  const auto c = static_cast<std::size_t>(column);
  std::vector<long long> index;
  for (const auto& row : rows) {
    const auto i = parse_integer(row.fields[c]);
    if (!i) return at_line(row.line) + ": index '" + row.fields[c] + "' is not an integer";
    index.push_back(*i);
  }
  const auto lowest = std::min_element(index.begin(), index.end());
  const long long base = *lowest;
  const auto n = static_cast<long long>(rows.size());
  if (base != 0 && base != 1)
    return at_line(rows[static_cast<std::size_t>(lowest - index.begin())].line) +
           ": the smallest index is " + std::to_string(base) + "; indices must run 0.." +
           std::to_string(n - 1) + " or 1.." + std::to_string(n);
  std::vector<int> line_of(rows.size(), 0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const long long slot = index[k] - base;
    if (slot >= n)
      return at_line(rows[k].line) + ": index " + std::to_string(index[k]) + " is beyond " +
             std::to_string(base) + ".." + std::to_string(base + n - 1) + " (" + std::to_string(n) +
             " points)";
    auto& seen = line_of[static_cast<std::size_t>(slot)];
    if (seen)
      return at_line(rows[k].line) + ": index " + std::to_string(index[k]) + " repeats " +
             at_line(seen);
    seen = rows[k].line;
  }
  if (order) {
    order->assign(rows.size(), 0);
    for (std::size_t k = 0; k < rows.size(); ++k)
      (*order)[static_cast<std::size_t>(index[k] - base)] = k;
  }
  return std::nullopt;
}

// Which field holds what; -1 = absent.
struct Columns {
  int x = -1, y = -1, index = -1, r = -1;
};

Columns columns_of_layout(const std::string& layout) {
  if (layout == "x y") return {0, 1, -1, -1};
  if (layout == "x y r") return {0, 1, -1, 2};
  return {1, 2, 0, -1};  // "i x y"
}

// Three numbers a line: "x y r" when the third is one radius > 0 throughout, else "i x y" when
// the first is a permutation, else neither (the error names both readings).
std::string guess_three_columns(const std::vector<Row>& rows) {
  const auto as_radius = radius_problem(rows, 2);
  if (!as_radius) return "x y r";
  const auto as_index = index_problem(rows, 0);
  if (!as_index) return "i x y";
  throw InputError("3 columns read neither as 'x y r' (" + *as_radius + ") nor as 'i x y' (" +
                   *as_index + "); a comment line '# layout: x y r' or '# layout: i x y' decides");
}

// The points of `rows` by `columns`: ordered by the index column when there is one; the radius
// column must hold one value > 0.
PointsFile assemble(const std::vector<Row>& rows, const Columns& columns) {
  PointsFile file;
  if (rows.empty()) return file;
  std::vector<std::size_t> order(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) order[k] = k;
  if (columns.index >= 0)
    if (auto problem = index_problem(rows, columns.index, &order)) throw InputError(*problem);
  if (columns.r >= 0) {
    if (auto problem = radius_problem(rows, columns.r)) throw InputError(*problem);
    file.radius = real_at(rows.front(), columns.r);
  }
  for (std::size_t k : order)
    file.points.push_back({coordinate_at(rows[k], columns.x), coordinate_at(rows[k], columns.y)});
  return file;
}

PointsFile read_text(std::istream& in, bool records) {
  const Scanned s = scan(in, 0);
  // Who decided the layout, for the error messages.
  std::string layout, decided_by;
  if (s.layout) {
    layout = *s.layout;
    decided_by = "as " + at_line(s.layout_line) + " says";
  } else if (records) {
    layout = "i x y";
    decided_by = "a records file";
  }
  if (!s.rows.empty()) {
    const Row& first = s.rows.front();
    const std::size_t width = layout.empty() ? first.fields.size() : (layout == "x y" ? 2 : 3);
    if (layout.empty() && width != 2 && width != 3)
      throw InputError(at_line(first.line) + ": expected 2 or 3 numbers ('x y', 'x y r' or " +
                       "'i x y'), got " + std::to_string(width));
    for (const auto& row : s.rows) {
      if (row.fields.size() != width)
        throw InputError(
            at_line(row.line) + ": expected " + std::to_string(width) + " numbers (" +
            (layout.empty() ? "like " + at_line(first.line) : "'" + layout + "', " + decided_by) +
            "), got " + std::to_string(row.fields.size()));
      for (std::size_t c = 0; c < width; ++c) real_at(row, static_cast<int>(c));
    }
    if (layout.empty()) layout = width == 2 ? "x y" : guess_three_columns(s.rows);
  } else if (layout.empty()) {
    layout = "x y";
  }
  PointsFile file = assemble(s.rows, columns_of_layout(layout));
  file.layout = layout;
  file.declared_d = s.declared_d;
  file.declared_convention = s.declared_convention;
  file.declared_n = s.declared_n;
  file.declared_label = s.declared_label;
  return file;
}

// The column a CSV header name stands for.
int* role_of(const std::string& name, Columns& c) {
  if (name == "x") return &c.x;
  if (name == "y") return &c.y;
  if (name == "index" || name == "i" || name == "id") return &c.index;
  if (name == "r" || name == "radius") return &c.r;
  return nullptr;  // rattler flags and unknown columns are not needed for the points
}

PointsFile read_csv(std::istream& in) {
  Scanned s = scan(in, ',');
  PointsFile file;
  file.layout = "csv";
  file.declared_d = s.declared_d;
  file.declared_convention = s.declared_convention;
  file.declared_n = s.declared_n;
  file.declared_label = s.declared_label;
  if (s.rows.empty()) return file;
  const Row& first = s.rows.front();
  const bool has_header = std::any_of(first.fields.begin(), first.fields.end(), [](auto& f) {
    long double v = 0;
    return !parse_real(f, v);
  });
  Columns columns;
  std::vector<Row> data(s.rows.begin() + (has_header ? 1 : 0), s.rows.end());
  if (has_header) {
    for (std::size_t c = 0; c < first.fields.size(); ++c) {
      const std::string name = lowercase(first.fields[c]);
      int* role = role_of(name, columns);
      if (!role) continue;
      if (*role >= 0) throw InputError(at_line(first.line) + ": two columns name '" + name + "'");
      *role = static_cast<int>(c);
    }
    if (columns.x < 0 || columns.y < 0)
      throw InputError(at_line(first.line) + ": the header names no '" +
                       (columns.x < 0 ? "x" : "y") + "' column");
  } else if (first.fields.size() == 2) {
    columns = {0, 1, -1, -1};
  } else if (first.fields.size() == 3) {
    for (const auto& row : data)
      if (row.fields.size() != 3)
        throw InputError(at_line(row.line) + ": " + std::to_string(row.fields.size()) +
                         " fields, expected 3 like " + at_line(first.line));
    columns = columns_of_layout(guess_three_columns(data));
  } else if (first.fields.size() == 4) {
    columns = {1, 2, 0, -1};  // the writer's index,x,y,rattler
  } else {
    throw InputError(at_line(first.line) + ": expected 'x,y' or 'index,x,y[,rattler]', got " +
                     std::to_string(first.fields.size()) + " fields and no header");
  }
  for (const auto& row : data)
    if (row.fields.size() != first.fields.size())
      throw InputError(at_line(row.line) + ": " + std::to_string(row.fields.size()) +
                       " fields, expected " + std::to_string(first.fields.size()) + " like " +
                       at_line(first.line));
  PointsFile points = assemble(data, columns);
  file.points = std::move(points.points);
  file.radius = points.radius;
  return file;
}

// number_float_t = long double: the parser then reads 21-digit numbers without rounding them to
// double first.
using LongJson = nlohmann::basic_json<std::map, std::vector, std::string, bool, std::int64_t,
                                      std::uint64_t, long double>;

// A number, or a decimal string (how JSON carries digits beyond a double's).
std::optional<long double> json_real(const LongJson& v) {
  long double x = 0;
  if (v.is_number()) return v.get<long double>();
  if (v.is_string() && parse_real(v.get<std::string>(), x)) return x;
  return std::nullopt;
}

long double json_coordinate(const LongJson& v, const std::string& where) {
  const auto x = json_real(v);
  if (!x) throw InputError(where + ": a coordinate is neither a number nor a decimal string");
  if (!std::isfinite(*x)) throw InputError(where + ": coordinate is not a finite number");
  return *x;
}

std::vector<Vec2L> json_point_list(const LongJson& list) {
  std::vector<Vec2L> pts;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto& p = list[k];
    const std::string where = "point " + std::to_string(k);
    if (p.is_array() && p.size() == 2)
      pts.push_back({json_coordinate(p[0], where), json_coordinate(p[1], where)});
    else if (p.is_object() && p.contains("x") && p.contains("y"))
      pts.push_back({json_coordinate(p["x"], where), json_coordinate(p["y"], where)});
    else
      throw InputError(where + ": expected [x, y] or {\"x\": .., \"y\": ..}");
  }
  return pts;
}

PointsFile read_json(std::istream& in) {
  LongJson j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw InputError(std::string("malformed JSON: ") + e.what());
  }
  PointsFile file;
  // write_json's d, checked against the points like a "# d:" header line.
  if (j.is_object() && j.contains("d"))
    if (const auto d = json_real(j["d"]); d && *d > 0 && std::isfinite(*d)) file.declared_d = d;
  if (j.is_object() && j.contains("convention") && j["convention"].is_string())
    file.declared_convention = parse_convention(j["convention"].get<std::string>());
  if (j.is_object() && j.contains("n") && j["n"].is_number_integer())
    file.declared_n = j["n"].get<long long>();
  if (j.is_object() && j.contains("label") && j["label"].is_string())
    file.declared_label = j["label"].get<std::string>();
  if (j.is_array()) {
    file.layout = "json list";
    file.points = json_point_list(j);
    return file;
  }
  if (!j.is_object() || !j.contains("points") || !j["points"].is_array())
    throw InputError("JSON has no \"points\" array (nor is it a list of points)");
  // The decimal strings, when they hold every point; files written before 2026-11-29 name them
  // "points_exact" (docs/conventions.md, "Names").
  const char* decimal = j.contains("points_decimal") ? "points_decimal" : "points_exact";
  const bool digits =
      j.contains(decimal) && j[decimal].is_array() && j[decimal].size() == j["points"].size();
  file.layout = "json points";
  file.points = json_point_list(digits ? j[decimal] : j["points"]);
  return file;
}

}  // namespace

PointsFile read_text_points(std::istream& in) {
  return read_text(in, false);
}
PointsFile read_records_points(std::istream& in) {
  return read_text(in, true);
}
PointsFile read_csv_points(std::istream& in) {
  return read_csv(in);
}
PointsFile read_json_points(std::istream& in) {
  return read_json(in);
}

void write_whole_file(const std::filesystem::path& path, const std::string& bytes) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  out.close();
  if (!out) {
    const int why = errno;
    throw std::runtime_error("cannot write " + path.string() + ": " +
                             (why ? std::strerror(why) : "write failed"));
  }
}

void csv_row(std::ostream& out, const std::vector<std::string>& fields) {
  bool first = true;
  for (const auto& f : fields) {
    out << (first ? "" : ",") << csv_field(f);
    first = false;
  }
  out << "\n";
}

std::filesystem::path writable_directory(const std::string& name) {
  const std::filesystem::path dir(name);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir) || access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write to directory '" + name + "'");
  return dir;
}

}  // namespace tripack
