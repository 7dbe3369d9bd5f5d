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
};

struct ExactAtlasResult {
  std::size_t rows = 0;     // in the atlas (after the n filter)
  std::size_t skipped = 0;  // already in atlas-exact.csv
  std::vector<pipeline::ExactResult> done;  // this call's rows, in finishing order
  bool cancelled = false;
  double seconds = 0;
};

// data/atlas-exact.csv: n, label, degree, polynomial (PARI syntax in x), root_low, root_high
// (rationals), proof (exact, existence, none), reason, seconds.
std::string exact_csv_header();
std::string exact_csv_row(const pipeline::ExactResult& r);

// A row of atlas-exact.csv as read back (strings as written).
struct ExactAtlasRow {
  long long n = 0;
  std::string label, degree, polynomial, root_low, root_high, proof, reason;
};
// Rows by label; an absent file gives none. Throws std::runtime_error naming the file and line
// for a row without the 9 columns.
std::map<std::string, ExactAtlasRow> read_exact_atlas(const std::filesystem::path& csv);

// Throws for an unreadable atlas or an unwritable DIR (before any row runs). A row whose file
// cannot be analysed gets proof "none" with the error as its reason.
ExactAtlasResult build_exact_atlas(const ExactAtlasSettings& settings, const CancelToken* cancel,
                                   const ProgressFn& progress);

}  // namespace tripack::jobs
