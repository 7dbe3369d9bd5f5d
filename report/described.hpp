// Output formats as writers of a result's description, one per format in one table: a new output
// format is its writer's file plus one line in output_writers() (report/described.cpp), and every
// command's result can be printed in it (--output-format NAME).
//
// A result's description is a JSON tree whose fields are named once: a described result
// (core/described.hpp) gives its fields directly; every other result gives the tree its JSON
// renderer builds (report/json.cpp and beside it), where each field is named once for every
// format. Text, JSON and CSV keep their hand-made views of those results (report/render.hpp).
#pragma once

#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "core/described.hpp"

namespace tripack::report {

using Tree = nlohmann::ordered_json;

struct OutputWriter {
  std::string format;  // the --output-format name
  void (*write)(std::ostream& out, const Tree& description);
};
const std::vector<OutputWriter>& output_writers();
std::string output_format_names();  // "text, json, csv, ..."

// The writer of `format`; throws std::invalid_argument naming the formats for any other.
void write_description(std::ostream& out, const Tree& description, const std::string& format);

// A described result's tree: {"result": title, field: value, ...} (numbers as numbers).
Tree tree_of(const Described& result);
// A JSON document (a renderer's output) as a tree, written in `format`.
void write_json_description(std::ostream& out, const std::string& json_text,
                            const std::string& format);

}  // namespace tripack::report
