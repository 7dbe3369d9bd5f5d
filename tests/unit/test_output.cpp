// Output formats (report/described.hpp): any result through the writers' table, from the
// fields its JSON renderer names once, and a described result in every format.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "core/described.hpp"
#include "jobs/billiards_search.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/described.hpp"
#include "report/render.hpp"
#include "search/search.hpp"

namespace tripack {
namespace {

TEST(Output, EveryWriterRendersAResultFromItsJsonFields) {
  // classify 22: three members (matrix p=3 k=1, even-ripple k=3, vacancy-segment p=6 k=1).
  std::ostringstream json;
  report::render(json, pipeline::classify(Catalogue::load(TRIPACK_DEFAULT_CATALOGUE), 22),
                 report::OutputFormat::Json);
  // Every writer renders it, except CSV, whose one row cannot hold the nested list of members:
  // it refuses the tree rather than writing it without them.
  for (const auto& writer : report::output_writers()) {
    std::ostringstream out;
    if (writer.format == "csv") {
      EXPECT_THROW(report::write_json_description(out, json.str(), writer.format),
                   std::invalid_argument);
      continue;
    }
    report::write_json_description(out, json.str(), writer.format);
    EXPECT_FALSE(out.str().empty()) << writer.format;
  }
  std::ostringstream text;
  report::write_json_description(text, json.str(), "text");
  EXPECT_NE(text.str().find("even-ripple"), std::string::npos) << text.str();
  EXPECT_THROW(report::write_json_description(text, json.str(), "no-such-format"),
               std::invalid_argument);
}

TEST(Output, ADescribedResultNamesItsFieldsOnceForEveryFormat) {
  Described d("exact atlas");
  d.number("rows", "479").text("table", "data/atlas-exact.csv");
  std::ostringstream text, json, csv;
  report::render(text, d, report::OutputFormat::Text);
  report::render(json, d, report::OutputFormat::Json);
  report::render(csv, d, report::OutputFormat::Csv);
  EXPECT_EQ(text.str(), "exact atlas\n  rows: 479\n  table: data/atlas-exact.csv\n");
  EXPECT_NE(json.str().find("\"rows\": 479"), std::string::npos) << json.str();
  EXPECT_EQ(csv.str(), "result,rows,table\nexact atlas,479,data/atlas-exact.csv\n");
}

// The distinct packings of search and billiards, as text: one row per packing whose columns
// line up whatever the widths of its cells (a label longer than 10 characters, d with fewer
// digits, bonds of 2 or 3 digits used to shift the rest of the row).
std::vector<PackingRecord> packings_of_many_widths() {
  std::vector<PackingRecord> packings(3);
  const char* labels[] = {"t187a", "t187a-inflated-t53a", "t187ab"};
  const long double ds[] = {0.0555556710635150292L, 0.0555556414551933L, 0.0555555555555556L};
  const int bonds[] = {513, 47, 1200};
  for (std::size_t i = 0; i < packings.size(); ++i) {
    auto& x = packings[i];
    x.label = labels[i];
    x.d = PreciseReal(ds[i]);
    x.pattern.bonds.resize(static_cast<std::size_t>(bonds[i]));
    x.pattern.rattlers.resize(i * 5);
    x.certified = i != 1;
    x.sources.push_back({PackingSource::Kind::Billiards, "", 7 + i, 1 + static_cast<long long>(i)});
  }
  return packings;
}

// The rows after the line starting with `title`, and in each the column where every one of
// `words` starts: the same in every row.
void expect_aligned(const std::string& text, const std::string& title, std::size_t rows) {
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line) && line.rfind(title, 0) != 0) {
  }
  std::vector<std::string> table;
  while (table.size() < rows && std::getline(in, line)) table.push_back(line);
  ASSERT_EQ(table.size(), rows) << text;
  for (const char* word : {"d = ", "bonds ", "rattlers ", "certified", "("}) {
    const auto column = table[0].find(word);
    ASSERT_NE(column, std::string::npos) << word << " in " << table[0];
    for (const auto& row : table) {
      const auto at = std::string(word) == "certified" && row.find("NOT certified") != row.npos
                          ? row.find("NOT certified")
                          : row.find(word);
      EXPECT_EQ(at, column) << "'" << word << "' not aligned:\n" << text;
    }
  }
}

TEST(Output, SearchTextColumnsAlignToTheWidestCell) {
  search::SearchResult r;
  r.request.n = 187;
  r.packings = packings_of_many_widths();
  r.chains.resize(3);
  std::ostringstream text;
  report::render(text, r, report::OutputFormat::Text);
  expect_aligned(text.str(), "distinct packings", 3);
  EXPECT_NE(text.str().find("  t187a-inflated-t53a  d = "), std::string::npos) << text.str();
}

TEST(Output, BilliardsTextColumnsAlignToTheWidestCell) {
  jobs::BilliardsSearchResult r;
  r.runs_asked = 0;
  r.packings = packings_of_many_widths();
  std::ostringstream text;
  report::render(text, r, report::OutputFormat::Text);
  expect_aligned(text.str(), "distinct packings", 3);
}

}  // namespace
}  // namespace tripack
