// tripack: the command line. Thin: parsing here, work in app/commands.cpp.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "app/commands.hpp"

int main(int argc, char** argv) {
  using namespace tripack::app;
  CLI::App cli{"tripack: dense packings of equal disks in an equilateral triangle"};
  cli.require_subcommand(1);
  GlobalOptions g;
  cli.add_option("--catalogue", g.catalogue,
                 "classes.yaml to use (default: $TRIPACK_CATALOGUE or the built-in path)");

  bool json = false;
  auto* classes = cli.add_subcommand("classes", "List the catalogue of classes");
  classes->add_flag("--json", json, "JSON output");

  long long classify_n = 0;
  auto* classify = cli.add_subcommand("classify", "Every (class, k[, p]) whose n(k) equals N");
  classify->add_option("N", classify_n, "number of disks")
      ->required()
      ->check(CLI::Range(1LL, 1000000000000LL));
  classify->add_flag("--json", json, "JSON output");

  BuildOptions b;
  auto* build = cli.add_subcommand("build", "Construct, polish and report a class member");
  build->add_option("class", b.class_id, "class id (see 'tripack classes')");
  build->add_option("--k", b.k, "class index k");
  build->add_option("--p", b.p, "matrix row p")->check(CLI::Range(1L, 1000000000L));
  build->add_option("--n", b.n, "number of disks: build the catalogue's best class containing n");
  build->add_option("--variant", b.variant, "variant (e.g. rattler, cavity-1, full)");
  build->add_option("--digits", b.digits, "significant digits of d (above 18: MPFR polish)")
      ->check(CLI::Range(1, 1000));
  build->add_option("-o,--output", b.output, "write coordinates (.txt, .csv or .json)");
  build->add_flag("--json", b.json, "print one JSON object");
  build->add_flag("!--no-polish", b.polish, "skip the Newton polish of the bond system");
  build->add_flag("!--no-certify", b.certify, "skip relax/bonds/rigidity/stress from the geometry");

  CheckFormulaOptions cf;
  auto* check =
      cli.add_subcommand("check-formula", "Compare built d with the catalogue's closed form");
  check->add_option("class", cf.class_id, "class id")->required();
  check->add_option("--k", cf.k_range, "k or a range A..B")->required();
  check->add_option("--p", cf.p, "matrix row p")->check(CLI::Range(1L, 1000000000L));
  check->add_flag("--json", cf.json, "JSON lines output");

  AnalyzeOptions an;
  auto* analyze = cli.add_subcommand(
      "analyze", "Relax, find bonds and rattlers, test rigidity, certify a file of points");
  analyze->add_option("file", an.file, "points: .txt (x y lines), .csv or .json")->required();
  analyze->add_option("--convention", an.convention,
                      "unit-triangle (centres in the side-1 triangle), radius or unit-disk-side "
                      "(circles in a container)");
  analyze->add_option("--digits", an.digits, "significant digits of d (above 18: MPFR polish)")
      ->check(CLI::Range(1, 1000));
  analyze->add_option("--n", an.n, "expected number of points")
      ->check(CLI::Range(1LL, 100000000LL));
  analyze->add_option("-o,--output", an.output,
                      "write the certified packing (.txt, .csv or .json)");
  analyze->add_flag("--json", an.json, "print one JSON object");

  BilliardsCommandOptions bl;
  auto* billiards = cli.add_subcommand(
      "billiards", "Lubachevsky-Stillinger runs from random starts, certified and ranked");
  billiards->add_option("N", bl.n, "number of disks (or give --scene)")
      ->check(CLI::Range(1LL, 10000000LL));
  billiards->add_option("--runs", bl.runs, "number of runs")->check(CLI::Range(1, 1000000));
  billiards->add_option("--seed", bl.seed, "seed of run 0 (run r uses seed + r)");
  billiards->add_option("--threads", bl.threads, "parallel runs")->check(CLI::Range(1, 256));
  billiards->add_option("--scene", bl.scene, "scene YAML (container, n, initial state, effects)");
  billiards->add_flag("--json", bl.json, "print one JSON object");
  billiards->add_flag("!--no-certify", bl.certify,
                      "skip relax/bonds/rigidity/stress of the end states");

  long table_kmax = 4;
  auto* table = cli.add_subcommand("table", "Build and polish the first terms of every class");
  table->add_option("--kmax", table_kmax, "largest k per class")->check(CLI::Range(1, 50));

  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "tripack: error: " << e.what() << "\n";
    return 2;
  }
  try {
    if (*classes) return cmd_classes(g, json);
    if (*classify) return cmd_classify(g, classify_n, json);
    if (*build) return cmd_build(g, b);
    if (*check) return cmd_check_formula(g, cf);
    if (*table) return cmd_table(g, table_kmax);
    if (*analyze) return cmd_analyze(an);
    if (*billiards) {
      if (bl.n == 0 && bl.scene.empty())
        throw std::invalid_argument("billiards needs N or --scene FILE");
      return cmd_billiards(g, bl);
    }
  } catch (const std::exception& e) {
    std::cerr << "tripack: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
