// A result described once: a tree of named fields (nlohmann's ordered JSON, keys in the order
// given) with its rows declared. Every output format is a writer over that tree, one per format in
// one table (output_writers(), description.cpp): a new format is its writer's file plus one line
// there, and every command's result can be printed in it (--output-format NAME). Conventions of
// the fields, the same in every result, are in docs/formats.md ("Results").
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace tripack::report {

using Tree = nlohmann::ordered_json;

struct DescribeOptions {
  bool points = false;  // include every packing's coordinates
};

struct Description {
  Tree fields = Tree::object();
  // The array field whose elements are the result's table rows (CSV writes one line per element);
  // empty: the whole result is one row.
  std::string rows;
  // The top-level fields the result's own text view prints in its own words; the text writer adds
  // every other field after the view, so a new field is never missing from the text.
  std::vector<std::string> shown_by_view;
};

struct OutputWriter {
  std::string format;  // the --output-format name
  void (*write)(std::ostream& out, const Description& description);
};
const std::vector<OutputWriter>& output_writers();
std::string output_format_names();  // "text, json, csv, ..."

// The writer of `format`; throws std::invalid_argument naming the formats for any other.
void write_description(std::ostream& out, const Description& description,
                       const std::string& format);

// After a result's own text view: its fields the view did not print, as "name value" lines.
void write_fields_not_shown(std::ostream& out, const Description& description);

// The result as one table, what every tabular writer writes: one line per element of the declared
// rows (one line when none are declared), every leaf of the tree a column named by its dotted path
// ("certificate.rigid", "chains.0.seed"; a list of scalars one cell, space-separated), the row's
// own leaves first, then the rest of the result on every line. Nothing is dropped.
struct ResultTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> lines;
};
ResultTable result_table(const Description& description);

// A scalar as text: strings as they are, null as "", numbers and booleans as JSON writes them.
std::string scalar_text(const Tree& value);

}  // namespace tripack::report
