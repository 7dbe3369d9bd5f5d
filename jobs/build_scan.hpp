// `tripack build-scan`: `build --n N` for every N of a range, one row per N appended to a table as
// its build ends (docs/performance.md, "build --n against n"). Resumable through the runner: the
// N already in the table are skipped, so an interrupted scan loses only the builds under way.
// The worked example of a resumable job in docs/extending.md.
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include "constructors/catalogue.hpp"
#include "core/option_values.hpp"
#include "core/options.hpp"
#include "core/progress.hpp"
#include "formats/tables.hpp"
#include "pipeline/build.hpp"

namespace tripack::jobs {

struct BuildScanRequest {
  std::pair<long long, long long> n{2, 100};
  std::filesystem::path table = "build-scan.csv";
  int threads = 1;  // builds at once (1: each build's timing undisturbed)
  pipeline::BuildSettings build;

  void declare(OptionList& o) {
    o.parsed(
        "--n", [this](const std::string& s) { n = parse_range(s, "--n"); }, "2..100",
        "the range of N: A..B or N");
    o.parsed(
        "--table", [this](const std::string& s) { table = s; }, "build-scan.csv",
        "the table: created if missing, its rows kept and their N skipped");
    o.option("--threads", threads, "builds at once").range(1, 256);
  }
};

// Its columns (formats/tables.hpp): n, member, d, bonds, rattlers, certified, seconds, error.
const TableFormat& build_scan_table_format();

struct BuildScanResult {
  long long rows = 0;     // N in the range
  long long skipped = 0;  // already in the table
  long long built = 0, certified = 0;
  bool cancelled = false;
  double seconds = 0;
};

// Progress: stage "build-scan", one report per N built (d: its d).
BuildScanResult scan_builds(const Catalogue& catalogue, const BuildScanRequest& request,
                            const JobContext& job = {});

}  // namespace tripack::jobs
