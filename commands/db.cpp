// The database commands: db best, check, export, import, prune.
#include <fmt/format.h>

#include <limits>
#include <memory>

#include "commands/common.hpp"
#include "core/option_values.hpp"
#include "jobs/import.hpp"
#include "jobs/stored.hpp"
#include "report/results/database.hpp"

namespace tripack::commands {

namespace {

constexpr const char* kDbHelp = "results database";

class DbBest : public Command {
 public:
  static constexpr CommandInfo kInfo{"db best",
                                     "One line per n: n, the best certified d, its label", false};

 private:
  std::string db = "tripack.db";
  long long n = 0;  // 0: every n
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("N", n, "only this n").range(2, 1e8);
    o.option("--db", db, kDbHelp);
    out.declare(o, true);
  }
  int run(const Context&) override {
    const auto table = n ? jobs::best_table(db, n, n)
                         : jobs::best_table(db, 0, std::numeric_limits<long long>::max());
    if (n && table.rows.empty())
      throw std::invalid_argument(fmt::format("no packings of n = {} in {}", n, db));
    print_result(table, out);
    return 0;
  }
};

class DbCheck : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "db check",
      "Integrity check and counts: runs, values of n, packings, duplicates (exit 1 if the "
      "check fails or there are duplicates)",
      false};

 private:
  std::string db = "tripack.db";
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("--db", db, kDbHelp);
    out.declare(o);
  }
  int run(const Context&) override {
    const jobs::DbCheck check = jobs::check_database(db);
    if (check.stats.integrity != "ok")
      throw std::runtime_error("database " + db +
                               " fails the integrity check: " + check.stats.integrity);
    print_result(check, out);
    if (check.duplicates() > 0) {
      // The result is printed (one JSON object with --json); the failure is one line on stderr.
      std::cerr << fmt::format(
          "tripack: error: database {} holds duplicates: {} runs with a repeated (n, seed), {} "
          "packings with a repeated (n, contact graph, d to 12 digits)\n",
          db, check.stats.duplicate_runs, check.stats.duplicate_packings);
      return 1;
    }
    return 0;
  }
};

class DbExport : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "db export", "The stored packings of N as coordinate files (best first: rank 1 is tNa)",
      false};

 private:
  jobs::DbExport request;

 public:
  void declare(OptionList& o) override { request.declare(o); }
  int run(const Context&) override {
    jobs::export_packings(request, std::cout);
    return 0;
  }
};

class DbImport : public RequestCommand<jobs::ImportRequest> {
 public:
  static constexpr CommandInfo kInfo{
      "db import",
      "Read packing files (any layout of 'analyze'), certify them like 'analyze' and store "
      "them; a file with overlapping disks or a packing that does not certify is refused and "
      "nothing is stored",
      true};

  int run(const Context& c) override {
    report::ProgressLine progress(std::cerr, terminal_line("import", out, 2));
    const auto result = jobs::import_packings(request, job_context(c, progress.callback()));
    progress.finish();
    if (result.cancelled) return cancelled("nothing was stored");
    for (const auto& x : result.packings)
      for (const auto& warning : x.warnings)
        std::cerr << "tripack: warning: " << x.file << ": " << warning << "\n";
    print_result(result, out);
    return 0;
  }
};

class DbPrune : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "db prune",
      "Keep the best K packings of every n (the runs stay, so the campaign still skips them) "
      "and compact the file: for keeping or committing a long campaign's database",
      false};

 private:
  std::string db = "tripack.db";
  long long keep = 0;  // packings kept per n
  std::pair<long long, long long> n{0, std::numeric_limits<long long>::max()};
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("--keep", keep, "packings kept per n").required().range(1, 1e9);
    o.parsed(
        "--n", [this](const std::string& s) { n = parse_range(s, "--n"); }, "every n",
        "only n in A..B (or N)");
    o.option("--db", db, kDbHelp);
    out.declare(o);
  }
  int run(const Context&) override {
    print_result(jobs::prune_database(db, keep, n.first, n.second), out);
    return 0;
  }
};

}  // namespace

std::vector<CommandEntry> db_commands() {
  return {entry<DbBest>(), entry<DbCheck>(), entry<DbExport>(), entry<DbImport>(),
          entry<DbPrune>()};
}

}  // namespace tripack::commands
