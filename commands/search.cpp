// The commands that look for packings: billiards, compare, search.
#include "search/search.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "formats/formats.hpp"
#include "jobs/billiards_runs.hpp"
#include "jobs/compare.hpp"
#include "jobs/stored.hpp"
#include "report/results/billiards.hpp"
#include "report/results/search.hpp"

namespace tripack::commands {

namespace {

// N or --scene, and the runs: what billiards and compare share.
struct BilliardsRuns {
  long long n = 0;    // 0: the scene's n
  std::string scene;  // YAML file; empty: the built-in scene
  jobs::BilliardsRunsRequest request;

  void declare(OptionList& o) {
    o.option("N", n, "number of disks (or give --scene)").range(1, 1e7);
    request.declare(o);
    o.option("--scene", scene, "scene YAML (container, n, initial state, effects)");
  }
  void prepare(const Context& c) {
    request.scene = scene.empty() ? default_scene(static_cast<int>(n)) : load_scene(scene);
    jobs::prepare_scene(load_catalogue(c), request.scene, n);
  }
};

class Billiards : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "billiards", "Lubachevsky-Stillinger runs from random starts, certified and ranked", true};

 private:
  BilliardsRuns runs;
  std::string output_dir;           // -o DIR: one coordinate file per distinct packing
  std::string file_format = "txt";  // of those files
  Output out;
  Diagrams diagrams;

 public:
  void declare(OptionList& o) override {
    runs.declare(o);
    o.flag("!--no-certify", runs.request.certify,
           "skip relax/bonds/rigidity/stress of the end states");
    o.option("-o,--output", output_dir,
             "directory: one coordinate file per distinct packing, named by its label");
    o.option("--format", file_format, "format of those files: " + format_names());
    out.declare(o, true);
    diagrams.declare(o);  // the best packing found
  }
  int run(const Context& c) override {
    if (runs.n == 0 && runs.scene.empty())
      throw std::invalid_argument("billiards needs N or --scene FILE");
    // -o DIR is checked before the runs (the runs must not end in an unwritable directory).
    const PackingFormat& format = format_named(file_format, "--format");
    const auto dir = output_dir.empty() ? std::filesystem::path() : writable_directory(output_dir);
    runs.prepare(c);
    report::ProgressLine progress(
        std::cerr, terminal_line(fmt::format("billiards n={}", runs.request.scene.n), out));
    const auto result = jobs::billiards_runs(runs.request, job_context(c, progress.callback()));
    progress.finish();
    // Files first: what was found is kept even if printing fails.
    if (!dir.empty())
      for (const auto& x : result.packings)
        write_packing_file((dir / (x.label + format.extensions.front())).string(), x, {});
    print_result(result, out);
    if (!result.packings.empty()) {
      const auto& best = result.packings.front();
      diagrams.draw(best.pattern, best.label, best.forces);
    }
    return result.cancelled ? cancelled("the result holds the runs that finished") : 0;
  }
};

class Compare : public RequestCommand<BilliardsRuns, true> {
 public:
  static constexpr CommandInfo kInfo{
      "compare", "The catalogue's best builder for N against the best billiards packing", true};

 private:
  BilliardsRuns& runs = request;

 public:
  int run(const Context& c) override {
    if (runs.n < 2) throw std::invalid_argument("compare needs N >= 2");
    const Catalogue catalogue = load_catalogue(c);
    runs.prepare(c);
    report::ProgressLine progress(
        std::cerr, terminal_line(fmt::format("billiards n={}", runs.request.scene.n), out));
    const auto result = jobs::compare_constructed(catalogue, runs.n, runs.request, {},
                                                  job_context(c, progress.callback()));
    progress.finish();
    print_result(result, out);
    return result.billiards.cancelled ? cancelled("the comparison holds the runs that finished")
                                      : 0;
  }
};

class Search : public RequestCommand<search::SearchRequest, true> {
 public:
  static constexpr CommandInfo kInfo{
      "search",
      "Basin-hopping search for the densest packing of N disks within a time budget: the best "
      "packing (certified), when it was first reached, and the distinct packings by rank",
      true};

 private:
  std::string db;  // empty: start from nothing stored, record nothing
  Diagrams diagrams;

 public:
  void declare(OptionList& o) override {
    RequestCommand::declare(o);
    o.option("--db", db,
             "campaign database: continue from its best packings of N and record every chain "
             "as a unit (N, seed)");
    diagrams.declare(o);
  }
  int run(const Context& c) override {
    std::optional<Catalogue> catalogue;  // read only when the chains start from the builders
    if (request.builder_starts && request.method == search::SearchMethod::BasinHopping) {
      catalogue.emplace(load_catalogue(c));
      request.builders = &*catalogue;
    }
    report::ProgressLine progress(std::cerr,
                                  terminal_line(fmt::format("search n={}", request.n), out));
    const auto result = jobs::search_and_record(request, db, job_context(c, progress.callback()));
    progress.finish();
    for (const auto& note : result.notes) std::cerr << "tripack: note: " << note << "\n";
    print_result(result.search, out);
    if (!result.search.packings.empty()) {
      const auto& best = result.search.packings.front();
      diagrams.draw(best.pattern, best.label, best.forces);
    }
    return result.search.cancelled ? cancelled("the result holds the steps that finished") : 0;
  }
};

}  // namespace

std::vector<CommandEntry> search_commands() {
  return {entry<Billiards>(), entry<Compare>(), entry<Search>()};
}

}  // namespace tripack::commands
