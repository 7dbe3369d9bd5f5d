#include "formats/tables.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
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

std::vector<TableRecord> read_table(const std::filesystem::path& csv, const TableFormat& format,
                                    bool missing_is_empty) {
  std::ifstream in(csv);
  if (!in) {
    if (missing_is_empty) return {};
    throw std::runtime_error("cannot read the " + format.what + " " + csv.string());
  }
  std::string line;
  std::vector<TableRecord> rows;
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
             table_header(format).substr(
                 0, std::min<std::size_t>(200, table_header(format).size() - 1)) +
             ")");
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

std::set<std::string> keys_in_table(const std::filesystem::path& csv, const TableFormat& format,
                                    std::size_t key_column,
                                    const std::function<bool(const TableRecord&)>& counts) {
  std::set<std::string> keys;
  for (const auto& row : read_table(csv, format, true))
    if (!counts || counts(row)) keys.insert(row.fields.at(key_column));
  return keys;
}

void sort_table(const std::filesystem::path& csv, const TableFormat& format, std::size_t key_column,
                const std::vector<std::string>& order) {
  std::map<std::string, std::size_t> rank;
  for (std::size_t i = 0; i < order.size(); ++i) rank.emplace(order[i], i);
  std::map<std::string, std::vector<std::string>> last;  // a key's last row wins
  std::vector<std::string> keys;                         // in the file's order
  for (auto& row : read_table(csv, format, true)) {
    const std::string key = row.fields.at(key_column);
    if (!last.count(key)) keys.push_back(key);
    last[key] = std::move(row.fields);
  }
  std::stable_sort(keys.begin(), keys.end(), [&](const std::string& a, const std::string& b) {
    const auto ra = rank.find(a), rb = rank.find(b);
    return (ra == rank.end() ? order.size() : ra->second) <
           (rb == rank.end() ? order.size() : rb->second);
  });
  std::string text = table_header(format);
  for (const auto& key : keys) text += table_line(last[key]);
  const std::filesystem::path temporary = csv.string() + ".tmp";
  {
    std::ofstream out(temporary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  std::filesystem::rename(temporary, csv);
}

}  // namespace tripack
