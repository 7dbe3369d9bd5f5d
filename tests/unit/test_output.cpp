// Output formats (report/description.hpp): every result described once, through the writers'
// table; the CSV writer keeps every field; a text view is followed by the fields it did not print.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "core/described.hpp"
#include "jobs/billiards_runs.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/render.hpp"
#include "report/results/billiards.hpp"
#include "report/results/catalogue.hpp"
#include "report/results/search.hpp"
#include "report/results/summary.hpp"
#include "search/search.hpp"

namespace tripack {
namespace {

TEST(Output, EveryWriterRendersEveryFieldOfAResult) {
  // classify 22: four members (matrix p=3 k=1, even-ripple k=3, vacancy-segment p=6 k=1,
  // jogged-line p=1 k=6), the rows of its table.
  const auto catalogue = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  const auto result = pipeline::classify(catalogue, 22);  // points into the catalogue
  for (const auto& writer : report::output_writers()) {
    std::ostringstream out;
    report::render(out, result, writer.format);
    EXPECT_NE(out.str().find("even-ripple"), std::string::npos) << writer.format << out.str();
  }
  std::ostringstream csv;
  report::render(csv, result, "csv");
  // A header, then one line per member: n (the context) on every line.
  const std::string lines = csv.str();
  EXPECT_EQ(csv.str().substr(0, csv.str().find('\n')), "class,k,p,display,n,seconds");
  EXPECT_EQ(std::count(lines.begin(), lines.end(), '\n'), 5) << csv.str();
  std::ostringstream text;
  EXPECT_THROW(report::render(text, result, "no-such-format"), std::invalid_argument);
}

TEST(Output, CsvFlattensNestedFieldsRatherThanDroppingThem) {
  report::Description d;
  d.fields = report::Tree::parse(
      R"({"n": 7, "best": {"d": "0.5", "certified": true}, "seeds": [1, 2], "runs": [{"s": 1}],
          "rows": [{"label": "t7a"}, {"label": "t7b", "extra": null}]})");
  d.rows = "rows";
  std::ostringstream csv;
  report::write_description(csv, d, "csv");
  EXPECT_EQ(csv.str(),
            "label,n,best.d,best.certified,seeds,runs.0.s,extra\n"
            "t7a,7,0.5,true,1 2,1,\n"
            "t7b,7,0.5,true,1 2,1,\n");
}

TEST(Output, ADescribedResultNamesItsFieldsOnceForEveryFormat) {
  Described d("exact atlas");
  d.number("rows", "479").text("table", "data/atlas-exact.csv");
  std::ostringstream text, json, csv;
  report::render(text, d, "text");
  report::render(json, d, "json");
  report::render(csv, d, "csv");
  EXPECT_EQ(text.str(),
            "result     exact atlas\nrows       479\ntable      data/atlas-exact.csv\n");
  EXPECT_EQ(json.str(),
            "{\"result\":\"exact atlas\",\"rows\":479,\"table\":\"data/atlas-exact.csv\"}\n");
  EXPECT_EQ(csv.str(), "result,rows,table\nexact atlas,479,data/atlas-exact.csv\n");
}

// A field the text view does not print follows it by name: a new field reaches the text too.
TEST(Output, TheTextViewIsFollowedByTheFieldsItDoesNotPrint) {
  const auto catalogue = Catalogue::load(TRIPACK_DEFAULT_CATALOGUE);
  const auto result = pipeline::classify(catalogue, 22);  // points into the catalogue
  auto d = report::View<pipeline::Classification>::describe(result, {});
  d.fields["new_field"] = 42;
  std::ostringstream rest;
  report::write_fields_not_shown(rest, d);
  EXPECT_EQ(rest.str(), "new_field  42\n");
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
  report::render(text, r, "text");
  expect_aligned(text.str(), "distinct packings", 3);
  EXPECT_NE(text.str().find("  t187a-inflated-t53a  d = "), std::string::npos) << text.str();
}

TEST(Output, BilliardsTextColumnsAlignToTheWidestCell) {
  jobs::BilliardsRunsResult r;
  r.runs_asked = 0;
  r.packings = packings_of_many_widths();
  std::ostringstream text;
  report::render(text, r, "text");
  expect_aligned(text.str(), "distinct packings", 3);
}

}  // namespace
}  // namespace tripack
