#include "report/description.hpp"

#include <algorithm>
#include <ostream>
#include <stdexcept>
#include <unordered_map>
#include <utility>

namespace tripack::report {

// The writers, each in its file (report/writer_FORMAT.cpp).
void write_text(std::ostream& out, const Description& description);
void write_json(std::ostream& out, const Description& description);
void write_csv(std::ostream& out, const Description& description);
void write_markdown(std::ostream& out, const Description& description);
void write_text_fields(std::ostream& out, const Tree& fields, const std::string& indent);

const std::vector<OutputWriter>& output_writers() {
  static const std::vector<OutputWriter> writers{
      {"text", write_text},
      {"json", write_json},
      {"csv", write_csv},
      {"markdown", write_markdown},
  };
  return writers;
}

std::string output_format_names() {
  std::string names;
  for (const auto& w : output_writers()) names += (names.empty() ? "" : ", ") + w.format;
  return names;
}

void write_description(std::ostream& out, const Description& description,
                       const std::string& format) {
  for (const auto& w : output_writers())
    if (w.format == format) return w.write(out, description);
  throw std::invalid_argument("--output-format must be one of " + output_format_names() +
                              ", not '" + format + "'");
}

void write_fields_not_shown(std::ostream& out, const Description& description) {
  Tree rest = Tree::object();
  for (const auto& [key, value] : description.fields.items())
    if (std::find(description.shown_by_view.begin(), description.shown_by_view.end(), key) ==
        description.shown_by_view.end())
      rest[key] = value;
  write_text_fields(out, rest, "");
}

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

// One line per element of the declared rows (one line when none are declared): the row's leaves
// first, then the rest of the result's leaves on every line. The header is every column any line
// has, in the order first met; a line lacking one has an empty cell.
ResultTable result_table(const Description& description) {
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
  ResultTable table;
  std::unordered_map<std::string, std::size_t> column;  // a name's place in the header
  for (const auto& row : rows) {
    Leaves line;
    collect_leaves(row, "", line);
    line.insert(line.end(), context_leaves.begin(), context_leaves.end());
    for (const auto& [name, cell] : line)
      if (column.emplace(name, table.header.size()).second) table.header.push_back(name);
    lines.push_back(std::move(line));
  }
  for (const auto& line : lines) {
    std::vector<std::string> cells(table.header.size());
    for (const auto& [name, cell] : line) cells[column.at(name)] = cell;
    table.lines.push_back(std::move(cells));
  }
  return table;
}

std::string scalar_text(const Tree& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_null()) return "";
  return value.dump(-1, ' ', false, Tree::error_handler_t::replace);
}

}  // namespace tripack::report
