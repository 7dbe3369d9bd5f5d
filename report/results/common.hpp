// What the result families share: the fields every packing-carrying result has (counts, points,
// 17-digit decimals) and the text views' aligned lines and tables.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "core/record.hpp"
#include "report/fields.hpp"
#include "report/render.hpp"

namespace tripack::report::results {

inline Tree optional_string(const std::string& s) {
  return s.empty() ? Tree(nullptr) : Tree(s);
}

inline Tree points_tree(const Packing& packing) {
  Tree points = Tree::array();
  for (const auto& p : packing.points)
    points.push_back({format_significant(p.x, kLongDoubleRoundTripDigits),
                      format_significant(p.y, kLongDoubleRoundTripDigits)});
  return points;
}

// A class member: its class, k, p and variant.
inline Tree member_tree(const Provenance& m) {
  return {{"class", m.class_id},
          {"k", m.k},
          {"p", m.p ? Tree(m.p) : Tree(nullptr)},
          {"variant", optional_string(m.variant)}};
}

// The counts and indices every packing-carrying object has.
inline void add_counts(Tree& j, const Pattern& pattern) {
  j["bonds"] = pattern.bonds.size();
  j["rattlers"] = pattern.rattlers.size();
  j["rattler_indices"] = pattern.rattlers;
}

// A text view's "key value" line, keys in a column of 10 (the text writer's too).
inline void line(std::ostream& out, std::string_view key, const std::string& value) {
  out << fmt::format("{:<10} {}\n", key, value);
}

// Rows of cells as columns, each column as wide as its widest cell (in characters, UTF-8
// aware), two spaces between columns, every line starting with `indent`: a long label or a d
// with more digits widens its column instead of shifting the rest of its row.
inline void aligned_rows(std::ostream& out, std::string_view indent,
                         const std::vector<std::vector<std::string>>& rows) {
  const auto width = [](const std::string& s) {
    return static_cast<std::size_t>(
        std::count_if(s.begin(), s.end(), [](char c) { return (c & 0xC0) != 0x80; }));
  };
  std::vector<std::size_t> widths;
  for (const auto& row : rows)
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (widths.size() <= c) widths.push_back(0);
      widths[c] = std::max(widths[c], width(row[c]));
    }
  for (const auto& row : rows) {
    std::string text(indent);
    for (std::size_t c = 0; c < row.size(); ++c) {
      text += row[c];
      if (c + 1 < row.size()) text += std::string(widths[c] - width(row[c]) + 2, ' ');
    }
    out << text << "\n";
  }
}

// The table of distinct packings of billiards and search: label, d, bonds, rattlers, verdict and
// `found` (where each was found), aligned.
inline void packing_rows(std::ostream& out, const std::vector<PackingRecord>& packings,
                         const std::function<std::string(const PackingRecord&)>& found) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& x : packings)
    rows.push_back({x.label, "d = " + x.d.str(15), fmt::format("bonds {}", x.bonds()),
                    fmt::format("rattlers {}", x.rattlers()),
                    x.certified ? "certified" : "NOT certified", found(x)});
  aligned_rows(out, "  ", rows);
}

inline std::string count_vs(std::size_t got, const std::optional<long long>& expected) {
  if (!expected) return std::to_string(got);
  return fmt::format("{} (catalogue: {}{})", got, *expected,
                     static_cast<long long>(got) == *expected ? "" : ", MISMATCH");
}

inline std::string ms(double seconds) {
  return fmt::format("{:.3f} ms", seconds * 1e3);
}

}  // namespace tripack::report::results
