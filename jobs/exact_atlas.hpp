// The exact atlas (docs/exact.md): `tripack exact` on every row of data/atlas.csv, on the job
// runner, resumable. Each finished row is appended at once to DIR/atlas-exact.csv (and its
// certificate written to DIR/exact/LABEL.gp when statement (I) is proven), so an interrupted run
// loses only the rows under way and a rerun skips every row already there; at the end the table
// is put in the atlas's order.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "constructors/catalogue.hpp"
#include "core/option_values.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"
#include "pipeline/exact.hpp"

namespace tripack::jobs {

struct ExactAtlasSettings {
  std::filesystem::path atlas;  // data/atlas.csv (its files are named relative to its directory)
  std::filesystem::path out;    // atlas-exact.csv and exact/ go here
  pipeline::ExactSettings exact;
  std::vector<long long> n_values;  // only these n (empty: every row)
  int threads = 2;
  bool retry_none = false;  // run the rows whose proof is "none" again (e.g. with more digits)

  void declare(OptionList& o) {
    o.parsed(
        "--atlas", [this](const std::string& s) { atlas = s; }, "the installed atlas",
        "the atlas table (atlas.csv)");
    o.parsed(
        "--out", [this](const std::string& s) { out = s; }, "the atlas's directory",
        "where atlas-exact.csv and exact/ go");
    o.parsed(
        "--n", [this](const std::string& s) { n_values = parse_range_list(s, "--n"); }, "every row",
        "only these n: A..B, N or a comma-separated list of them");
    exact.declare(o);
    o.option("--threads", threads, "rows at once").range(1, 256);
    o.flag("--retry-none", retry_none,
           "run the rows whose proof is 'none' again (with more --digits, a larger --max-degree)");
  }
};

struct ExactAtlasResult {
  std::size_t rows = 0;                     // in the atlas (after the n filter)
  std::size_t skipped = 0;                  // already in atlas-exact.csv
  std::vector<pipeline::ExactResult> done;  // this call's rows, in finishing order
  bool cancelled = false;
  double seconds = 0;
};

// data/atlas-exact.csv (formats/tables.hpp): n, label, degree, polynomial (PARI syntax in x),
// root_low, root_high (rationals), proof (exact, existence, none), reason, seconds; a row as read
// back (strings as written):
struct ExactAtlasRow {
  long long n = 0;
  std::string label, degree, polynomial, root_low, root_high, proof, reason;
};
// Rows by label; an absent file gives none. Throws std::runtime_error naming the file and line
// for a row without the 9 columns.
std::map<std::string, ExactAtlasRow> read_exact_atlas(const std::filesystem::path& csv);

// `tripack exact FILE...` or `exact --class C --k A..B`: each packing's exact d, and for every
// proven one LABEL.gp in `certificates` (written as soon as it is proven) naming its coordinates:
// the packing file, or for a class member LABEL.txt written beside it.
struct ExactRequest {
  std::vector<std::string> files;  // or a class:
  std::string class_id;
  std::pair<long long, long long> k{1, 0};  // empty unless given
  long p = 0;
  pipeline::ExactSettings exact;
  std::string certificates;  // empty: none written

  void declare(OptionList& o) {
    o.option("FILE", files, "packing files (any layout of 'analyze')");
    o.option("--class", class_id, "or the members of this class (see 'tripack classes')");
    o.parsed(
        "--k", [this](const std::string& s) { k = parse_range(s, "--k"); }, "",
        "with --class: k = A..B (or K)");
    o.option("--p", p, "with --class: matrix row p").range(0, 1e9);
    exact.declare(o);
    o.option("--certificates", certificates,
             "write LABEL.gp (checked by checker/check_exact.sh) here for every proven packing");
  }
};
// Throws std::invalid_argument for neither or both of files and a class, and before any work for
// an unwritable certificates directory.
pipeline::ExactRun run_exact(const Catalogue& catalogue, const ExactRequest& request);

// Throws for an unreadable atlas or an unwritable DIR (before any row runs). A row whose file
// cannot be analysed gets proof "none" with the error as its reason.
ExactAtlasResult build_exact_atlas(const ExactAtlasSettings& settings, const JobContext& job = {});

}  // namespace tripack::jobs
