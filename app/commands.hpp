// The tripack subcommands: options in, pipeline call, files written, result rendered. Each returns
// the process exit code; errors are thrown and turned into one line by main().
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "report/render.hpp"

namespace tripack::app {

struct GlobalOptions {
  std::string catalogue;  // empty: Catalogue::default_path()
  // Set by main() on Ctrl-C or SIGTERM (mpirun passes a Ctrl-C on to the ranks as SIGTERM): long
  // jobs stop between items and report what finished. Null: nothing cancels (tests).
  const CancelToken* cancel = nullptr;
};

// --json / --csv / --points: how the result is printed.
struct OutputOptions {
  bool json = false;
  bool csv = false;
  bool points = false;  // JSON: with coordinates
  report::OutputFormat format() const {
    return json ? report::OutputFormat::Json
                : (csv ? report::OutputFormat::Csv : report::OutputFormat::Text);
  }
};

// --svg FILE / --png FILE / --pdf FILE: a diagram of the result's packing (report/diagram.hpp).
struct DiagramTargets {
  std::string svg, png, pdf;
  bool forces = false;  // bond forces of the stress certificate as line widths
};

inline constexpr long kUnsetK = -1000000000;  // --k not given (0 and negatives are user errors)

struct BuildOptions {
  DiagramTargets diagrams;
  std::string class_id;
  long k = kUnsetK, p = 0;
  long long n = 0;  // --n: choose the best builder for n
  std::string variant;
  int digits = 15;
  std::string output;  // -o FILE
  bool polish = true;
  bool certify = true;
  OutputOptions out;
};

struct AnalyzeOptions {
  DiagramTargets diagrams;
  std::string file;
  std::string convention;  // empty: unit-triangle (radius for an x y r file)
  int digits = 15;
  long long n = 0;           // expected number of points (0: any)
  std::string output;        // -o FILE: the certified packing (unit triangle)
  bool lp_any_size = false;  // run the LP relax and certificates above AnalysisOptions::lp_limit
  OutputOptions out;
};

struct CheckFormulaOptions {
  std::string class_id;
  std::string k_range;  // "A..B" or "K"
  long p = 0;
  OutputOptions out;
};

struct BilliardsCommandOptions {
  DiagramTargets diagrams;
  long long n = 0;  // 0: the scene's n
  int runs = 10;
  std::uint64_t seed = 1;  // run r uses seed + r, so every run is reproducible on its own
  int threads = 1;
  std::string scene;  // YAML file; empty: the built-in scene
  bool certify = true;
  std::string output_dir;           // -o DIR: one coordinate file per distinct packing
  std::string file_format = "txt";  // of those files: txt, csv, json, pck
  OutputOptions out;
};

// `tripack search N --seconds S` (docs/search.md).
struct SearchOptions {
  DiagramTargets diagrams;
  long long n = 0;
  double seconds = 10;
  long long steps = 0;  // 0: no step limit
  std::uint64_t seed = 1;
  int threads = 1;
  std::string db;  // empty: start from nothing stored, record nothing
  std::string method = "basin-hopping";
  bool lattice_starts = true;
  std::string target;  // stop once this d is reached (decimal)
  OutputOptions out;
};
int cmd_search(const GlobalOptions& g, const SearchOptions& o);

struct ExploreOptions {
  long long max_n = 300;
  long long search_steps = 100;
  long long discovered_max_n = 60;
  int threads = 2;
  std::uint64_t seed = 1;
  std::string out = "report";
  bool accuracy = true;
  // The atlas shown beside the exploration: empty = the project's data/atlas.csv when it exists,
  // "none" = no atlas.
  std::string atlas;
};
// `tripack draw FILE|CLASS`: a diagram of a points file (analysed) or a class member (built).
// `tripack exact FILE...` (docs/exact.md).
struct ExactOptions {
  std::vector<std::string> files;  // or a class:
  std::string class_id;
  std::string k_range;  // "A..B" or "K"
  long p = 0;
  int digits = 300;  // D: found from D digits, confirmed from 2D
  int first_digits = 0;  // 0: digits only; else first_digits, twice that, ... up to digits
  int max_degree = 48;
  std::string certificates;  // a directory: LABEL.gp for every proven packing
  bool existence = true;     // --no-existence: the polynomial only
  OutputOptions out;
};
int cmd_exact(const GlobalOptions& g, const ExactOptions& o);

// `tripack exact-atlas` (docs/exact.md): every atlas row, resumable.
struct ExactAtlasOptions {
  std::string atlas;    // empty: the project's data/atlas.csv
  std::string out;      // empty: the atlas's directory
  std::string n_range;  // "A..B", "N" or a list; empty: every row
  int digits = 300;
  int first_digits = 0;  // as ExactOptions
  int max_degree = 48;
  int threads = 2;
  bool retry_none = false;
};
int cmd_exact_atlas(const GlobalOptions& g, const ExactAtlasOptions& o);

struct DrawOptions {
  std::string what;  // a points file, or a class id
  long k = kUnsetK, p = 0;
  std::string variant, convention;
  std::string output;  // .svg, .png or .pdf
  bool forces = false;
  bool disk_labels = true;
  int width = 900;
};
int cmd_draw(const GlobalOptions& g, const DrawOptions& o);

// `tripack campaign` and `tripack db best|check|export|import` (issue 11).
struct CampaignOptions {
  std::string n_range;  // "A..B" or "N"
  int runs = 20;
  std::uint64_t seed = 1;
  int threads = 1;
  std::string db = "tripack.db";
  std::string scene;          // YAML: effects and stop rule for every n
  double search_seconds = 0;  // > 0: search chains of this budget instead of billiards runs
  OutputOptions out;
};
int cmd_campaign(const GlobalOptions& g, const CampaignOptions& o);
// The read commands (best, check, export) never create the database file.
struct DbOptions {
  std::string db = "tripack.db";
  long long n = 0;  // 0: every n
  OutputOptions out;
};
int cmd_db_best(const DbOptions& o);
struct DbCheckOptions {
  std::string db = "tripack.db";
  OutputOptions out;
};
int cmd_db_check(const DbCheckOptions& o);
struct DbExportOptions {
  std::string db = "tripack.db";
  long long n = 0;
  std::string format;  // txt, csv, json, records; empty: -o FILE's extension, else txt
  std::string convention = "unit-triangle";
  long long rank = 1;  // 1 = the best
  bool all = false;
  std::string output;  // -o FILE (one packing) or DIR (--all, or an existing directory)
  int digits = 21;     // of the coordinates; d, L, r, S get at most the 18 stored
};
int cmd_db_export(const DbExportOptions& o);
struct DbImportOptions {
  std::vector<std::string> files;
  std::string db = "tripack.db";
  std::string convention;  // empty: as each file declares (analyze's rule)
  int threads = 2;         // files analysed at once
  OutputOptions out;
};
int cmd_db_import(const GlobalOptions& g, const DbImportOptions& o);
struct DbPruneOptions {
  std::string db = "tripack.db";
  long long keep = 0;   // packings kept per n (required)
  std::string n_range;  // "A..B" or "N"; empty: every n
  OutputOptions out;
};
int cmd_db_prune(const DbPruneOptions& o);

int cmd_explore(const GlobalOptions& g, const ExploreOptions& o);

// `tripack atlas` (issue 12): the campaign database and the builders merged, certified, polished
// to 30 digits and written as DIR/atlas.csv + DIR/atlas/*.txt.
struct AtlasOptions {
  std::string db = "data/atlas.db";
  std::string out = "data";
  std::string n_range = "2..200";
  std::string ranked = "16..34";  // these n keep `ranked_count` packings
  int ranked_count = 20;
  int digits = 30;
  int threads = 2;
  OutputOptions out_format;
};
int cmd_atlas(const GlobalOptions& g, const AtlasOptions& o);

int cmd_classes(const GlobalOptions& g, const OutputOptions& out);
int cmd_classify(const GlobalOptions& g, long long n, const OutputOptions& out);
int cmd_build(const GlobalOptions& g, const BuildOptions& o);
int cmd_check_formula(const GlobalOptions& g, const CheckFormulaOptions& o);
int cmd_table(const GlobalOptions& g, long k_count, const OutputOptions& out);
int cmd_analyze(const AnalyzeOptions& o);
int cmd_billiards(const GlobalOptions& g, const BilliardsCommandOptions& o);
int cmd_compare(const GlobalOptions& g, const BilliardsCommandOptions& o);

}  // namespace tripack::app
