#include "core/io.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace tripack {

FileFormat format_from_path(const std::string& path) {
  auto ends_with = [&](const char* ext) {
    const std::string e(ext);
    return path.size() >= e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
  };
  if (ends_with(".csv")) return FileFormat::Csv;
  if (ends_with(".json")) return FileFormat::Json;
  return FileFormat::Text;
}

std::string format_significant(long double value, int digits) {
  return fmt::format("{:.{}Lg}", value, digits);
}

namespace {

std::string coord(long double v) {
  return format_significant(v, 21);
}

std::vector<char> rattler_mask(const Pattern& p) {
  std::vector<char> m(p.packing.size(), 0);
  for (int r : p.rattlers) m[static_cast<std::size_t>(r)] = 1;
  return m;
}

}  // namespace

void write_text(std::ostream& out, const Pattern& pattern) {
  const auto& pk = pattern.packing;
  const auto& pv = pattern.provenance;
  out << "# tripack packing, unit-triangle convention: vertices (0,0) (1,0) (1/2,sqrt3/2)\n";
  out << "# n: " << pk.size() << "\n";
  out << "# d: " << format_significant(pk.d, 21) << "\n";
  if (!pv.class_id.empty()) {
    out << "# class: " << pv.class_id << "\n# k: " << pv.k << "\n";
    if (pv.p) out << "# p: " << pv.p << "\n";
    if (!pv.variant.empty()) out << "# variant: " << pv.variant << "\n";
  }
  out << "# bonds: " << pattern.bonds.size() << "\n# rattlers:";
  for (int r : pattern.rattlers) out << ' ' << r;
  out << "\n";
  for (const auto& p : pk.points) out << coord(p.x) << ' ' << coord(p.y) << "\n";
}

void write_csv(std::ostream& out, const Pattern& pattern) {
  const auto mask = rattler_mask(pattern);
  out << "index,x,y,rattler\n";
  for (std::size_t i = 0; i < pattern.packing.size(); ++i) {
    const auto& p = pattern.packing.points[i];
    out << i << ',' << coord(p.x) << ',' << coord(p.y) << ',' << int(mask[i]) << "\n";
  }
}

void write_json(std::ostream& out, const Pattern& pattern) {
  using nlohmann::json;
  const auto& pk = pattern.packing;
  json j;
  j["convention"] = "unit-triangle";
  j["n"] = pk.size();
  j["d"] = format_significant(pk.d, 21);
  j["L"] = format_significant(1.0L / pk.d, 21);
  j["class"] = pattern.provenance.class_id;
  j["k"] = pattern.provenance.k;
  j["p"] = pattern.provenance.p;
  j["variant"] = pattern.provenance.variant;
  json pts = json::array(), exact = json::array();
  for (const auto& p : pk.points) {
    pts.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
    exact.push_back({coord(p.x), coord(p.y)});
  }
  j["points"] = std::move(pts);
  j["points_exact"] = std::move(exact);
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

void write_pattern(const std::string& path, const Pattern& pattern) {
  std::ofstream out(path);
  if (!out) throw InputError("cannot open '" + path + "' for writing");
  switch (format_from_path(path)) {
    case FileFormat::Text:
      write_text(out, pattern);
      break;
    case FileFormat::Csv:
      write_csv(out, pattern);
      break;
    case FileFormat::Json:
      write_json(out, pattern);
      break;
  }
  if (!out) throw InputError("failed writing '" + path + "'");
}

namespace {

Vec2L checked_point(long double x, long double y, const std::string& where) {
  if (!std::isfinite(x) || !std::isfinite(y))
    throw InputError(where + ": coordinate is not a finite number");
  return {x, y};
}

std::vector<Vec2L> read_rows(std::istream& in, bool csv) {
  std::vector<Vec2L> pts;
  std::string line;
  int lineno = 0;
  bool header_allowed = csv;
  while (std::getline(in, line)) {
    ++lineno;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<std::string> fields;
    if (csv) {
      std::stringstream ss(line);
      std::string f;
      while (std::getline(ss, f, ',')) fields.push_back(f);
    } else {
      std::stringstream ss(line);
      std::string f;
      while (ss >> f) fields.push_back(f);
    }
    const std::string where = "line " + std::to_string(lineno);
    auto parse = [&](const std::string& s, long double& v) {
      std::size_t used = 0;
      try {
        v = std::stold(s, &used);
      } catch (...) {
        return false;
      }
      return s.find_first_not_of(" \t\r", used) == std::string::npos;
    };
    if (csv) {
      // index,x,y[,rattler] or x,y
      long double a = 0, b = 0, c = 0;
      const bool with_index = fields.size() >= 3;
      bool ok = with_index ? (parse(fields[0], a) && parse(fields[1], b) && parse(fields[2], c))
                           : (fields.size() == 2 && parse(fields[0], b) && parse(fields[1], c));
      if (!ok && header_allowed) {
        header_allowed = false;
        continue;
      }
      if (!ok)
        throw InputError(where + ": expected 'x,y' or 'index,x,y,...' numbers, got '" + line + "'");
      pts.push_back(checked_point(b, c, where));
    } else {
      long double x = 0, y = 0;
      if (fields.size() != 2 || !parse(fields[0], x) || !parse(fields[1], y))
        throw InputError(where + ": expected two numbers 'x y', got '" + line + "'");
      pts.push_back(checked_point(x, y, where));
    }
    header_allowed = false;
  }
  if (in.bad()) throw InputError("read error");
  return pts;
}

std::vector<Vec2L> read_json_points(std::istream& in) {
  nlohmann::json j;
  try {
    in >> j;
  } catch (const std::exception& e) {
    throw InputError(std::string("malformed JSON: ") + e.what());
  }
  if (!j.is_object() || !j.contains("points") || !j["points"].is_array())
    throw InputError("JSON has no \"points\" array");
  const bool exact = j.contains("points_exact") && j["points_exact"].is_array() &&
                     j["points_exact"].size() == j["points"].size();
  std::vector<Vec2L> pts;
  std::size_t idx = 0;
  for (const auto& p : exact ? j["points_exact"] : j["points"]) {
    const std::string where = "point " + std::to_string(idx++);
    auto value = [&](const nlohmann::json& v) -> long double {
      if (v.is_number()) return v.get<double>();
      if (v.is_string()) {
        try {
          std::size_t used = 0;
          const auto s = v.get<std::string>();
          const long double x = std::stold(s, &used);
          if (used == s.size()) return x;
        } catch (...) {
        }
      }
      throw InputError(where + ": expected [x, y]");
    };
    if (!p.is_array() || p.size() != 2) throw InputError(where + ": expected [x, y]");
    pts.push_back(checked_point(value(p[0]), value(p[1]), where));
  }
  return pts;
}

}  // namespace

std::vector<Vec2L> read_points(std::istream& in, FileFormat format) {
  switch (format) {
    case FileFormat::Text:
      return read_rows(in, false);
    case FileFormat::Csv:
      return read_rows(in, true);
    case FileFormat::Json:
      return read_json_points(in);
  }
  return {};
}

std::vector<Vec2L> read_points_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read '" + path + "'");
  try {
    return read_points(in, format_from_path(path));
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
}

}  // namespace tripack
