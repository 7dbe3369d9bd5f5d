// The command table: every command once, in the order of the help. A new command is its file in
// commands/ (a Command and its make_ function) plus its line here (docs/extending.md).
#include <memory>

#include "commands/command.hpp"

namespace tripack::commands {

std::unique_ptr<Command> make_classes();
std::unique_ptr<Command> make_classify();
std::unique_ptr<Command> make_table();
std::unique_ptr<Command> make_check_formula();
std::unique_ptr<Command> make_build();
std::unique_ptr<Command> make_analyze();
std::unique_ptr<Command> make_draw();
std::unique_ptr<Command> make_billiards();
std::unique_ptr<Command> make_compare();
std::unique_ptr<Command> make_search();
std::unique_ptr<Command> make_explore();
std::unique_ptr<Command> make_campaign();
std::unique_ptr<Command> make_atlas();
std::unique_ptr<Command> make_exact();
std::unique_ptr<Command> make_exact_atlas();
std::unique_ptr<Command> make_db_best();
std::unique_ptr<Command> make_db_check();
std::unique_ptr<Command> make_db_export();
std::unique_ptr<Command> make_db_import();
std::unique_ptr<Command> make_db_prune();

const std::vector<CommandEntry>& command_table() {
  constexpr bool kLongJob = true;
  static const std::vector<CommandEntry> table{
      {"classes", "List the catalogue of classes", false, make_classes},
      {"classify", "Every (class, k[, p]) whose n(k) equals N", false, make_classify},
      {"table", "Build, polish and certify the first terms of every class", false, make_table},
      {"check-formula", "Compare built d with the catalogue's closed form", false,
       make_check_formula},
      {"build", "Construct, polish and certify a class member", false, make_build},
      {"analyze",
       "Relax, find bonds and rattlers, test rigidity, certify a file of points.\n"
       "Layouts (one point per line unless JSON; '#' lines are comments; indices are 0-based):\n"
       "  x y        centres (default convention: unit-triangle, the side-1 triangle with\n"
       "             vertices (0,0) (1,0) (1/2,sqrt3/2))\n"
       "  x y r      circles of radius r (implies --convention radius)\n"
       "  i x y      the record tables' style (i = 0..n-1 or 1..n, any order)\n"
       "  CSV        with a header naming x, y (and index, r, rattler), or bare x,y rows\n"
       "  JSON       {\"points\": [[x, y], ...]} or a bare list [[x, y], ...]",
       false, make_analyze},
      {"draw",
       "Diagram of a packing (a points file, analysed; or a class member, built), like the "
       "paper's figures: shaded disks, unshaded rattlers, bond dots, labels, d",
       false, make_draw},
      {"billiards", "Lubachevsky-Stillinger runs from random starts, certified and ranked",
       kLongJob, make_billiards},
      {"compare", "The catalogue's best builder for N against the best billiards packing", kLongJob,
       make_compare},
      {"search",
       "Basin-hopping search for the densest packing of N disks within a time budget: the best "
       "packing (certified), when it was first reached, and the distinct packings by rank",
       kLongJob, make_search},
      {"explore",
       "The main job: build and certify every class member up to --max-n, billiards for small "
       "n, compare, and write a report directory (delta(n) plot, diagrams, CSV/JSON, index.html)",
       kLongJob, make_explore},
      {"campaign",
       "Billiards runs over a range of n as work units (n, seed) on threads, or on MPI ranks "
       "when started by mpirun (rank 0 hands out units and writes); every finished unit goes to "
       "an SQLite database at once, and rerunning continues where it stopped",
       kLongJob, make_campaign},
      {"atlas",
       "The best certified packings of every n: a campaign's database and every builder whose "
       "class contains n, certified anew, polished in MPFR, ranked and labelled; writes "
       "DIR/atlas.csv and DIR/atlas/LABEL.txt",
       kLongJob, make_atlas},
      {"exact",
       "The minimal polynomial P of d (integer relation from D digits, confirmed from 2D, "
       "proven irreducible, root isolated) and a proof that the exact configuration exists",
       false, make_exact},
      {"exact-atlas",
       "'exact' on every atlas row: DIR/atlas-exact.csv and DIR/exact/LABEL.gp, resumable (a "
       "rerun skips the rows already in the table)",
       kLongJob, make_exact_atlas},
      {"db best", "One line per n: n, the best certified d, its label", false, make_db_best},
      {"db check",
       "Integrity check and counts: runs, values of n, packings, duplicates (exit 1 if the "
       "check fails or there are duplicates)",
       false, make_db_check},
      {"db export", "The stored packings of N as coordinate files (best first: rank 1 is tNa)",
       false, make_db_export},
      {"db import",
       "Read packing files (any layout of 'analyze'), certify them like 'analyze' and store "
       "them; a file with overlapping disks or a packing that does not certify is refused and "
       "nothing is stored",
       kLongJob, make_db_import},
      {"db prune",
       "Keep the best K packings of every n (the runs stay, so the campaign still skips them) "
       "and compact the file: for keeping or committing a long campaign's database",
       false, make_db_prune},
  };
  return table;
}

std::string group_summary(const std::string& group) {
  if (group == "db") return "Read, check, export and import a campaign database";
  return group;
}

}  // namespace tripack::commands
