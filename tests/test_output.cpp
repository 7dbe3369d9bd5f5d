// Output formats (report/described.hpp): any result through the writers' table, from the
// fields its JSON renderer names once, and a described result in every format.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/described.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/described.hpp"
#include "report/render.hpp"

namespace tripack {
namespace {

TEST(Output, EveryWriterRendersAResultFromItsJsonFields) {
  // classify 22: three members (matrix p=3 k=1, even-ripple k=3, vacancy-segment p=6 k=1).
  std::ostringstream json;
  report::render(json, pipeline::classify(Catalogue::load(TRIPACK_DEFAULT_CATALOGUE), 22),
                 report::OutputFormat::Json);
  for (const auto& writer : report::output_writers()) {
    std::ostringstream out;
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

}  // namespace
}  // namespace tripack
