#include "jobs/import.hpp"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "analysis/compare.hpp"
#include "core/io.hpp"
#include "core/points.hpp"
#include "core/timing.hpp"
#include "formats/formats.hpp"
#include "jobs/stored.hpp"
#include "pipeline/analyze.hpp"
#include "runner/runner.hpp"
#include "store/results_db.hpp"

namespace tripack::jobs {

namespace {

// One file read, checked and analysed; `stored` is what goes into the database.
ImportedPacking analyse_file(const ImportRequest& request, const std::string& path,
                             const std::string& tool_version, store::StoredPacking& stored) {
  const auto start = Clock::now();
  ImportedPacking out;
  out.file = path;
  out.source = std::filesystem::path(path).filename().string();
  PointsReading reading;
  try {
    PointsFile file = read_packing_file(path);  // its errors name the file already
    out.layout = file.layout;
    try {
      reading = packing_from_points(std::move(file), request.convention, std::nullopt);
    } catch (const InputError& e) {
      throw InputError(path + ": " + e.what());
    }
  } catch (const InputError& e) {
    throw ImportError(e.what());
  }
  out.convention = reading.convention;
  out.warnings = reading.warnings;
  const Packing& start_packing = reading.packing;
  out.n = static_cast<long long>(start_packing.size());
  out.d_file = format_significant(start_packing.d, kLongDoubleDigits);
  if (reading.stated_d && *reading.stated_d > start_packing.d * (1 + kOverlapTolerance))
    throw ImportError(fmt::format(
        "{}: overlapping disks: the file states d = {} but its closest centres are {} apart "
        "(the disks overlap by {:.3g} of d); refused, nothing stored",
        path, format_significant(*reading.stated_d, kLongDoubleDigits), out.d_file,
        static_cast<double>(1 - start_packing.d / *reading.stated_d)));
  if (reading.header_d_differs && !request.accept_header_d)
    throw ImportError(fmt::format(
        "{}: the header's d = {} differs from the points' d = {}; refused, nothing stored "
        "(--accept-header-d stores it)",
        path, format_significant(*reading.stated_d, kLongDoubleDigits), out.d_file));
  const pipeline::Analysis analysis = pipeline::analyze_packing(start_packing, {});
  out.verdict = analysis.status();
  if (!analysis.certified())
    throw ImportError(
        fmt::format("{}: not certified ({}); refused, nothing stored", path, out.verdict));
  PackingRecord record = pipeline::record_of(analysis);
  record.sources.push_back({PackingSource::Kind::Import, out.source});
  out.d = record.d.str(kLongDoubleDigits);
  out.graph_hash = record.graph_hash;
  out.bonds = record.bonds();
  out.rattlers = record.pattern.rattlers;
  stored = store::stored_of(record, tool_version);
  out.seconds = seconds_since(start);
  return out;
}

}  // namespace

ImportResult import_packings(const ImportRequest& request, const JobContext& job) {
  const auto start = Clock::now();
  if (request.files.empty()) throw ImportError("db import needs at least one file");
  ImportResult result;
  result.db = request.db;
  // A database that exists is checked before the analyses (a text file as --db, another
  // version), so a long analysis cannot end in a refusal; a missing one is created only when
  // there is something to store.
  {
    std::error_code ec;
    if (std::filesystem::exists(request.db, ec)) store::ResultsDb::open(request.db);
  }
  // The files on the runner's threads; the first refusal stops the job (rethrown here).
  std::vector<store::StoredPacking> stored(request.files.size());
  result.packings.resize(request.files.size());
  ProgressCounter counter("import", static_cast<long long>(request.files.size()));
  JobItems items;
  items.count = request.files.size();
  items.run = [&](std::size_t i) {
    result.packings[i] = analyse_file(request, request.files[i], job.tool_version, stored[i]);
    return std::string();
  };
  items.finished = [&](std::size_t i, const std::string&) {
    job.report(counter.finished(request.files[i]));
  };
  if (ThreadExecutor(request.threads).run_items(items, job.cancel).cancelled) {
    ImportResult cancelled;
    cancelled.db = request.db;
    cancelled.cancelled = true;
    return cancelled;
  }
  store::ResultsDb db = store::ResultsDb::open(request.db);
  const std::vector<store::AddOutcome> outcomes = db.add_packings(stored);
  for (std::size_t i = 0; i < outcomes.size(); ++i) {
    auto& x = result.packings[i];
    x.added = outcomes[i].added;
    x.id = outcomes[i].id;
    (x.added ? result.added : result.already) += 1;
    std::vector<long long> ids;
    const auto ranked = ranked_packings(db, x.n, &ids);
    for (std::size_t r = 0; r < ranked.size(); ++r)
      if (ids[r] == x.id) x.label = ranked[r].label;
  }
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
