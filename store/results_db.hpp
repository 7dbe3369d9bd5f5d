// The campaign results database (docs/campaigns.md): SQLite in WAL mode. Every finished
// work unit (n, seed) is one transaction (BEGIN IMMEDIATE) holding the run and, when new for its n,
// the packing it found; so a killed campaign loses at most the unit it was running, and a rerun
// skips every unit already recorded. Errors are StoreError with one line naming the file.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/packing.hpp"
#include "core/record.hpp"

struct sqlite3;

namespace tripack::store {

// Version 2 (db import): packings record where they came from (origin "campaign" or
// "import", source = the imported file's name) and imported ones have no seed (first_seed NULL).
// A version-1 file is migrated in place when opened (one transaction; every row kept).
// Version 3 (search): a run has a method ("billiards", or "search S s" for a search
// chain of S seconds) and a unit is (n, seed, method). Older files are migrated in place.
inline constexpr int kSchemaVersion = 3;

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A distinct packing of one n, as stored. d is text with every digit the analysis had;
// graph_hash identifies the contact graph up to the triangle's 6 symmetries (computed by the
// caller), so (n, graph_hash, d to 12 digits) is one packing.
struct StoredPacking {
  long long id = 0;  // the row's id once stored (0 before)
  long long n = 0;
  std::string d;
  std::string graph_hash;
  std::vector<Vec2L> points;  // unit triangle, 21 significant digits in the database
  std::vector<Bond> bonds;
  std::vector<int> rattlers;
  bool certified = false;
  std::uint64_t first_seed = 0;  // the first run that ended in it, when has_seed
  bool has_seed = true;          // false: imported, and no run has ended in it since
  long long runs = 1;            // units that ended in it (0 for an import no run found)
  // Of those, the units that started from nothing stored: billiards runs and search chains, not
  // a search continued from stored packings. Read from the runs table; never written.
  long long independent_runs = 0;
  std::string origin = "campaign";  // "campaign" (a run found it) or "import" (from a file)
  std::string source;               // the imported file's name; empty for a campaign's
  std::string tool_version;
};

// The row as the one packing record (core/record.hpp) and back: sources from origin, seed and
// runs ("campaign" is a billiards source, "import" an import source named by `source`, plus a
// billiards source once a run has found it), d as stored (kLongDoubleDigits digits).
PackingRecord record_of(const StoredPacking& stored);
StoredPacking stored_of(const PackingRecord& record, const std::string& tool_version);

// What `tripack db check` reports. Counts come from the tables themselves (GROUP BY), so a
// duplicate the unique constraints should have prevented is seen.
struct DbStatistics {
  std::string integrity;  // PRAGMA integrity_check: "ok" when sound
  long long runs = 0;
  long long packings = 0;
  long long imported = 0;            // packings whose origin is "import"
  long long n_values = 0;            // distinct n with a run or a packing
  long long duplicate_runs = 0;      // rows beyond the first sharing (n, seed)
  long long duplicate_packings = 0;  // rows beyond the first sharing (n, graph_hash, d to 12
                                     // significant digits)
};

// Whether add_packings stored a packing, or found it already there (same n, contact graph and d
// to 12 digits): then nothing changed and `id` is the row that was there.
struct AddOutcome {
  long long id = 0;
  bool added = false;
};

// One finished work unit.
struct RunRecord {
  long long n = 0;
  std::uint64_t seed = 0;
  std::string method = "billiards";  // or "search S s": a search chain (search/search.hpp)
  std::string outcome;               // "certified", "not certified", "error: ..."
  long long events = 0;
  double seconds = 0;
  std::optional<StoredPacking> packing;  // the analysed end state, when usable
  std::string tool_version;
};

// An independent unit (a billiards run or a search chain from random starts) and the stored
// packing it ended in: who reached what (the atlas's provenance column).
struct UnitOfPacking {
  long long packing_id = 0;
  std::string method;
  std::uint64_t seed = 0;
  double seconds = 0;
};

struct OpenOptions {
  int busy_timeout_ms = 5000;  // wait this long for a lock held by another writer
  // false: the file must exist (the read commands never create an empty database).
  bool create = true;
  // true: a file this process cannot write is still read (the read commands: a database on
  // read-only media or of another user); writing to it then fails with "read-only".
  bool allow_read_only = false;
};

class ResultsDb {
 public:
  // Creates the file (and its schema) if missing and options.create; refuses a file of another
  // schema version (a version-1 file is migrated), a file that is not a tripack database (also
  // an SQLite file without tripack's tables), and one it cannot write. A database already at
  // this version is opened without a write lock, so reading works while another process writes.
  static ResultsDb open(const std::string& path, const OpenOptions& options = {});
  ResultsDb(ResultsDb&&) noexcept;
  ResultsDb& operator=(ResultsDb&&) noexcept;
  ~ResultsDb();

  bool has_run(long long n, std::uint64_t seed, const std::string& method = "billiards") const;
  std::vector<std::uint64_t> finished_seeds(long long n,
                                            const std::string& method = "billiards") const;
  long long run_count() const;
  // Records the unit and its packing in one transaction; a unit already recorded is left as it
  // is (false), so a rerun never counts a unit twice.
  bool record(const RunRecord& run);
  // Packings that come with no run (db import), all in one transaction: each is added unless the
  // same packing is there already (see AddOutcome); any failure stores none of them.
  std::vector<AddOutcome> add_packings(const std::vector<StoredPacking>& packings);
  // Deletes these packings in one transaction; the runs that ended in them stay (their outcome
  // kept, their packing unlinked). A later run that finds one again stores it anew.
  void remove_packings(const std::vector<long long>& ids);
  // Folds the WAL into the main file and rebuilds it without free pages (VACUUM), so the file
  // alone holds everything, as small as it can be: for copying or committing it. Needs no other
  // connection to be open.
  void compact();
  std::vector<StoredPacking> packings(long long n) const;  // largest d first
  std::vector<StoredPacking> best_per_n() const;           // one per n, by n
  // The independent units of n whose packing is stored, by method and seed.
  std::vector<UnitOfPacking> independent_units(long long n) const;
  std::string integrity_check() const;  // "ok" when sound
  DbStatistics statistics() const;      // integrity and counts
  const std::string& path() const { return path_; }

 private:
  ResultsDb(std::string path, sqlite3* db);
  static ResultsDb open_read_only(const std::string& path, const OpenOptions& options);
  std::string path_;
  sqlite3* db_ = nullptr;
};

}  // namespace tripack::store
