#include "formats/tables.hpp"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "core/io.hpp"

namespace tripack {

const TableFormat& atlas_table_format() {
  static const TableFormat f{"atlas table",
                             "atlas.csv",
                             {"n", "rank", "label", "d", "L", "delta", "bonds", "rattlers",
                              "certified", "confirmations", "source", "file", "provenance"}};
  return f;
}

const TableFormat& atlas_gaps_table_format() {
  static const TableFormat f{"atlas gaps table",
                             "atlas-gaps.csv",
                             {"class", "p", "k", "n", "n_label", "next_label", "L_n", "L_next",
                              "L_difference", "delta_difference", "paper_tight"}};
  return f;
}

const TableFormat& exact_atlas_table_format() {
  static const TableFormat f{"exact atlas table",
                             "atlas-exact.csv",
                             {"n", "label", "degree", "polynomial", "root_low", "root_high",
                              "proof", "reason", "seconds"}};
  return f;
}

std::string table_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += csv_field(fields[i]);
  }
  return line + "\n";
}

std::string table_header(const TableFormat& format) {
  return table_line(format.columns);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::vector<TableRow> read_table(const std::filesystem::path& csv, const TableFormat& format,
                                 bool missing_is_empty) {
  std::ifstream in(csv);
  if (!in) {
    if (missing_is_empty) return {};
    throw std::runtime_error("cannot read the " + format.what + " " + csv.string());
  }
  std::string line;
  std::vector<TableRow> rows;
  long long number = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(fmt::format("{}:{}: {}", csv.string(), number, why));
  };
  while (std::getline(in, line)) {
    ++number;
    auto f = split_csv(line);
    if (number == 1) {
      if (f != format.columns)
        fail("not a tripack " + format.what + " (its header is not " +
             table_header(format).substr(0, 200) + ")");
      continue;
    }
    if (line.empty()) continue;
    if (f.size() != format.columns.size())
      fail(fmt::format("{} fields, expected {}", f.size(), format.columns.size()));
    rows.push_back({number, std::move(f)});
  }
  if (number == 0) fail("empty file");
  return rows;
}

}  // namespace tripack
