// `tripack db import`: packing files into the results database. Each file is read like
// `tripack analyze` reads it (core/io + core/points: every layout, the three conventions), checked
// for overlapping disks, analysed by the same pipeline (pipeline::analyze_packing: relax, bonds,
// rattlers, rigidity, stress) and, when certified, stored with its contact-graph hash, bonds,
// rattlers, origin "import", source = the file's name and no seed. All files are analysed (on the
// job runner's threads) before anything is written, then stored in one transaction: a refused
// file stores none of them.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/conventions.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"

namespace tripack::jobs {

// A file refused: one line naming it and why.
struct ImportError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Disks overlap when the file's stated diameter (PointsReading::stated_d: its "# d:" header,
// JSON "d", or 2r of an "x y r" file) exceeds the points' minimum distance by more than this
// fraction of it: far above the rounding of the 17-21 digits tripack writes, far below any real
// overlap. (Coordinates rounded to few digits under an exact d header fail it: such a file
// states a d its points do not have.)
inline constexpr long double kOverlapTolerance = 1e-9L;

struct ImportRequest {
  std::vector<std::string> files;
  std::string db = "tripack.db";         // created if missing
  std::optional<Convention> convention;  // none: as each file declares (analyze's rule)
  int threads = 2;                       // files analysed at once (the job runner's threads)
  bool accept_header_d = false;          // store a file whose "# d:" differs from its points' d

  void declare(OptionList& o) {
    o.option("FILE", files, "packing files (any layout of 'analyze')").required();
    o.option("--db", db, "results database, created if missing");
    o.parsed(
        "--convention", [this](const std::string& s) { convention = convention_from_option(s); },
        "as the file declares, else unit-triangle", kConventionHelp);
    o.option("--threads", threads, "files analysed at once").range(1, 256);
    o.flag("--accept-header-d", accept_header_d,
           "store a file whose header d differs from its points' d (refused by default: the "
           "file is not what it says it is)");
  }
};

struct ImportedPacking {
  std::string file;    // as given
  std::string source;  // what the database records: the file's name without its directories
  std::string layout;  // how it was read ("x y", "i x y", "csv", ...)
  Convention convention = Convention::UnitTriangle;
  std::vector<std::string> warnings;  // the reader's (rounded input, orientation)
  long long n = 0;
  std::string d_file;  // the points' minimum distance as read, 18 digits
  std::string d;       // the certified d as stored, 18 digits
  std::string graph_hash;
  std::size_t bonds = 0;
  std::vector<int> rattlers;
  std::string verdict;
  bool added = false;  // false: the same packing (n, contact graph, d to 12 digits) was stored
  long long id = 0;    // its row
  std::string label;   // its label among the stored packings of n after the import
  double seconds = 0;  // reading and analysis
};

struct ImportResult {
  std::string db;
  std::vector<ImportedPacking> packings;  // in the order of the files
  long long added = 0, already = 0;
  bool cancelled = false;  // then nothing was stored
  double seconds = 0;
};

// Throws ImportError (one line naming the file) for a file that cannot be read or is malformed
// (InputError of the reader: also coinciding points, points outside the triangle beyond the
// rounding tolerance, an orientation that cannot be told), that has overlapping disks (see
// kOverlapTolerance) or whose packing is not certified; store::StoreError for the database
// (another schema version, not a database, locked). In every case nothing is stored.
// Progress: stage "import", one report per analysed file. Cancelled: it stops before the store,
// and nothing is stored.
ImportResult import_packings(const ImportRequest& request, const JobContext& job = {});

}  // namespace tripack::jobs
