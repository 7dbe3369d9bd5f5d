// tripack: the command line. Parsing here, the work in app/commands.cpp.
#include <signal.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <thread>

#include "app/commands.hpp"

namespace {

using namespace tripack::app;

// Every subcommand prints one result; --json / --csv choose the format, --points adds coordinates.
void add_output_flags(CLI::App* command, OutputOptions& out, bool with_points = false) {
  command->add_flag("--json", out.json, "print one JSON object");
  command->add_flag("--csv", out.csv, "print CSV (a header, then rows)");
  if (with_points)
    command->add_flag("--points", out.points, "with --json: every packing's coordinates");
}

void add_diagram_options(CLI::App* command, DiagramTargets& d) {
  command->add_option("--svg", d.svg, "draw the packing to this SVG file");
  command->add_option("--png", d.png, "draw the packing to this PNG file");
  command->add_option("--pdf", d.pdf, "draw the packing to this PDF file");
  command->add_flag("--forces", d.forces, "draw the stress certificate's bond forces as widths");
}

// A subcommand and what it runs once parsed.
using Action = std::function<int()>;

Action add_build(CLI::App& cli, const GlobalOptions& g, BuildOptions& b) {
  auto* c = cli.add_subcommand("build", "Construct, polish and certify a class member");
  c->add_option("class", b.class_id, "class id (see 'tripack classes')");
  c->add_option("--k", b.k, "class index k");
  c->add_option("--p", b.p, "matrix row p")->check(CLI::Range(1L, 1000000000L));
  c->add_option("--n", b.n, "number of disks: build the catalogue's best class containing n");
  c->add_option("--variant", b.variant, "variant (e.g. rattler, cavity-1, full)");
  c->add_option("--digits", b.digits, "significant digits of d (above 18: MPFR polish)")
      ->check(CLI::Range(1, 100000));
  c->add_option("-o,--output", b.output,
                "write coordinates: .txt (x y), .csv, .json, or .pck (i x y, record tables)");
  c->add_flag("!--no-polish", b.polish, "skip the Newton polish of the bond system");
  c->add_flag("!--no-certify", b.certify, "skip relax/bonds/rigidity/stress from the geometry");
  add_output_flags(c, b.out, true);
  add_diagram_options(c, b.diagrams);
  return [c, &g, &b] { return *c ? cmd_build(g, b) : -1; };
}

Action add_analyze(CLI::App& cli, AnalyzeOptions& a) {
  auto* c = cli.add_subcommand(
      "analyze",
      "Relax, find bonds and rattlers, test rigidity, certify a file of points.\n"
      "Layouts (one point per line unless JSON; '#' lines are comments; indices are 0-based):\n"
      "  x y        centres (default convention: unit-triangle, the side-1 triangle with\n"
      "             vertices (0,0) (1,0) (1/2,sqrt3/2))\n"
      "  x y r      circles of radius r (implies --convention radius)\n"
      "  i x y      the record tables' style (i = 0..n-1 or 1..n, any order)\n"
      "  CSV        with a header naming x, y (and index, r, rattler), or bare x,y rows\n"
      "  JSON       {\"points\": [[x, y], ...]} or a bare list [[x, y], ...]");
  c->add_option("file", a.file, "the points file")->required();
  c->add_option("--convention", a.convention,
                "unit-triangle (centres in the side-1 triangle), radius (circles of radius r in "
                "a side-1 triangle) or unit-disk-side (unit circles in a triangle of side S)");
  c->add_option("--digits", a.digits, "significant digits of d, r, S (above 18: MPFR polish)")
      ->check(CLI::Range(1, 100000));
  c->add_option("--n", a.n, "expected number of points")->check(CLI::Range(1LL, 100000000LL));
  c->add_option("-o,--output", a.output,
                "write the certified packing: .txt, .csv, .json or .pck (i x y)");
  c->add_flag("--lp-any-size", a.lp_any_size,
              "run the LP relax and certificates however large n is (above 3000 disks they can "
              "take hours; by default a state the LP-free path cannot certify is then reported "
              "not certified)");
  add_output_flags(c, a.out, true);
  add_diagram_options(c, a.diagrams);
  return [c, &a] { return *c ? cmd_analyze(a) : -1; };
}

void add_search_options(CLI::App* c, BilliardsCommandOptions& o) {
  c->add_option("N", o.n, "number of disks (or give --scene)")->check(CLI::Range(1LL, 10000000LL));
  c->add_option("--runs", o.runs, "number of runs")->check(CLI::Range(1, 1000000));
  c->add_option("--seed", o.seed, "seed of run 0 (run r uses seed + r)");
  c->add_option("--threads", o.threads, "parallel runs")->check(CLI::Range(1, 256));
  c->add_option("--scene", o.scene, "scene YAML (container, n, initial state, effects)");
  add_output_flags(c, o.out, true);
}

Action add_billiards(CLI::App& cli, const GlobalOptions& g, BilliardsCommandOptions& o) {
  auto* c = cli.add_subcommand(
      "billiards", "Lubachevsky-Stillinger runs from random starts, certified and ranked");
  add_search_options(c, o);
  c->add_flag("!--no-certify", o.certify, "skip relax/bonds/rigidity/stress of the end states");
  c->add_option("-o,--output", o.output_dir,
                "directory: one coordinate file per distinct packing, named by its label");
  c->add_option("--format", o.file_format, "format of those files: txt, csv, json or pck");
  add_diagram_options(c, o.diagrams);  // the best packing found
  return [c, &g, &o] { return *c ? cmd_billiards(g, o) : -1; };
}

Action add_search(CLI::App& cli, const GlobalOptions& g, SearchOptions& o) {
  auto* c = cli.add_subcommand(
      "search",
      "Basin-hopping search for the densest packing of N disks within a time budget: the best "
      "packing (certified), when it was first reached, and the distinct packings by rank");
  c->add_option("N", o.n, "number of disks")->required()->check(CLI::Range(2LL, 100000LL));
  c->add_option("--seconds", o.seconds, "wall-time budget of each chain")
      ->check(CLI::Range(1e-3, 1e7));
  c->add_option("--steps", o.steps,
                "also stop each chain after this many steps (0: no limit); a step budget on one "
                "thread is exactly reproducible")
      ->check(CLI::Range(0LL, 1000000000LL));
  c->add_option("--seed", o.seed, "seed of chain 0 (chain c uses seed + c)");
  c->add_option("--threads", o.threads, "independent chains, one per thread")
      ->check(CLI::Range(1, 256));
  c->add_option("--db", o.db,
                "campaign database: continue from its best packings of N and record every chain "
                "as a unit (N, seed)");
  c->add_option("--method", o.method,
                "basin-hopping (the search) or restarts (independent default billiards runs, the "
                "baseline)");
  c->add_option("--target", o.target, "stop a chain once a certified d >= this is found");
  c->add_flag("!--no-lattice-starts", o.lattice_starts,
              "every fresh start from random (default: half are the triangular lattice with "
              "random vacancies)");
  add_output_flags(c, o.out, true);
  add_diagram_options(c, o.diagrams);
  return [c, &g, &o] { return *c ? cmd_search(g, o) : -1; };
}

Action add_compare(CLI::App& cli, const GlobalOptions& g, BilliardsCommandOptions& o) {
  auto* c = cli.add_subcommand(
      "compare", "The catalogue's best builder for N against the best billiards packing");
  add_search_options(c, o);
  return [c, &g, &o] { return *c ? cmd_compare(g, o) : -1; };
}

Action add_check_formula(CLI::App& cli, const GlobalOptions& g, CheckFormulaOptions& o) {
  auto* c = cli.add_subcommand("check-formula", "Compare built d with the catalogue's closed form");
  c->add_option("class", o.class_id, "class id")->required();
  c->add_option("--k", o.k_range, "k or a range A..B")->required();
  c->add_option("--p", o.p, "matrix row p")->check(CLI::Range(1L, 1000000000L));
  add_output_flags(c, o.out);
  return [c, &g, &o] { return *c ? cmd_check_formula(g, o) : -1; };
}

Action add_draw(CLI::App& cli, const GlobalOptions& g, DrawOptions& o) {
  auto* c = cli.add_subcommand(
      "draw",
      "Diagram of a packing (a points file, analysed; or a class member, built), like the "
      "paper's figures: shaded disks, unshaded rattlers, bond dots, labels, d");
  c->add_option("what", o.what, "a points file (any layout of 'analyze') or a class id")
      ->required();
  c->add_option("--k", o.k, "class index k");
  c->add_option("--p", o.p, "matrix row p")->check(CLI::Range(1L, 1000000000L));
  c->add_option("--variant", o.variant, "variant");
  c->add_option("--convention", o.convention, "of the points file (see analyze)");
  c->add_option("-o,--output", o.output, "the picture: .svg, .png or .pdf")->required();
  c->add_flag("--forces", o.forces, "bond forces of the stress certificate as line widths");
  c->add_flag("!--no-labels", o.disk_labels, "no disk indices");
  c->add_option("--width", o.width, "PNG width in pixels")->check(CLI::Range(100, 20000));
  return [c, &g, &o] { return *c ? cmd_draw(g, o) : -1; };
}

Action add_explore(CLI::App& cli, const GlobalOptions& g, ExploreOptions& o) {
  auto* c = cli.add_subcommand(
      "explore",
      "The main job: build and certify every class member up to --max-n, billiards for small n, "
      "compare, and write a report directory (delta(n) plot, diagrams, CSV/JSON, index.html)");
  c->add_option("--max-n", o.max_n, "class members up to this n (default 300)")
      ->check(CLI::Range(2LL, 100000LL));
  c->add_option("--discovered-max-n", o.discovered_max_n,
                "members of the discovered classes (vacancy segments) up to this n (default 60)")
      ->check(CLI::Range(2LL, 100000LL));
  c->add_option("--search-steps", o.search_steps,
                "basin-hopping steps per chain for each n <= 60 (default 100)")
      ->check(CLI::Range(1LL, 100000000LL));
  c->add_option("--threads", o.threads, "parallel runs (default 2)")->check(CLI::Range(1, 256));
  c->add_option("--seed", o.seed, "seed of run 0 (run r uses seed + r)");
  c->add_option("--out", o.out, "report directory (default ./report)");
  c->add_flag("!--no-accuracy", o.accuracy, "skip the accuracy-against-time study (~20 s)");
  c->add_option("--atlas", o.atlas,
                "atlas.csv to show beside the exploration (default: the project's "
                "data/atlas.csv when present; 'none': no atlas)");
  return [c, &g, &o] { return *c ? cmd_explore(g, o) : -1; };
}

Action add_campaign(CLI::App& cli, const GlobalOptions& g, CampaignOptions& o) {
  auto* c = cli.add_subcommand(
      "campaign",
      "Billiards runs over a range of n as work units (n, seed) on threads, or on MPI ranks when "
      "started by mpirun (rank 0 hands out units and writes); every finished unit goes to an "
      "SQLite database at once, and rerunning continues where it stopped");
  c->add_option("--n", o.n_range, "A..B or N")->required();
  c->add_option("--runs", o.runs, "seeds per n (default 20)")->check(CLI::Range(1, 1000000));
  c->add_option("--seed", o.seed, "first seed (default 1)");
  c->add_option("--threads", o.threads,
                "parallel units (default 1); under mpirun, rank 0's own (0: it only hands out)")
      ->check(CLI::Range(0, 256));
  c->add_option("--db", o.db, "results database (default tripack.db)");
  c->add_option("--scene", o.scene, "scene YAML (effects, stop rule) for every n");
  c->add_option("--search-seconds", o.search_seconds,
                "every unit is a search chain of this many seconds from random starts (method "
                "'search S s'), not one billiards run")
      ->check(CLI::Range(1e-3, 1e7));
  add_output_flags(c, o.out, true);
  return [c, &g, &o] { return *c ? cmd_campaign(g, o) : -1; };
}

Action add_atlas(CLI::App& cli, const GlobalOptions& g, AtlasOptions& o) {
  auto* c = cli.add_subcommand(
      "atlas",
      "The best certified packings of every n: a campaign's database and every builder whose "
      "class contains n, certified anew, polished in MPFR, ranked and labelled; writes "
      "DIR/atlas.csv and DIR/atlas/LABEL.txt");
  c->add_option("--db", o.db, "the campaign database (default data/atlas.db)");
  c->add_option("--out", o.out, "the data directory (default data)");
  c->add_option("--n", o.n_range, "A..B, N, or a list of them: 254,255,256 (default 2..200)");
  c->add_option("--ranked", o.ranked, "these n keep --ranked-count packings (default 16..34)");
  c->add_option("--ranked-count", o.ranked_count, "packings kept for --ranked n (default 20)")
      ->check(CLI::Range(1, 1000));
  c->add_option("--digits", o.digits, "significant digits of d and the coordinates (default 30)")
      ->check(CLI::Range(19, 1000));
  c->add_option("--threads", o.threads, "parallel values of n (default 2)")
      ->check(CLI::Range(1, 256));
  add_output_flags(c, o.out_format);
  return [c, &g, &o] { return *c ? cmd_atlas(g, o) : -1; };
}

// The database commands' options.
struct DbCommandOptions {
  DbOptions best;
  DbCheckOptions check;
  DbExportOptions exp;
  DbImportOptions imp;
  DbPruneOptions prune;
};

Action add_db(CLI::App& cli, const GlobalOptions& g, DbCommandOptions& o) {
  auto* c = cli.add_subcommand("db", "Read, check, export and import a campaign database");
  c->require_subcommand(1);
  const char* db_help = "results database (default tripack.db)";
  const char* conventions =
      "unit-triangle (centres in the side-1 triangle), radius (circles of radius r in a side-1 "
      "triangle) or unit-disk-side (unit circles in a triangle of side S)";

  auto* best = c->add_subcommand("best", "One line per n: n, the best certified d, its label");
  best->add_option("N", o.best.n, "only this n")->check(CLI::Range(2LL, 100000000LL));
  best->add_option("--db", o.best.db, db_help);
  add_output_flags(best, o.best.out, true);

  auto* check = c->add_subcommand(
      "check",
      "Integrity check and counts: runs, values of n, packings, duplicates (exit 1 if "
      "the check fails or there are duplicates)");
  check->add_option("--db", o.check.db, db_help);
  add_output_flags(check, o.check.out);

  auto* exp = c->add_subcommand(
      "export", "The stored packings of N as coordinate files (best first: rank 1 is tNa)");
  exp->add_option("N", o.exp.n, "number of disks")->required()->check(CLI::Range(2LL, 100000000LL));
  exp->add_option("--db", o.exp.db, db_help);
  exp->add_option("--format", o.exp.format,
                  "txt (x y; x y r in the radius convention), csv, json or records (i x y with "
                  "d, r, S in the header); default: -o's extension, else txt");
  exp->add_option("--convention", o.exp.convention, conventions);
  auto* rank = exp->add_option("--rank", o.exp.rank, "which packing: 1 = the best (default)")
                   ->check(CLI::Range(1LL, 1000000000LL));
  auto* all = exp->add_flag("--all", o.exp.all, "every stored packing of N");
  rank->excludes(all);
  exp->add_option("-o,--output", o.exp.output,
                  "a file (one packing) or a directory (--all: one file per packing, named by "
                  "its label); default: stdout");
  exp->add_option("--digits", o.exp.digits,
                  "significant digits of the coordinates (the database keeps 21; d keeps 18)")
      ->check(CLI::Range(1, 21));

  auto* imp = c->add_subcommand(
      "import",
      "Read packing files (any layout of 'analyze'), certify them like 'analyze' and store them; "
      "a file with overlapping disks or a packing that does not certify is refused and nothing "
      "is stored");
  imp->add_option("FILE", o.imp.files, "packing files")->required();
  imp->add_option("--db", o.imp.db, "results database, created if missing (default tripack.db)");
  imp->add_option("--convention", o.imp.convention,
                  std::string(conventions) + "; default: as the file declares, else unit-triangle");
  imp->add_option("--threads", o.imp.threads, "files analysed at once (default 2)")
      ->check(CLI::Range(1, 256));
  add_output_flags(imp, o.imp.out);

  auto* prune = c->add_subcommand(
      "prune",
      "Keep the best K packings of every n (the runs stay, so the campaign still skips them) "
      "and compact the file: for keeping or committing a long campaign's database");
  prune->add_option("--keep", o.prune.keep, "packings kept per n")
      ->required()
      ->check(CLI::Range(1LL, 1000000000LL));
  prune->add_option("--n", o.prune.n_range, "only n in A..B (or N); default: every n");
  prune->add_option("--db", o.prune.db, db_help);
  add_output_flags(prune, o.prune.out);

  return [=, &o] {
    if (*prune) return cmd_db_prune(o.prune);
    if (*best) return cmd_db_best(o.best);
    if (*check) return cmd_db_check(o.check);
    if (*exp) return cmd_db_export(o.exp);
    if (*imp) return cmd_db_import(g, o.imp);
    return -1;
  };
}

Action add_exact(CLI::App& cli, const GlobalOptions& g, ExactOptions& o) {
  auto* c = cli.add_subcommand(
      "exact",
      "The minimal polynomial P of d (integer relation from D digits, confirmed from 2D, "
      "proven irreducible, root isolated) and a proof that the exact configuration exists");
  c->add_option("FILE", o.files, "packing files (any layout of 'analyze')");
  c->add_option("--class", o.class_id, "or the members of this class (see 'tripack classes')");
  c->add_option("--k", o.k_range, "with --class: k = A..B (or K)");
  c->add_option("--p", o.p, "with --class: matrix row p")->check(CLI::Range(0L, 1000000000L));
  c->add_option("--digits", o.digits, "D: digits the relation is found from (default 300)")
      ->check(CLI::Range(40, 20000));
  c->add_option("--first-digits", o.first_digits,
                "try D = this, twice this, ... up to --digits until the row is proven (default: "
                "--digits only)")
      ->check(CLI::Range(40, 20000));
  c->add_option("--max-degree", o.max_degree, "largest degree of P tried (default 48)")
      ->check(CLI::Range(1, 200));
  c->add_option("--certificates", o.certificates,
                "write LABEL.gp (checked by checker/check_exact.sh) here for every proven packing");
  c->add_flag("!--no-existence", o.existence, "only the polynomial, no proof of statement (I)");
  add_output_flags(c, o.out);
  return [c, &g, &o] { return *c ? cmd_exact(g, o) : -1; };
}

Action add_exact_atlas(CLI::App& cli, const GlobalOptions& g, ExactAtlasOptions& o) {
  auto* c = cli.add_subcommand(
      "exact-atlas",
      "'exact' on every atlas row: DIR/atlas-exact.csv and DIR/exact/LABEL.gp, resumable (a rerun "
      "skips the rows already in the table)");
  c->add_option("--atlas", o.atlas, "the atlas table (default: the project's data/atlas.csv)");
  c->add_option("--out", o.out,
                "where atlas-exact.csv and exact/ go (default: the atlas's directory)");
  c->add_option("--n", o.n_range, "only these n: A..B, N or a comma-separated list of them");
  c->add_option("--digits", o.digits, "D (default 300)")->check(CLI::Range(40, 20000));
  c->add_option("--first-digits", o.first_digits,
                "try D = this, twice this, ... up to --digits until the row is proven (default: "
                "--digits only)")
      ->check(CLI::Range(40, 20000));
  c->add_option("--max-degree", o.max_degree, "largest degree of P tried (default 48)")
      ->check(CLI::Range(1, 200));
  c->add_option("--threads", o.threads, "rows at once (default 2)")->check(CLI::Range(1, 256));
  c->add_flag(
      "--retry-none", o.retry_none,
      "run the rows whose proof is 'none' again (with more --digits, a larger --max-degree)");
  return [c, &g, &o] { return *c ? cmd_exact_atlas(g, o) : -1; };
}

bool wants_json(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--json") return true;
  return false;
}

// One line on stderr; with --json also {"error": ...} on stdout, so a program reading stdout
// always gets one JSON object.
int fail(const std::string& message, bool json, int code) {
  std::cerr << "tripack: error: " << message << "\n";
  if (json) tripack::report::render_error_json(std::cout, message);
  return code;
}

// The commands that stop cleanly between items when asked (the long jobs).
bool observes_cancel(const CLI::App& cli) {
  for (const auto* command : cli.get_subcommands()) {
    const std::string name = command->get_name();
    if (name == "db")
      for (const auto* sub : command->get_subcommands()) return sub->get_name() == "import";
    return name == "explore" || name == "atlas" || name == "campaign" || name == "billiards" ||
           name == "compare" || name == "exact-atlas" || name == "search";
  }
  return false;
}

// Ctrl-C and SIGTERM (mpirun passes a Ctrl-C on to the ranks as SIGTERM) are taken by a thread
// of their own (sigwait), not a handler: the first sets the token, so the job starts nothing new
// and reports what finished; the second ends the program at once. Blocked before any other
// thread starts, so every thread inherits the mask and only this one receives them.
void cancel_on_signals(tripack::CancelToken& cancel) {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread([signals, &cancel] {
    for (;;) {
      int received = 0;
      if (sigwait(&signals, &received) != 0) continue;
      if (cancel.cancel_again()) std::_Exit(130);
      std::cerr << "\ntripack: stopping after the items under way (again to stop at once)\n";
    }
  }).detach();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"tripack: dense packings of equal disks in an equilateral triangle"};
  cli.require_subcommand(1);
  GlobalOptions g;
  cli.add_option("--catalogue", g.catalogue,
                 "classes.yaml to use (default: $TRIPACK_CATALOGUE or the built-in path)");
  OutputOptions classes_out, classify_out, table_out;
  auto* classes = cli.add_subcommand("classes", "List the catalogue of classes");
  add_output_flags(classes, classes_out);
  long long classify_n = 0;
  auto* classify = cli.add_subcommand("classify", "Every (class, k[, p]) whose n(k) equals N");
  classify->add_option("N", classify_n, "number of disks")
      ->required()
      ->check(CLI::Range(1LL, 1000000000000LL));
  add_output_flags(classify, classify_out);
  long table_k = 4;
  auto* table =
      cli.add_subcommand("table", "Build, polish and certify the first terms of every class");
  table->add_option("--kmax", table_k, "how many k per class")->check(CLI::Range(1, 50));
  add_output_flags(table, table_out);
  BuildOptions build;
  AnalyzeOptions analyze;
  CheckFormulaOptions check;
  BilliardsCommandOptions billiards, compare;
  SearchOptions search;
  ExploreOptions explore;
  DrawOptions draw;
  CampaignOptions campaign;
  DbCommandOptions db;
  AtlasOptions atlas;
  ExactOptions exact;
  ExactAtlasOptions exact_atlas;
  const std::vector<Action> actions{
      add_exact(cli, g, exact),
      add_exact_atlas(cli, g, exact_atlas),
      add_campaign(cli, g, campaign),
      add_atlas(cli, g, atlas),
      add_db(cli, g, db),
      add_build(cli, g, build),
      add_analyze(cli, analyze),
      add_check_formula(cli, g, check),
      add_billiards(cli, g, billiards),
      add_compare(cli, g, compare),
      add_search(cli, g, search),
      add_explore(cli, g, explore),
      add_draw(cli, g, draw),
      [&] { return *classes ? cmd_classes(g, classes_out) : -1; },
      [&] { return *classify ? cmd_classify(g, classify_n, classify_out) : -1; },
      [&] { return *table ? cmd_table(g, table_k, table_out) : -1; }};
  const bool json = wants_json(argc, argv);
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(e.what(), json, 2);
  }
  tripack::CancelToken cancel;  // outlives the signal thread: main never returns before exit
  if (observes_cancel(cli)) {
    cancel_on_signals(cancel);
    g.cancel = &cancel;
  }
  try {
    for (const auto& action : actions)
      if (const int code = action(); code >= 0) return code;
  } catch (const std::exception& e) {
    return fail(e.what(), json, 1);
  }
  return 0;
}
