// The results database read the way the rest of tripack ranks packings: the stored
// packings of n in the billiards runs' order, labelled tNa, tNb, ... by
// pipeline::label_order / paper_labels, and the results of `tripack db best`, `db check` and
// `db export` (rendered by report/results/database.hpp). Read commands never create a database.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "core/options.hpp"
#include "core/record.hpp"
#include "formats/formats.hpp"
#include "search/search.hpp"
#include "store/results_db.hpp"

namespace tripack::jobs {

// Every stored packing of n as a record (store::record_of), ranked and labelled by
// core/ranking.hpp like every other list of packings (imports without a seed after the runs'
// packings where d ties). `ids`, when given, receives each one's database row in the same order.
std::vector<PackingRecord> ranked_packings(const store::ResultsDb& db, long long n,
                                           std::vector<long long>* ids = nullptr);

// `tripack db best`: the best packing of every n in [n_first, n_last] that has one.
struct BestTable {
  std::string db;
  std::vector<PackingRecord> rows;  // by n
  double seconds = 0;
};
BestTable best_table(const store::ResultsDb& db, long long n_first, long long n_last);
// Opens `path` for reading (it must exist).
BestTable best_table(const std::string& path, long long n_first, long long n_last);

// `tripack db check`.
struct DbCheck {
  std::string db;
  int schema_version = store::kSchemaVersion;
  store::DbStatistics stats;
  long long duplicates() const { return stats.duplicate_runs + stats.duplicate_packings; }
  bool ok() const { return stats.integrity == "ok" && duplicates() == 0; }
  double seconds = 0;
};
DbCheck check_database(const std::string& path);

// `tripack db export`: the packings of n asked for: rank `rank` (1 = the best), or all of them.
// Throws std::invalid_argument (one line) when n has no stored packing or the rank is not one;
// store::StoreError when there is no database.
std::vector<PackingRecord> select_packings(const std::string& path, long long n, long long rank,
                                           bool all);

// `tripack db prune`: keeps the best `keep` stored packings of every n in [n_first, n_last]
// (ranked_packings' order) and deletes the others; every run stays, so a rerun of the campaign
// still skips it (a run that later finds a deleted packing stores it anew). Then compacts the
// file (VACUUM, WAL folded in) so that it alone holds everything: long campaigns (the atlas)
// keep and commit their database this way. Throws like ResultsDb::open for the database and
// std::invalid_argument for keep < 1.
struct PruneResult {
  std::string db;
  long long keep = 0;
  long long n_values = 0;  // values of n in the range with stored packings
  long long kept = 0, removed = 0;
  std::uintmax_t bytes_before = 0, bytes_after = 0;  // the file with its WAL
  std::string not_compacted;                         // why compaction failed (the deletions stand)
  double seconds = 0;
};
PruneResult prune_database(const std::string& path, long long keep, long long n_first,
                           long long n_last);

// A search chain as a campaign database unit (n, seed, method search::search_method): its best
// certified packing; steps as events.
store::RunRecord run_record_of(const search::SearchResult& result, std::size_t chain,
                               const std::string& tool_version);
// `tripack db export`: stored packings of n as coordinate files (best first: rank 1 is tNa).
struct DbExport {
  std::string db = "tripack.db";
  long long n = 0;
  std::string format;  // a format table name; empty: -o FILE's extension, else txt
  std::string convention = "unit-triangle";
  long long rank = 1;  // 1 = the best
  bool all = false;
  std::string output;  // a file (one packing) or a directory (--all, or an existing directory)
  int digits = 21;     // of the coordinates; d, L, r, S get at most the 18 stored

  void declare(OptionList& o) {
    o.option("N", n, "number of disks").required().range(2, 1e8);
    o.option("--db", db, "results database");
    o.option("--format", format,
             "one of " + format_names() +
                 " (records: i x y with d, r, S in the header); "
                 "default: -o's extension, else txt");
    o.option("--convention", convention, kConventionHelp);
    o.option("--rank", rank, "which packing: 1 = the best").range(1, 1e9);
    o.flag("--all", all, "every stored packing of N (not with --rank)");
    o.option("-o,--output", output,
             "a file (one packing) or a directory (--all: one file per packing, named by its "
             "label); default: stdout");
    o.option("--digits", digits,
             "significant digits of the coordinates (the database keeps 21; d keeps 18)")
        .range(1, 21);
  }
};
// Everything the request decides is checked before the database is read. Without -o the
// packings go to `out` (several: one after another; JSON: an array); with -o, each file's path
// goes to `out`.
void export_packings(const DbExport& request, std::ostream& out);

// `tripack search --db FILE`: the database (opened, or created, before any work) gives its best
// packings of n as starts, and every chain is recorded as a unit before the result is returned.
// Without a database: the search alone. `notes`: chains already recorded (not recorded again).
struct RecordedSearch {
  search::SearchResult search;
  std::vector<std::string> notes;
};
RecordedSearch search_and_record(search::SearchRequest request, const std::string& db,
                                 const JobContext& job);

// The best `count` stored packings of n as search starts (largest d first).
std::vector<Packing> stored_starts(const store::ResultsDb& db, long long n, std::size_t count);

}  // namespace tripack::jobs
