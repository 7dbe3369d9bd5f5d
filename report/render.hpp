// Renderers of the pipeline's results: one result type per command, one function per format
// (text for people, JSON and CSV for programs), so a new format is one file, not one per command.
// Pictures (diagrams, plots) come in their own files.
//
// JSON conventions, the same in every command: one object per invocation; high-precision numbers
// (d, L, r, S, coordinates) are decimal strings; `bonds` and `rattlers` are counts, with
// `rattler_indices` (0-based) where known; `seconds` is the total wall time; errors are
// {"error": "..."} (see render_error_json).
#pragma once

#include <iosfwd>
#include <string>

#include "constructors/catalogue.hpp"
#include "jobs/billiards_search.hpp"
#include "jobs/compare.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "pipeline/exact.hpp"
#include "report/atlas_report.hpp"
#include "report/campaign_report.hpp"
#include "report/described.hpp"
#include "search/search.hpp"

namespace tripack::report {

enum class OutputFormat { Text, Json, Csv };

struct RenderOptions {
  bool points = false;  // JSON: include every packing's coordinates
};

void render_text(std::ostream& out, const Catalogue& catalogue, const RenderOptions& options);
void render_json(std::ostream& out, const Catalogue& catalogue, const RenderOptions& options);
void render_csv(std::ostream& out, const Catalogue& catalogue, const RenderOptions& options);

void render_text(std::ostream& out, const pipeline::Classification& c, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::Classification& c, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::Classification& c, const RenderOptions& o);

void render_text(std::ostream& out, const pipeline::BestBuild& b, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::BestBuild& b, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::BestBuild& b, const RenderOptions& o);

void render_text(std::ostream& out, const pipeline::FormulaCheck& c, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::FormulaCheck& c, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::FormulaCheck& c, const RenderOptions& o);

void render_text(std::ostream& out, const pipeline::CatalogueTable& t, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::CatalogueTable& t, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::CatalogueTable& t, const RenderOptions& o);

void render_text(std::ostream& out, const pipeline::FileAnalysis& a, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::FileAnalysis& a, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::FileAnalysis& a, const RenderOptions& o);

// `tripack exact`; the CSV is data/atlas-exact.csv's format (docs/exact.md).
void render_text(std::ostream& out, const pipeline::ExactRun& r, const RenderOptions& o);
void render_json(std::ostream& out, const pipeline::ExactRun& r, const RenderOptions& o);
void render_csv(std::ostream& out, const pipeline::ExactRun& r, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::BilliardsSearchResult& r, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::BilliardsSearchResult& r, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::BilliardsSearchResult& r, const RenderOptions& o);

// `tripack search`: the best packing (certified, seconds_to_best), the distinct packings by rank,
// the chains.
void render_text(std::ostream& out, const search::SearchResult& r, const RenderOptions& o);
void render_json(std::ostream& out, const search::SearchResult& r, const RenderOptions& o);
void render_csv(std::ostream& out, const search::SearchResult& r, const RenderOptions& o);

void render_text(std::ostream& out, const jobs::ConstructedVsBilliards& c, const RenderOptions& o);
void render_json(std::ostream& out, const jobs::ConstructedVsBilliards& c, const RenderOptions& o);
void render_csv(std::ostream& out, const jobs::ConstructedVsBilliards& c, const RenderOptions& o);

// The one dispatch point: a result in the chosen format.
template <class Result>
void render(std::ostream& out, const Result& result, OutputFormat format,
            const RenderOptions& options = {}) {
  switch (format) {
    case OutputFormat::Text:
      return render_text(out, result, options);
    case OutputFormat::Json:
      return render_json(out, result, options);
    case OutputFormat::Csv:
      return render_csv(out, result, options);
  }
}

// A described result (core/described.hpp): through the output writers' table.
void render(std::ostream& out, const Described& result, OutputFormat format,
            const RenderOptions& options = {});

// {"error": message} on one line.
void render_error_json(std::ostream& out, const std::string& message);

}  // namespace tripack::report
