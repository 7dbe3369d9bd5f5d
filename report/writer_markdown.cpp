#include <ostream>
#include <string>
#include <vector>

#include "report/description.hpp"

namespace tripack::report {

namespace {

// A cell of a Markdown table: a '|' escaped, a line break as a space.
std::string markdown_cell(const std::string& text) {
  std::string cell;
  for (char c : text) {
    if (c == '|') cell += '\\';
    cell += c == '\n' ? ' ' : c;
  }
  return cell;
}

void markdown_line(std::ostream& out, const std::vector<std::string>& cells) {
  out << "|";
  for (const auto& c : cells) out << " " << markdown_cell(c) << " |";
  out << "\n";
}

}  // namespace

// Markdown: the result's table (result_table) as a GitHub-flavoured Markdown table, to paste into
// a note or a manual.
void write_markdown(std::ostream& out, const Description& description) {
  const ResultTable table = result_table(description);
  markdown_line(out, table.header);
  out << "|";
  for (std::size_t i = 0; i < table.header.size(); ++i) out << "---|";
  out << "\n";
  for (const auto& line : table.lines) markdown_line(out, line);
}

}  // namespace tripack::report
