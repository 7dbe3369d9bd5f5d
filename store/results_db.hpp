// The campaign results database (SPEC §7, issue 11): SQLite in WAL mode. Every finished work
// unit (n, seed) is one transaction (BEGIN IMMEDIATE) holding the run and, when new for its n,
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

struct sqlite3;

namespace tripack::store {

inline constexpr int kSchemaVersion = 1;

class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A distinct packing of one n, as stored. d is text with every digit the analysis had;
// graph_hash identifies the contact graph up to the triangle's 6 symmetries (computed by the
// caller), so (n, graph_hash, d to 12 digits) is one packing.
struct StoredPacking {
  long long n = 0;
  std::string d;
  std::string graph_hash;
  std::vector<Vec2L> points;  // unit triangle, 21 significant digits in the database
  std::vector<Bond> bonds;
  std::vector<int> rattlers;
  bool certified = false;
  std::uint64_t first_seed = 0;
  long long runs = 1;  // units that ended in it
  std::string tool_version;
};

// One finished work unit.
struct RunRecord {
  long long n = 0;
  std::uint64_t seed = 0;
  std::string outcome;  // "certified", "not certified", "error: ..."
  long long events = 0;
  double seconds = 0;
  std::optional<StoredPacking> packing;  // the analysed end state, when usable
  std::string tool_version;
};

struct OpenOptions {
  int busy_timeout_ms = 5000;  // wait this long for a lock held by another writer
};

class ResultsDb {
 public:
  // Creates the file (and its schema) if missing; refuses a file of another schema version, a
  // file that is not a tripack database, and one it cannot write.
  static ResultsDb open(const std::string& path, const OpenOptions& options = {});
  ResultsDb(ResultsDb&&) noexcept;
  ResultsDb& operator=(ResultsDb&&) noexcept;
  ~ResultsDb();

  bool has_run(long long n, std::uint64_t seed) const;
  std::vector<std::uint64_t> finished_seeds(long long n) const;
  long long run_count() const;
  // Records the unit and its packing in one transaction; a unit already recorded is left as it
  // is (false), so a rerun never counts a unit twice.
  bool record(const RunRecord& run);
  std::vector<StoredPacking> packings(long long n) const;  // largest d first
  std::vector<StoredPacking> best_per_n() const;           // one per n, by n
  std::string integrity_check() const;                     // "ok" when sound
  const std::string& path() const { return path_; }

 private:
  ResultsDb(std::string path, sqlite3* db);
  std::string path_;
  sqlite3* db_ = nullptr;
};

}  // namespace tripack::store
