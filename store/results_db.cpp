#include "store/results_db.hpp"

#include <fmt/format.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <utility>

#include "core/io.hpp"

namespace tripack::store {

namespace {

// The packings table of version 2, under a given name (the migration builds it beside the old
// one). first_seed is NULL for a packing imported from a file that no run has found.
std::string packings_table(const char* name) {
  return fmt::format(R"sql(
CREATE TABLE IF NOT EXISTS {}(
  id INTEGER PRIMARY KEY,
  n INTEGER NOT NULL,
  d TEXT NOT NULL,
  d_key TEXT NOT NULL,
  d_value REAL NOT NULL,
  graph_hash TEXT NOT NULL,
  points TEXT NOT NULL,
  bonds TEXT NOT NULL,
  rattlers TEXT NOT NULL,
  certified INTEGER NOT NULL,
  first_seed INTEGER,
  runs INTEGER NOT NULL,
  origin TEXT NOT NULL,
  source TEXT,
  tool_version TEXT NOT NULL,
  UNIQUE(n, graph_hash, d_key));
)sql",
                     name);
}

// The runs table of version 3 (a unit is (n, seed, method): a billiards run or a search chain),
// under a given name (the migration builds it beside the old one).
std::string runs_table(const char* name) {
  return fmt::format(R"sql(
CREATE TABLE IF NOT EXISTS {}(
  n INTEGER NOT NULL,
  seed INTEGER NOT NULL,
  method TEXT NOT NULL DEFAULT 'billiards',
  outcome TEXT NOT NULL,
  events INTEGER NOT NULL,
  seconds REAL NOT NULL,
  packing_id INTEGER REFERENCES packings(id),
  tool_version TEXT NOT NULL,
  PRIMARY KEY(n, seed, method));
)sql",
                     name);
}

constexpr const char* kMetaTable =
    "CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);";

// Version 1 -> 2: the packings table rebuilt with origin and source columns and a nullable
// first_seed (SQLite cannot change a column's NOT NULL in place): create the new table, copy,
// drop the old, rename (SQLite's documented order, which leaves runs' REFERENCES packings(id)
// naming the new table). Run inside the open's write transaction with foreign keys off.
constexpr const char* kMigrate1To2 = R"sql(
INSERT INTO packings_v2(id, n, d, d_key, d_value, graph_hash, points, bonds, rattlers, certified,
                        first_seed, runs, origin, source, tool_version)
  SELECT id, n, d, d_key, d_value, graph_hash, points, bonds, rattlers, certified, first_seed,
         runs, 'campaign', NULL, tool_version FROM packings;
DROP TABLE packings;
ALTER TABLE packings_v2 RENAME TO packings;
UPDATE meta SET value = '2' WHERE key = 'schema_version';
)sql";

// Version 2 -> 3: runs gained `method` (every older run is a billiards run) and the key
// (n, seed, method), so a search chain and a billiards run of one seed are two units. The same
// create-copy-drop-rename order as above.
constexpr const char* kMigrate2To3 = R"sql(
INSERT INTO runs_v3(n, seed, method, outcome, events, seconds, packing_id, tool_version)
  SELECT n, seed, 'billiards', outcome, events, seconds, packing_id, tool_version FROM runs;
DROP TABLE runs;
ALTER TABLE runs_v3 RENAME TO runs;
UPDATE meta SET value = '3' WHERE key = 'schema_version';
)sql";

// The schema versions open() migrates in place.
bool migratable(const std::string& version) {
  return version == "1" || version == "2";
}

// A prepared statement, finalized on scope exit.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& path, const char* sql) : db_(db), path_(path) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail("prepare");
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement& bind(int i, long long v) {
    sqlite3_bind_int64(stmt_, i, v);
    return *this;
  }
  Statement& bind(int i, double v) {
    sqlite3_bind_double(stmt_, i, v);
    return *this;
  }
  Statement& bind(int i, const std::string& v) {
    sqlite3_bind_text(stmt_, i, v.c_str(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
    return *this;
  }
  // True while a row is available.
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    fail("step");
  }
  // Ready to run again with new bindings.
  void reset() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
  }
  long long integer(int c) const { return sqlite3_column_int64(stmt_, c); }
  bool is_null(int c) const { return sqlite3_column_type(stmt_, c) == SQLITE_NULL; }
  double real(int c) const { return sqlite3_column_double(stmt_, c); }
  std::string text(int c) const {
    const auto* p = sqlite3_column_text(stmt_, c);
    return p ? reinterpret_cast<const char*>(p) : "";
  }

 private:
  [[noreturn]] void fail(const char* what) const;
  sqlite3* db_;
  const std::string& path_;
  sqlite3_stmt* stmt_ = nullptr;
};

// One line for an SQLite failure on `path`, naming the usual causes plainly.
[[noreturn]] void fail_on(sqlite3* db, const std::string& path, const char* what) {
  const int code = db ? sqlite3_errcode(db) & 0xff : SQLITE_CANTOPEN;
  const std::string detail = db ? sqlite3_errmsg(db) : "cannot open";
  switch (code) {
    case SQLITE_NOTADB:
      throw StoreError(fmt::format("{} is not a tripack database ({})", path, detail));
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      throw StoreError(
          fmt::format("database {} is locked by another process ({}: {})", path, what, detail));
    case SQLITE_READONLY:
      throw StoreError(fmt::format("cannot write to database {} (read-only: {})", path, detail));
    case SQLITE_CANTOPEN:
      throw StoreError(fmt::format("cannot open database {} ({})", path, detail));
    default:
      throw StoreError(fmt::format("database {}: {} failed: {}", path, what, detail));
  }
}

void Statement::fail(const char* what) const {
  fail_on(db_, path_, what);
}

void exec(sqlite3* db, const std::string& path, const char* sql) {
  char* message = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &message) != SQLITE_OK) {
    sqlite3_free(message);
    fail_on(db, path, sql);
  }
}

std::string points_text(const std::vector<Vec2L>& points) {
  std::string s;
  for (const auto& p : points)
    s += format_significant(p.x, 21) + " " + format_significant(p.y, 21) + "\n";
  return s;
}

std::vector<Vec2L> parse_points(const std::string& text) {
  std::vector<Vec2L> points;
  std::istringstream in(text);
  for (long double x, y; in >> x >> y;) points.push_back({x, y});
  return points;
}

std::string bonds_text(const std::vector<Bond>& bonds) {
  std::string s;
  for (const auto& b : bonds) s += fmt::format("{} {}\n", b.a, b.b);
  return s;
}

std::vector<Bond> parse_bonds(const std::string& text) {
  std::vector<Bond> bonds;
  std::istringstream in(text);
  for (int a, b; in >> a >> b;) bonds.push_back(Bond{a, b});
  return bonds;
}

std::string ints_text(const std::vector<int>& v) {
  return fmt::format("{}", fmt::join(v, " "));
}

std::vector<int> parse_ints(const std::string& text) {
  std::vector<int> v;
  std::istringstream in(text);
  for (int x; in >> x;) v.push_back(x);
  return v;
}

// The key under which two stored d are the same packing's: 12 significant digits.
std::string d_key(const std::string& d) {
  return identity_d_key(std::stold(d));
}

// The units that started from nothing stored or built (search/search.hpp's method names).
constexpr const char* kIndependentMethod =
    "runs.method NOT LIKE '%, continued' AND runs.method NOT LIKE '%, from builders%'";

const std::string kPackingColumns =
    "id, n, d, graph_hash, points, bonds, rattlers, certified, first_seed, runs, origin, source, "
    "tool_version, (SELECT COUNT(*) FROM runs WHERE runs.packing_id = packings.id AND " +
    std::string(kIndependentMethod) + ")";
// Largest d first; then most runs, then the first seed (imports without one last), then age.
constexpr const char* kPackingOrder = "d_value DESC, runs DESC, first_seed IS NULL, first_seed, id";

StoredPacking packing_from_row(const Statement& s) {
  StoredPacking p;
  p.id = s.integer(0);
  p.n = s.integer(1);
  p.d = s.text(2);
  p.graph_hash = s.text(3);
  p.points = parse_points(s.text(4));
  p.bonds = parse_bonds(s.text(5));
  p.rattlers = parse_ints(s.text(6));
  p.certified = s.integer(7) != 0;
  p.has_seed = !s.is_null(8);
  p.first_seed = p.has_seed ? static_cast<std::uint64_t>(s.integer(8)) : 0;
  p.runs = s.integer(9);
  p.origin = s.text(10);
  p.source = s.text(11);
  p.tool_version = s.text(12);
  p.independent_runs = s.integer(13);
  return p;
}

// The row of the same packing (core/record.hpp's same_packing: n, contact graph, d), if stored.
std::optional<long long> find_packing(sqlite3* db, const std::string& path,
                                      const StoredPacking& p) {
  Statement find(db, path, "SELECT id, d FROM packings WHERE n = ?1 AND graph_hash = ?2");
  find.bind(1, p.n).bind(2, p.graph_hash);
  const IdentityFields wanted{p.n, p.graph_hash, std::stold(p.d)};
  while (find.step()) {
    const std::string d = find.text(1);
    if (same_packing(wanted, {p.n, p.graph_hash, std::stold(d)})) return find.integer(0);
  }
  return std::nullopt;
}

// Inserts a packing; first_seed is NULL when it has no seed (an import).
long long insert_packing(sqlite3* db, const std::string& path, const StoredPacking& p) {
  Statement add(db, path,
                "INSERT INTO packings(n, d, d_key, d_value, graph_hash, points, bonds, rattlers, "
                "certified, first_seed, runs, origin, source, tool_version) "
                "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14)");
  add.bind(1, p.n)
      .bind(2, p.d)
      .bind(3, d_key(p.d))
      .bind(4, static_cast<double>(std::stold(p.d)))
      .bind(5, p.graph_hash)
      .bind(6, points_text(p.points))
      .bind(7, bonds_text(p.bonds))
      .bind(8, ints_text(p.rattlers))
      .bind(9, static_cast<long long>(p.certified))
      .bind(11, p.runs)
      .bind(12, p.origin)
      .bind(14, p.tool_version);
  if (p.has_seed) add.bind(10, static_cast<long long>(p.first_seed));  // else NULL
  if (!p.source.empty()) add.bind(13, p.source);                       // else NULL
  add.step();
  return sqlite3_last_insert_rowid(db);
}

// The schema version the file records; nullopt when it has no meta table or no version row.
std::optional<std::string> schema_version(sqlite3* db, const std::string& path) {
  Statement meta(db, path, "SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = 'meta'");
  if (!meta.step()) return std::nullopt;
  Statement version(db, path, "SELECT value FROM meta WHERE key = 'schema_version'");
  if (!version.step()) return std::nullopt;
  return version.text(0);
}

long long table_count(sqlite3* db, const std::string& path) {
  Statement s(db, path, "SELECT COUNT(*) FROM sqlite_master WHERE type = 'table'");
  s.step();
  return s.integer(0);
}

[[noreturn]] void wrong_version(const std::string& path, const std::string& version) {
  throw StoreError(fmt::format("database {} has schema version {}; this tripack reads version {}",
                               path, version, kSchemaVersion));
}

}  // namespace

namespace {

// A new database appears whole or not at all: its schema is written into a private file beside
// it, which is then hard-linked to `path` (link(2) fails if `path` exists, so a database another
// process created meanwhile is never replaced). A process killed while creating leaves no
// tableless `path` behind (the soak test's kill at 173 ms did), at most its private file.
void create_whole(const std::string& path) {
  const std::string fresh = fmt::format("{}.creating.{}", path, ::getpid());
  std::filesystem::remove(fresh);
  sqlite3* db = nullptr;
  const int rc =
      sqlite3_open_v2(fresh.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
  auto fail = [&](const std::string& detail) {
    sqlite3_close(db);
    std::filesystem::remove(fresh);
    throw StoreError(fmt::format("cannot create database {} ({})", path, detail));
  };
  if (rc != SQLITE_OK) fail(db ? sqlite3_errmsg(db) : "out of memory");
  std::string sql = "PRAGMA journal_mode=WAL; BEGIN; ";
  sql += packings_table("packings");
  sql += kMetaTable;
  sql += runs_table("runs");
  sql += fmt::format("INSERT INTO meta(key, value) VALUES ('schema_version', '{}'); COMMIT;",
                     kSchemaVersion);
  if (sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK)
    fail(sqlite3_errmsg(db));
  // The last connection's close folds the WAL into the file and removes -wal and -shm.
  if (sqlite3_close(db) != SQLITE_OK) fail("close failed");
  db = nullptr;
  const int linked = ::link(fresh.c_str(), path.c_str());
  const int why = errno;
  std::filesystem::remove(fresh);
  if (linked != 0 && why != EEXIST)
    throw StoreError(fmt::format("cannot create database {} ({})", path, std::strerror(why)));
}

}  // namespace

ResultsDb ResultsDb::open(const std::string& path, const OpenOptions& options) {
  {
    std::error_code ec;
    const bool exists = std::filesystem::exists(path, ec);
    if (!exists && !options.create)
      throw StoreError(fmt::format(
          "no database {} (a campaign or db import creates one; give --db FILE)", path));
    if (!exists) create_whole(path);
  }
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | (options.create ? SQLITE_OPEN_CREATE : 0);
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    const std::string detail = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw StoreError(fmt::format("cannot open database {} ({})", path, detail));
  }
  if (sqlite3_db_readonly(db, "main") == 1) {
    sqlite3_close(db);
    if (!options.allow_read_only)
      throw StoreError(fmt::format("cannot write to database {} (read-only)", path));
    return open_read_only(path, options);
  }
  ResultsDb out(path, db);
  sqlite3_busy_timeout(db, options.busy_timeout_ms);
  exec(db, path, "PRAGMA synchronous=NORMAL");
  // Reading the schema is the first access to the file: a text file fails here (not a database).
  const long long tables = table_count(db, path);
  const auto version = schema_version(db, path);
  if (tables > 0 && !version)
    throw StoreError(fmt::format(
        "{} is not a tripack database (an SQLite database without tripack's tables)", path));
  if (version && *version != std::to_string(kSchemaVersion) && !migratable(*version))
    wrong_version(path, *version);
  if (tables == 0 && !options.create)
    throw StoreError(fmt::format("{} is not a tripack database (it is empty)", path));
  if (!version || migratable(*version)) {
    // A new file, or an older version: written in one transaction, checked again inside it (another
    // process may have created or migrated it meanwhile). WAL: readers do not block the writer,
    // and a commit survives a killed process.
    exec(db, path, "PRAGMA journal_mode=WAL");
    exec(db, path, "BEGIN IMMEDIATE");
    try {
      const auto now = schema_version(db, path);
      if (!now) {
        if (table_count(db, path) > 0)
          throw StoreError(fmt::format(
              "{} is not a tripack database (an SQLite database without tripack's tables)", path));
        exec(db, path, packings_table("packings").c_str());
        exec(db, path, kMetaTable);
        exec(db, path, runs_table("runs").c_str());
        Statement set(db, path, "INSERT INTO meta(key, value) VALUES ('schema_version', ?1)");
        set.bind(1, std::to_string(kSchemaVersion)).step();
      } else if (migratable(*now)) {
        if (*now == "1") {
          exec(db, path, packings_table("packings_v2").c_str());
          exec(db, path, kMigrate1To2);
        }
        exec(db, path, runs_table("runs_v3").c_str());
        exec(db, path, kMigrate2To3);
      } else if (*now != std::to_string(kSchemaVersion)) {
        wrong_version(path, *now);
      }
      exec(db, path, "COMMIT");
    } catch (...) {
      sqlite3_exec(db, "ROLLBACK", nullptr, nullptr, nullptr);
      throw;
    }
  }
  // Outside any transaction (the pragma is a no-op inside one).
  exec(db, path, "PRAGMA foreign_keys=ON");
  return out;
}

// A file this process cannot write, opened for reading only. A WAL reader needs the -shm file
// beside the database; where it cannot be created (a read-only directory), the file is read as
// immutable (no locks: right for read-only media, where nobody writes it).
ResultsDb ResultsDb::open_read_only(const std::string& path, const OpenOptions& options) {
  std::string uri = "file:";
  for (const char c : path)
    uri += (c == '?' || c == '#' || c == '%')
               ? fmt::format("%{:02X}", static_cast<unsigned>(static_cast<unsigned char>(c)))
               : std::string(1, c);
  for (const bool immutable : {false, true}) {
    sqlite3* db = nullptr;
    const std::string name = immutable ? uri + "?immutable=1" : uri;
    if (sqlite3_open_v2(name.c_str(), &db, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, nullptr) !=
        SQLITE_OK) {
      const std::string detail = db ? sqlite3_errmsg(db) : "out of memory";
      sqlite3_close(db);
      throw StoreError(fmt::format("cannot open database {} ({})", path, detail));
    }
    sqlite3_busy_timeout(db, options.busy_timeout_ms);
    const int probe =
        sqlite3_exec(db, "SELECT COUNT(*) FROM sqlite_master", nullptr, nullptr, nullptr);
    if (probe != SQLITE_OK && !immutable) {  // e.g. SQLITE_READONLY_CANTINIT: no -shm
      sqlite3_close(db);
      continue;
    }
    ResultsDb out(path, db);
    const auto version = schema_version(db, path);  // a text file fails here
    if (!version)
      throw StoreError(
          fmt::format("{} is not a tripack database (read-only, without tripack's "
                      "tables)",
                      path));
    if (migratable(*version))
      throw StoreError(
          fmt::format("database {} has schema version {} and is read-only here: "
                      "open it once with write access to migrate it",
                      path, *version));
    if (*version != std::to_string(kSchemaVersion)) wrong_version(path, *version);
    return out;
  }
  throw StoreError(fmt::format("cannot open database {} (read-only)", path));
}

ResultsDb::ResultsDb(std::string path, sqlite3* db) : path_(std::move(path)), db_(db) {}

ResultsDb::ResultsDb(ResultsDb&& other) noexcept
    : path_(std::move(other.path_)), db_(std::exchange(other.db_, nullptr)) {}

ResultsDb& ResultsDb::operator=(ResultsDb&& other) noexcept {
  std::swap(path_, other.path_);
  std::swap(db_, other.db_);
  return *this;
}

ResultsDb::~ResultsDb() {
  sqlite3_close(db_);
}

bool ResultsDb::has_run(long long n, std::uint64_t seed, const std::string& method) const {
  Statement s(db_, path_, "SELECT 1 FROM runs WHERE n = ?1 AND seed = ?2 AND method = ?3");
  s.bind(3, method);
  return s.bind(1, n).bind(2, static_cast<long long>(seed)).step();
}

std::vector<std::uint64_t> ResultsDb::finished_seeds(long long n, const std::string& method) const {
  Statement s(db_, path_, "SELECT seed FROM runs WHERE n = ?1 AND method = ?2 ORDER BY seed");
  s.bind(2, method);
  s.bind(1, n);
  std::vector<std::uint64_t> seeds;
  while (s.step()) seeds.push_back(static_cast<std::uint64_t>(s.integer(0)));
  return seeds;
}

long long ResultsDb::run_count() const {
  Statement s(db_, path_, "SELECT COUNT(*) FROM runs");
  s.step();
  return s.integer(0);
}

bool ResultsDb::record(const RunRecord& run) {
  exec(db_, path_, "BEGIN IMMEDIATE");
  try {
    if (has_run(run.n, run.seed, run.method)) {
      exec(db_, path_, "ROLLBACK");
      return false;
    }
    long long packing_id = -1;
    if (run.packing) {
      StoredPacking p = *run.packing;
      if (const auto id = find_packing(db_, path_, p)) {
        packing_id = *id;
        // first_seed is the smallest seed that found it, whatever order the units finished in
        // (threads, ranks); an imported packing a run finds gets its first seed now.
        Statement bump(db_, path_,
                       "UPDATE packings SET runs = runs + 1, first_seed = MIN(COALESCE(first_seed, "
                       "?2), ?2) WHERE id = ?1");
        bump.bind(1, packing_id).bind(2, static_cast<long long>(run.seed)).step();
        // A campaign's packing keeps the coordinates of that smallest seed's run, so the
        // database is the same for any order of the units; an import keeps the file's.
        Statement adopt(db_, path_,
                        "UPDATE packings SET d = ?2, d_value = ?3, points = ?4, bonds = ?5, "
                        "rattlers = ?6 WHERE id = ?1 AND origin = 'campaign' AND first_seed = ?7");
        adopt.bind(1, packing_id)
            .bind(2, p.d)
            .bind(3, static_cast<double>(std::stold(p.d)))
            .bind(4, points_text(p.points))
            .bind(5, bonds_text(p.bonds))
            .bind(6, ints_text(p.rattlers))
            .bind(7, static_cast<long long>(run.seed))
            .step();
      } else {
        p.first_seed = run.seed;
        p.has_seed = true;
        p.runs = 1;
        p.origin = "campaign";
        p.source.clear();
        p.tool_version = run.tool_version;
        packing_id = insert_packing(db_, path_, p);
      }
    }
    Statement add(db_, path_,
                  "INSERT INTO runs(n, seed, outcome, events, seconds, packing_id, tool_version, "
                  "method) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8)");
    add.bind(1, run.n)
        .bind(2, static_cast<long long>(run.seed))
        .bind(3, run.outcome)
        .bind(4, run.events)
        .bind(5, run.seconds)
        .bind(7, run.tool_version)
        .bind(8, run.method);
    if (packing_id >= 0) add.bind(6, packing_id);  // else NULL
    add.step();
    exec(db_, path_, "COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  return true;
}

std::vector<AddOutcome> ResultsDb::add_packings(const std::vector<StoredPacking>& packings) {
  std::vector<AddOutcome> outcomes;
  exec(db_, path_, "BEGIN IMMEDIATE");
  try {
    for (const auto& p : packings) {
      if (const auto id = find_packing(db_, path_, p)) {
        outcomes.push_back({*id, false});
        continue;
      }
      outcomes.push_back({insert_packing(db_, path_, p), true});
    }
    exec(db_, path_, "COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  return outcomes;
}

void ResultsDb::remove_packings(const std::vector<long long>& ids) {
  exec(db_, path_, "BEGIN IMMEDIATE");
  try {
    Statement unlink(db_, path_, "UPDATE runs SET packing_id = NULL WHERE packing_id = ?1");
    Statement remove(db_, path_, "DELETE FROM packings WHERE id = ?1");
    for (const long long id : ids) {
      unlink.bind(1, id).step();
      unlink.reset();
      remove.bind(1, id).step();
      remove.reset();
    }
    exec(db_, path_, "COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

void ResultsDb::compact() {
  exec(db_, path_, "VACUUM");
  exec(db_, path_, "PRAGMA wal_checkpoint(TRUNCATE)");
}

std::vector<StoredPacking> ResultsDb::packings(long long n) const {
  const std::string sql = fmt::format("SELECT {} FROM packings WHERE n = ?1 ORDER BY {}",
                                      kPackingColumns, kPackingOrder);
  Statement s(db_, path_, sql.c_str());
  s.bind(1, n);
  std::vector<StoredPacking> out;
  while (s.step()) out.push_back(packing_from_row(s));
  return out;
}

std::vector<UnitOfPacking> ResultsDb::independent_units(long long n) const {
  const std::string sql = fmt::format(
      "SELECT packing_id, method, seed, seconds FROM runs WHERE n = ?1 AND packing_id IS NOT NULL "
      "AND {} ORDER BY method, seed",
      kIndependentMethod);
  Statement s(db_, path_, sql.c_str());
  s.bind(1, n);
  std::vector<UnitOfPacking> out;
  while (s.step())
    out.push_back({s.integer(0), s.text(1), static_cast<std::uint64_t>(s.integer(2)), s.real(3)});
  return out;
}

std::vector<StoredPacking> ResultsDb::best_per_n() const {
  // The largest d of every n (ties: most runs, then first seed), by n.
  const std::string sql = fmt::format(
      "SELECT {} FROM (SELECT *, ROW_NUMBER() OVER (PARTITION BY n ORDER BY {}) AS rank FROM "
      "packings) AS packings WHERE rank = 1 ORDER BY n",
      kPackingColumns, kPackingOrder);
  Statement s(db_, path_, sql.c_str());
  std::vector<StoredPacking> out;
  while (s.step()) out.push_back(packing_from_row(s));
  return out;
}

std::string ResultsDb::integrity_check() const {
  Statement s(db_, path_, "PRAGMA integrity_check");
  std::string result;
  while (s.step()) result += (result.empty() ? "" : "; ") + s.text(0);
  return result;
}

DbStatistics ResultsDb::statistics() const {
  DbStatistics st;
  st.integrity = integrity_check();
  // One read transaction: every count from the same state of the file.
  exec(db_, path_, "BEGIN");
  try {
    auto count = [&](const char* sql) {
      Statement s(db_, path_, sql);
      s.step();
      return s.integer(0);
    };
    st.runs = count("SELECT COUNT(*) FROM runs");
    st.packings = count("SELECT COUNT(*) FROM packings");
    st.imported = count("SELECT COUNT(*) FROM packings WHERE origin = 'import'");
    st.n_values = count("SELECT COUNT(*) FROM (SELECT n FROM runs UNION SELECT n FROM packings)");
    st.duplicate_runs = count(
        "SELECT COALESCE(SUM(c - 1), 0) FROM (SELECT COUNT(*) AS c FROM runs GROUP BY n, seed, "
        "method "
        "HAVING COUNT(*) > 1)");
    // d to 12 significant digits recomputed from the stored text, not the d_key column.
    st.duplicate_packings = count(
        "SELECT COALESCE(SUM(c - 1), 0) FROM (SELECT COUNT(*) AS c FROM packings GROUP BY n, "
        "graph_hash, printf('%.11e', CAST(d AS REAL)) HAVING COUNT(*) > 1)");
    exec(db_, path_, "COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  return st;
}

PackingRecord record_of(const StoredPacking& stored) {
  Pattern pattern;
  pattern.packing.points = stored.points;
  pattern.packing.d = std::stold(stored.d);
  pattern.bonds = stored.bonds;
  pattern.rattlers = stored.rattlers;
  PackingRecord record = PackingRecord::of(std::move(pattern));
  record.certified = stored.certified;
  record.graph_hash = stored.graph_hash;
  if (stored.origin == "import")
    record.sources.push_back({PackingSource::Kind::Import, stored.source});
  if (stored.has_seed)
    record.sources.push_back({PackingSource::Kind::Billiards, "", stored.first_seed, stored.runs,
                              stored.independent_runs});
  return record;
}

StoredPacking stored_of(const PackingRecord& record, const std::string& tool_version) {
  StoredPacking stored;
  stored.n = record.n();
  stored.d = record.d.str(kLongDoubleDigits);
  stored.graph_hash = record.graph_hash;
  stored.points = record.pattern.packing.points;
  stored.bonds = record.pattern.bonds;
  stored.rattlers = record.pattern.rattlers;
  stored.certified = record.certified;
  stored.has_seed = record.has_seed();
  stored.first_seed = stored.has_seed ? record.first_seed() : 0;
  stored.runs = record.runs();
  for (const auto& s : record.sources)
    if (s.kind == PackingSource::Kind::Import) {
      stored.origin = "import";
      stored.source = s.name;
    }
  stored.tool_version = tool_version;
  return stored;
}

}  // namespace tripack::store
