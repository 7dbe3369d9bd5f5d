#include "jobs/atlas_files.hpp"

#include <fmt/format.h>

#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/io.hpp"
#include "formats/formats.hpp"
#include "formats/tables.hpp"
#include "pipeline/analyze.hpp"

namespace tripack::jobs {

namespace {

std::vector<std::string> fields_of(const PackingRecord& r, const std::string& provenance) {
  return {std::to_string(r.n()),
          std::to_string(r.rank),
          r.label,
          r.d.str(),
          r.L.str(),
          atlas_delta(r),
          std::to_string(r.pattern.bonds.size()),
          std::to_string(r.pattern.rattlers.size()),
          r.certified ? "true" : "false",
          std::to_string(r.confirmations()),
          r.source_text(),
          r.file,
          provenance};
}

}  // namespace

void write_atlas(const AtlasResult& atlas, const std::filesystem::path& dir) {
  const auto files = dir / "atlas";
  std::filesystem::create_directories(files);
  std::set<std::string> written;
  for (const auto& row : atlas.rows) {
    // Through the format table (the text format, by the file's extension), with every digit the
    // polish gave d and the coordinates (more digits asked than known: the known ones, as they
    // are).
    WriteOptions options;
    options.label = row.label;
    options.digits = options.d_digits = std::numeric_limits<int>::max();
    options.comments = {
        "rank: " + std::to_string(row.rank),
        "L: " + row.L.str(),
        "delta: " + atlas_delta(row),
        "source: " + row.source_text(),
        "confirmations: " + std::to_string(row.confirmations()),
        "provenance: " + (atlas.provenance.count(row.label) ? atlas.provenance.at(row.label) : ""),
        std::string("certified: ") + (row.certified ? "yes" : "no") + " (" + row.verdict + ")"};
    if (!row.pattern.rattlers.empty())
      options.comments.push_back(
          "the rattlers' places (free in their cages) are the analysis' long double ones");
    write_packing_file((dir / row.file).string(), row, options);
    written.insert((dir / row.file).filename().string());
  }
  // A rerun over the same range replaces the table: files of rows that left it go too.
  for (const auto& entry : std::filesystem::directory_iterator(files))
    if (entry.path().extension() == ".txt" && !written.count(entry.path().filename().string()))
      std::filesystem::remove(entry.path());
  std::string gaps = table_header(atlas_gaps_table_format());
  for (const auto& g : atlas.gaps)
    gaps += table_line(
        {g.class_id, g.p ? std::to_string(g.p) : "", std::to_string(g.k), std::to_string(g.n),
         g.label_n, g.label_next, format_significant(g.L_n, kLongDoubleDigits),
         format_significant(g.L_next, kLongDoubleDigits), format_significant(g.L_next - g.L_n, 15),
         format_significant(g.delta_difference, 15), g.claim_tight});
  write_whole_file(dir / atlas_gaps_table_format().file, gaps);
  write_whole_file(dir / atlas_table_format().file, atlas_table(atlas));
}

std::string atlas_table(const AtlasResult& atlas) {
  std::string table = table_header(atlas_table_format());
  for (const auto& row : atlas.rows) {
    const auto p = atlas.provenance.find(row.label);
    table += table_line(fields_of(row, p == atlas.provenance.end() ? "" : p->second));
  }
  return table;
}

std::vector<PackingRecord> read_atlas(const std::filesystem::path& csv) {
  std::vector<PackingRecord> rows;
  for (const auto& [number, f] : read_table(csv, atlas_table_format())) {
    long long n = 0, confirmations = 0;
    PackingRecord row;
    try {
      n = std::stoll(f[0]);
      row.rank = static_cast<std::size_t>(std::stoll(f[1]));
      (void)std::stoll(f[6]);
      (void)std::stoll(f[7]);
      const long double d = std::stold(f[3]);
      row.d = PreciseReal(d, f[3], significant_digits(f[3]));
      row.L = PreciseReal(std::stold(f[4]), f[4], significant_digits(f[4]));
      (void)std::stold(f[5]);
      confirmations = std::stoll(f[9]);
    } catch (const std::exception&) {
      throw std::runtime_error(
          fmt::format("{}:{}: a number field is not a number", csv.string(), number));
    }
    row.label = f[2];
    row.certified = f[8] == "true";
    row.sources.push_back({PackingSource::Kind::Table, f[10], 0, confirmations});
    row.file = f[11];
    // The coordinates file gives the pattern (its points and d; bonds come with load_atlas).
    const PointsFile points = read_packing_file((csv.parent_path() / row.file).string());
    if (static_cast<long long>(points.points.size()) != n)
      throw std::runtime_error(fmt::format("{}:{}: {} has {} points, the row says n = {}",
                                           csv.string(), number, row.file, points.points.size(),
                                           n));
    row.pattern.packing.points = points.points;
    row.pattern.packing.d = row.d.value();
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<AtlasGap> read_atlas_gaps(const std::filesystem::path& csv) {
  std::vector<AtlasGap> gaps;
  for (const auto& [number, f] : read_table(csv, atlas_gaps_table_format())) {
    AtlasGap g;
    try {
      g.class_id = f[0];
      g.p = f[1].empty() ? 0 : std::stol(f[1]);
      g.k = std::stol(f[2]);
      g.n = std::stoll(f[3]);
      g.label_n = f[4];
      g.label_next = f[5];
      g.L_n = std::stold(f[6]);
      g.L_next = std::stold(f[7]);
      g.delta_difference = std::stold(f[9]);
      g.claim_tight = f[10];
    } catch (const std::exception&) {
      throw std::runtime_error(
          fmt::format("{}:{}: a number field is not a number", csv.string(), number));
    }
    gaps.push_back(std::move(g));
  }
  return gaps;
}

std::vector<PackingRecord> load_atlas(const std::filesystem::path& csv, long long max_rank) {
  std::vector<PackingRecord> rows;
  for (auto& row : read_atlas(csv)) {
    if (static_cast<long long>(row.rank) > max_rank) continue;
    pipeline::AnalyzeRequest request;
    request.file = (csv.parent_path() / row.file).string();
    request.expected_n = row.n();
    PackingRecord analysed = pipeline::record_of(pipeline::analyze_file(request).analysis);
    analysed.d = row.d;  // the table's digits
    analysed.L = row.L;
    analysed.label = row.label;
    analysed.rank = row.rank;
    analysed.file = row.file;
    analysed.sources = row.sources;
    rows.push_back(std::move(analysed));
  }
  return rows;
}

}  // namespace tripack::jobs
