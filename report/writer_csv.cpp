#include <algorithm>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "core/io.hpp"
#include "report/description.hpp"

namespace tripack::report {

namespace {

using Leaves = std::vector<std::pair<std::string, std::string>>;

// Every leaf of a tree by its dotted path ("certificate.rigid", "chains.0.seed"); a list of
// scalars is one cell, space-separated. Nothing is dropped: every field has a column.
void collect_leaves(const Tree& value, const std::string& path, Leaves& leaves) {
  const auto child = [&](const std::string& key) { return path.empty() ? key : path + "." + key; };
  bool scalars = value.is_array();
  if (value.is_array())
    for (const auto& item : value) scalars = scalars && !item.is_structured();
  if (value.is_object() && !value.empty()) {
    for (const auto& [key, item] : value.items()) collect_leaves(item, child(key), leaves);
  } else if (value.is_array() && !scalars) {
    for (std::size_t i = 0; i < value.size(); ++i)
      collect_leaves(value[i], child(std::to_string(i)), leaves);
  } else if (value.is_array()) {
    std::string cell;
    for (const auto& item : value) {
      if (!cell.empty()) cell += ' ';
      cell += scalar_text(item);
    }
    leaves.emplace_back(path, cell);
  } else if (!path.empty()) {  // an empty object at the top (a row of no fields) has no column
    leaves.emplace_back(path, value.is_object() ? "" : scalar_text(value));
  }
}

}  // namespace

// CSV (RFC 4180): one line per element of the declared rows (one line when none are declared),
// its leaves first, then the rest of the result's leaves on every line. The header is every
// column any line has, in the order first met; a line lacking one leaves its cell empty.
void write_csv(std::ostream& out, const Description& description) {
  Tree context = description.fields;
  Tree rows = Tree::array();
  if (!description.rows.empty() && context.contains(description.rows)) {
    rows = context[description.rows];
    context.erase(description.rows);
  }
  if (rows.empty()) rows.push_back(Tree::object());
  Leaves context_leaves;
  collect_leaves(context, "", context_leaves);
  std::vector<Leaves> lines;
  std::vector<std::string> header;
  for (const auto& row : rows) {
    Leaves line;
    collect_leaves(row, "", line);
    line.insert(line.end(), context_leaves.begin(), context_leaves.end());
    for (const auto& [name, cell] : line)
      if (std::find(header.begin(), header.end(), name) == header.end()) header.push_back(name);
    lines.push_back(std::move(line));
  }
  csv_row(out, header);
  for (const auto& line : lines) {
    std::vector<std::string> cells(header.size());
    for (const auto& [name, cell] : line)
      cells[static_cast<std::size_t>(std::find(header.begin(), header.end(), name) -
                                     header.begin())] = cell;
    csv_row(out, cells);
  }
}

}  // namespace tripack::report
