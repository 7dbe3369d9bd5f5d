#include "report/described.hpp"

#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "report/render.hpp"

namespace tripack::report {

// The writers, each in its file (report/described_FORMAT.cpp).
void write_text_tree(std::ostream& out, const Tree& description);
void write_json_tree(std::ostream& out, const Tree& description);
void write_csv_tree(std::ostream& out, const Tree& description);

const std::vector<OutputWriter>& output_writers() {
  static const std::vector<OutputWriter> writers{
      {"text", write_text_tree},
      {"json", write_json_tree},
      {"csv", write_csv_tree},
  };
  return writers;
}

std::string output_format_names() {
  std::string names;
  for (const auto& w : output_writers()) names += (names.empty() ? "" : ", ") + w.format;
  return names;
}

void write_description(std::ostream& out, const Tree& description, const std::string& format) {
  for (const auto& w : output_writers())
    if (w.format == format) return w.write(out, description);
  throw std::invalid_argument("--output-format must be one of " + output_format_names() +
                              ", not '" + format + "'");
}

Tree tree_of(const Described& result) {
  Tree tree;
  tree["result"] = result.title;
  for (const auto& f : result.fields)
    tree[f.name] = f.number ? Tree::parse(f.value) : Tree(f.value);
  return tree;
}

void write_json_description(std::ostream& out, const std::string& json_text,
                            const std::string& format) {
  write_description(out, Tree::parse(json_text), format);
}

void render(std::ostream& out, const Described& result, OutputFormat format, const RenderOptions&) {
  write_description(
      out, tree_of(result),
      format == OutputFormat::Json ? "json" : (format == OutputFormat::Csv ? "csv" : "text"));
}

}  // namespace tripack::report
