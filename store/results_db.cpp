#include "store/results_db.hpp"

#include <fmt/format.h>
#include <sqlite3.h>

#include <cstring>
#include <sstream>
#include <utility>

#include "core/io.hpp"

namespace tripack::store {

namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE IF NOT EXISTS meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS packings(
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
  first_seed INTEGER NOT NULL,
  runs INTEGER NOT NULL,
  tool_version TEXT NOT NULL,
  UNIQUE(n, graph_hash, d_key));
CREATE TABLE IF NOT EXISTS runs(
  n INTEGER NOT NULL,
  seed INTEGER NOT NULL,
  outcome TEXT NOT NULL,
  events INTEGER NOT NULL,
  seconds REAL NOT NULL,
  packing_id INTEGER REFERENCES packings(id),
  tool_version TEXT NOT NULL,
  PRIMARY KEY(n, seed));
)sql";

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
  long long integer(int c) const { return sqlite3_column_int64(stmt_, c); }
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
  return format_significant(std::stold(d), 12);
}

constexpr const char* kPackingColumns =
    "n, d, graph_hash, points, bonds, rattlers, certified, first_seed, runs, tool_version";

StoredPacking packing_from_row(const Statement& s) {
  StoredPacking p;
  p.n = s.integer(0);
  p.d = s.text(1);
  p.graph_hash = s.text(2);
  p.points = parse_points(s.text(3));
  p.bonds = parse_bonds(s.text(4));
  p.rattlers = parse_ints(s.text(5));
  p.certified = s.integer(6) != 0;
  p.first_seed = static_cast<std::uint64_t>(s.integer(7));
  p.runs = s.integer(8);
  p.tool_version = s.text(9);
  return p;
}

}  // namespace

ResultsDb ResultsDb::open(const std::string& path, const OpenOptions& options) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
      SQLITE_OK) {
    const std::string detail = db ? sqlite3_errmsg(db) : "out of memory";
    sqlite3_close(db);
    throw StoreError(fmt::format("cannot open database {} ({})", path, detail));
  }
  ResultsDb out(path, db);
  sqlite3_busy_timeout(db, options.busy_timeout_ms);
  if (sqlite3_db_readonly(db, "main") == 1)
    throw StoreError(fmt::format("cannot write to database {} (read-only)", path));
  // WAL: readers do not block the writer, and a commit survives a killed process.
  exec(db, path, "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL; PRAGMA foreign_keys=ON;");
  exec(db, path, "BEGIN IMMEDIATE");
  exec(db, path, kSchema);
  {
    Statement version(db, path, "SELECT value FROM meta WHERE key = 'schema_version'");
    if (version.step()) {
      const std::string v = version.text(0);
      if (v != std::to_string(kSchemaVersion)) {
        exec(db, path, "ROLLBACK");
        throw StoreError(
            fmt::format("database {} has schema version {}; this tripack reads version {}", path, v,
                        kSchemaVersion));
      }
    } else {
      Statement set(db, path, "INSERT INTO meta(key, value) VALUES ('schema_version', ?1)");
      set.bind(1, std::to_string(kSchemaVersion)).step();
    }
  }
  exec(db, path, "COMMIT");
  return out;
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

bool ResultsDb::has_run(long long n, std::uint64_t seed) const {
  Statement s(db_, path_, "SELECT 1 FROM runs WHERE n = ?1 AND seed = ?2");
  return s.bind(1, n).bind(2, static_cast<long long>(seed)).step();
}

std::vector<std::uint64_t> ResultsDb::finished_seeds(long long n) const {
  Statement s(db_, path_, "SELECT seed FROM runs WHERE n = ?1 ORDER BY seed");
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
    if (has_run(run.n, run.seed)) {
      exec(db_, path_, "ROLLBACK");
      return false;
    }
    long long packing_id = -1;
    if (run.packing) {
      const StoredPacking& p = *run.packing;
      Statement find(db_, path_,
                     "SELECT id FROM packings WHERE n = ?1 AND graph_hash = ?2 AND d_key = ?3");
      find.bind(1, p.n).bind(2, p.graph_hash).bind(3, d_key(p.d));
      if (find.step()) {
        packing_id = find.integer(0);
        Statement bump(db_, path_, "UPDATE packings SET runs = runs + 1 WHERE id = ?1");
        bump.bind(1, packing_id).step();
      } else {
        Statement add(db_, path_,
                      "INSERT INTO packings(n, d, d_key, d_value, graph_hash, points, bonds, "
                      "rattlers, certified, first_seed, runs, tool_version) "
                      "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, 1, ?11)");
        add.bind(1, p.n)
            .bind(2, p.d)
            .bind(3, d_key(p.d))
            .bind(4, static_cast<double>(std::stold(p.d)))
            .bind(5, p.graph_hash)
            .bind(6, points_text(p.points))
            .bind(7, bonds_text(p.bonds))
            .bind(8, ints_text(p.rattlers))
            .bind(9, static_cast<long long>(p.certified))
            .bind(10, static_cast<long long>(run.seed))
            .bind(11, run.tool_version)
            .step();
        packing_id = sqlite3_last_insert_rowid(db_);
      }
    }
    Statement add(db_, path_,
                  "INSERT INTO runs(n, seed, outcome, events, seconds, packing_id, tool_version) "
                  "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)");
    add.bind(1, run.n)
        .bind(2, static_cast<long long>(run.seed))
        .bind(3, run.outcome)
        .bind(4, run.events)
        .bind(5, run.seconds)
        .bind(7, run.tool_version);
    if (packing_id >= 0) add.bind(6, packing_id);  // else NULL
    add.step();
    exec(db_, path_, "COMMIT");
  } catch (...) {
    sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  return true;
}

std::vector<StoredPacking> ResultsDb::packings(long long n) const {
  const std::string sql = fmt::format(
      "SELECT {} FROM packings WHERE n = ?1 ORDER BY d_value DESC, runs DESC, first_seed",
      kPackingColumns);
  Statement s(db_, path_, sql.c_str());
  s.bind(1, n);
  std::vector<StoredPacking> out;
  while (s.step()) out.push_back(packing_from_row(s));
  return out;
}

std::vector<StoredPacking> ResultsDb::best_per_n() const {
  // The largest d of every n (ties: most runs, then first seed), by n.
  const std::string sql = fmt::format(
      "SELECT {} FROM (SELECT *, ROW_NUMBER() OVER (PARTITION BY n ORDER BY d_value DESC, runs "
      "DESC, first_seed) AS rank FROM packings) WHERE rank = 1 ORDER BY n",
      kPackingColumns);
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

}  // namespace tripack::store
