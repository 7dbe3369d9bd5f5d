// The explorer's report directory: data first (CSV, JSON, coordinate files), then the
// pictures (Cairo diagrams, gnuplot plots), then index.html, which is written last so that a
// page on disk always describes files that exist. Works from a partial (interrupted) result too.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "jobs/atlas_files.hpp"
#include "jobs/exact_atlas.hpp"
#include "jobs/explore.hpp"

namespace tripack::report {

// The atlas (data/atlas.csv) shown beside the exploration: its best packing of every n
// in the delta(n) plot (grey dots), a table, a diagram per n, the n where it beats every
// builder; its table and files are copied into DIR/atlas/ so the report stays self-contained.
struct ExploreAtlas {
  std::filesystem::path csv;         // where atlas.csv was read
  std::vector<PackingRecord> rows;   // every row as read (no bonds: files keep none)
  std::vector<PackingRecord> best;   // the rank-1 rows, read back and analysed
  std::vector<jobs::AtlasGap> gaps;  // atlas-gaps.csv beside it (empty if absent)
  // atlas-exact.csv beside it, by label (empty if absent): P's degree, the proof, certificates in
  // exact/ (docs/exact.md).
  std::map<std::string, jobs::ExactAtlasRow> exact;
};

struct ExploreReportOptions {
  bool diagrams = true;  // SVG + PNG per packing (PNG only for the large terms beyond max n)
  bool forces = true;    // also a forces diagram of each certified builder packing
  const ExploreAtlas* atlas = nullptr;
};

// Writes `dir` (created if needed). Throws a one-line error when the directory cannot be written
// or gnuplot is missing (after the data files are written). `progress` gets a line per artifact.
void write_explore_report(const jobs::ExploreResult& result, const std::filesystem::path& dir,
                          const ExploreReportOptions& options = {},
                          const std::function<void(const std::string&)>& progress = {});

// The coordinate file name of a packing row, relative to the report directory.
std::string packing_file_name(const PackingRecord& row);

}  // namespace tripack::report
