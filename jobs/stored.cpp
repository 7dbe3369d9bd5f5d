#include "jobs/stored.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "core/io.hpp"
#include "core/ranking.hpp"
#include "core/timing.hpp"

namespace tripack::jobs {

namespace {

store::OpenOptions for_reading() {
  store::OpenOptions options;
  options.create = false;
  options.allow_read_only = true;
  return options;
}

}  // namespace

std::vector<PackingRecord> ranked_packings(const store::ResultsDb& db, long long n,
                                           std::vector<long long>* ids) {
  const std::vector<store::StoredPacking> stored = db.packings(n);
  std::vector<PackingRecord> records;
  for (const auto& p : stored) records.push_back(store::record_of(p));
  const auto order = rank_records(n, records);
  if (ids) {
    ids->clear();
    for (std::size_t i : order) ids->push_back(stored[i].id);
  }
  return records;
}

BestTable best_table(const store::ResultsDb& db, long long n_first, long long n_last) {
  const auto start = Clock::now();
  BestTable table;
  table.db = db.path();
  for (const auto& best : db.best_per_n())
    if (best.n >= n_first && best.n <= n_last)
      table.rows.push_back(ranked_packings(db, best.n).front());
  table.seconds = seconds_since(start);
  return table;
}

BestTable best_table(const std::string& path, long long n_first, long long n_last) {
  const auto start = Clock::now();
  BestTable table = best_table(store::ResultsDb::open(path, for_reading()), n_first, n_last);
  table.seconds = seconds_since(start);
  return table;
}

DbCheck check_database(const std::string& path) {
  const auto start = Clock::now();
  DbCheck check;
  check.db = path;
  check.stats = store::ResultsDb::open(path, for_reading()).statistics();
  check.seconds = seconds_since(start);
  return check;
}

std::vector<PackingRecord> select_packings(const std::string& path, long long n, long long rank,
                                           bool all) {
  const store::ResultsDb db = store::ResultsDb::open(path, for_reading());
  std::vector<PackingRecord> ranked = ranked_packings(db, n);
  if (ranked.empty())
    throw std::invalid_argument(fmt::format("no packings of n = {} in {}", n, path));
  if (all) return ranked;
  if (rank < 1 || rank > static_cast<long long>(ranked.size()))
    throw std::invalid_argument(fmt::format(
        "rank {} is out of range: n = {} has {} stored packing{} in {} (ranks 1..{}: {} .. {})",
        rank, n, ranked.size(), ranked.size() == 1 ? "" : "s", path, ranked.size(),
        ranked.front().label, ranked.back().label));
  return {std::move(ranked[static_cast<std::size_t>(rank - 1)])};
}

namespace {

std::uintmax_t file_bytes(const std::string& path) {
  std::uintmax_t bytes = 0;
  for (const char* suffix : {"", "-wal"}) {
    std::error_code error;
    const auto size = std::filesystem::file_size(path + suffix, error);
    if (!error) bytes += size;
  }
  return bytes;
}

}  // namespace

PruneResult prune_database(const std::string& path, long long keep, long long n_first,
                           long long n_last) {
  if (keep < 1) throw std::invalid_argument("--keep must be at least 1");
  const auto start = Clock::now();
  PruneResult result;
  result.db = path;
  result.keep = keep;
  store::OpenOptions options;
  options.create = false;
  store::ResultsDb db = store::ResultsDb::open(path, options);
  result.bytes_before = file_bytes(path);
  std::vector<long long> doomed;
  for (const auto& best : db.best_per_n()) {
    if (best.n < n_first || best.n > n_last) continue;
    ++result.n_values;
    std::vector<long long> ids;
    const auto ranked = ranked_packings(db, best.n, &ids);
    for (std::size_t r = 0; r < ranked.size(); ++r) {
      if (static_cast<long long>(ranked[r].rank) <= keep)
        ++result.kept;
      else
        doomed.push_back(ids[r]);
    }
  }
  result.removed = static_cast<long long>(doomed.size());
  db.remove_packings(doomed);
  try {
    db.compact();
  } catch (const store::StoreError& e) {
    result.not_compacted = e.what();
  }
  result.bytes_after = file_bytes(path);
  result.seconds = seconds_since(start);
  return result;
}

store::RunRecord run_record_of(const search::SearchResult& result, std::size_t chain,
                               const std::string& tool_version) {
  const search::SearchChain& c = result.chains.at(chain);
  store::RunRecord run;
  run.n = result.request.n;
  run.seed = c.seed;
  run.method = search::search_method(result);
  run.events = c.steps;
  run.seconds = c.seconds;
  run.tool_version = tool_version;
  run.outcome = c.best ? "certified" : "no certified packing";
  if (c.best) run.packing = store::stored_of(*c.best, tool_version);
  return run;
}

std::vector<Packing> stored_starts(const store::ResultsDb& db, long long n, std::size_t count) {
  std::vector<Packing> starts;
  for (const store::StoredPacking& stored : db.packings(n)) {
    if (starts.size() == count) break;
    Packing p;
    p.d = std::stold(stored.d);
    p.points = stored.points;
    starts.push_back(std::move(p));
  }
  return starts;
}

RecordedSearch search_and_record(search::SearchRequest request, const std::string& db,
                                 const JobContext& job) {
  std::optional<store::ResultsDb> store;
  if (!db.empty()) {
    store.emplace(store::ResultsDb::open(db));
    request.starts = stored_starts(*store, request.n, 3);
  }
  RecordedSearch recorded;
  recorded.search = search::run_search(request, job);
  const auto& result = recorded.search;
  if (store)
    for (std::size_t c = 0; c < result.chains.size(); ++c)
      if (!store->record(run_record_of(result, c, job.tool_version)))
        recorded.notes.push_back(
            fmt::format("{} already holds n = {} seed = {} ({}); not recorded again", db, request.n,
                        result.chains[c].seed, search::search_method(result)));
  return recorded;
}

void export_packings(const DbExport& o, std::ostream& out) {
  if (o.all && o.rank != 1) throw std::invalid_argument("--rank and --all exclude each other");
  const PackingFormat* format = o.format.empty() ? nullptr : &format_named(o.format, "--format");
  const Convention convention = convention_from_option(o.convention);
  const bool into_directory =
      !o.output.empty() && (o.all || std::filesystem::is_directory(o.output));
  if (!o.output.empty() && !into_directory) {
    const PackingFormat* named = format_of_extension(o.output);
    if (format && named && format != named)
      throw std::invalid_argument("-o " + o.output + " names another format than --format " +
                                  o.format);
    if (!format) format = named;
  }
  const PackingFormat& chosen = format ? *format : packing_formats().front();
  const auto selected = select_packings(o.db, o.n, o.rank, o.all);
  auto write_options = [&](const PackingRecord& r) {
    WriteOptions w;
    w.convention = convention;
    w.digits = o.digits;
    w.d_digits = std::min(o.digits, kLongDoubleDigits);  // the digits the database keeps of d
    w.label = r.label;
    return w;
  };
  if (o.output.empty()) {
    // Rendered whole before printing. Several packings follow one another (JSON: an array).
    std::ostringstream buffer;
    const bool array = chosen.name == "json" && selected.size() > 1;
    if (array) buffer << "[\n";
    for (std::size_t i = 0; i < selected.size(); ++i) {
      if (i > 0) buffer << (array ? ",\n" : "\n");
      chosen.write(buffer, selected[i], write_options(selected[i]));
    }
    if (array) buffer << "]\n";
    out << buffer.str() << std::flush;
    return;
  }
  const std::filesystem::path dir =
      into_directory ? writable_directory(o.output) : std::filesystem::path();
  for (const auto& r : selected) {
    const std::filesystem::path path = into_directory ? dir / (r.label + chosen.extensions.front())
                                                      : std::filesystem::path(o.output);
    std::ostringstream bytes;
    chosen.write(bytes, r, write_options(r));
    write_whole_file(path, bytes.str());
    out << path.string() << "\n";
  }
}

}  // namespace tripack::jobs
