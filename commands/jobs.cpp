// The long workflows: explore, campaign, atlas, exact, exact-atlas.
#include <fmt/format.h>

#include <map>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "core/data_directory.hpp"
#include "jobs/atlas.hpp"
#include "jobs/atlas_files.hpp"
#include "jobs/campaign.hpp"
#include "jobs/exact_atlas.hpp"
#include "jobs/explore.hpp"
#include "jobs/stored.hpp"
#include "report/explore_report.hpp"
#include "report/plot.hpp"
#include "report/results/atlas.hpp"
#include "report/results/database.hpp"
#include "report/results/exact.hpp"
#include "report/results/summary.hpp"
#include "runner/ranks.hpp"

namespace tripack::commands {

namespace {

class Explore : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "explore",
      "The main job: build and certify every class member up to --max-n, billiards for small "
      "n, compare, and write a report directory (delta(n) plot, diagrams, CSV/JSON, index.html)",
      true};

 private:
  jobs::ExploreSettings settings;
  std::string out = "out/report";
  std::string atlas;  // empty: the installed atlas when there is one; "none": no atlas
  Output summary;     // how the closing summary is printed (the report directory is the result)

 public:
  void declare(OptionList& o) override {
    settings.declare(o);
    summary.declare(o);
    o.option("--out", out, "report directory");
    o.option("--atlas", atlas,
             "atlas.csv to show beside the exploration (default: the installed atlas when "
             "present; 'none': no atlas)");
  }
  int run(const Context& c) override {
    const Catalogue catalogue = load_catalogue(c);
    report::find_gnuplot();  // before any work: a missing gnuplot is one line, not a lost hour
    const std::filesystem::path dir = writable_directory(out);
    const double estimate = jobs::estimated_explore_seconds(catalogue, settings);
    if (estimate > 300)
      std::cerr << fmt::format(
          "tripack: warning: this exploration is estimated at ~{:.0f} minutes on 2 cores (the "
          "defaults take about 6); Ctrl-C stops it with a consistent report of what finished\n",
          estimate / 60);
    // The atlas is read (every file analysed) before the exploration: a bad one costs nothing.
    std::optional<report::ExploreAtlas> shown;
    std::filesystem::path csv = atlas;
    if (atlas.empty()) {
      std::error_code ec;
      try {
        csv = data_directory() / "atlas.csv";
      } catch (const std::exception&) {
        csv.clear();
      }
      if (!csv.empty() && !std::filesystem::exists(csv, ec)) csv.clear();
    }
    if (atlas != "none" && !csv.empty()) {
      auto rows = jobs::read_atlas(csv);
      std::cerr << fmt::format("explore: the atlas {}: {} rows, analysing its best packings\n",
                               csv.string(), rows.size());
      const auto gaps_csv = csv.parent_path() / "atlas-gaps.csv";
      shown =
          report::ExploreAtlas{csv, std::move(rows), jobs::load_atlas(csv, 1),
                               std::filesystem::exists(gaps_csv) ? jobs::read_atlas_gaps(gaps_csv)
                                                                 : std::vector<jobs::AtlasGap>{},
                               jobs::read_exact_atlas(csv.parent_path() / "atlas-exact.csv")};
    }
    auto line = job_line(kInfo.name, 0);
    line.log_stages = true;  // a log gets one line per stage: building, search, billiards, ...
    report::ProgressLine progress(std::cerr, line);
    const auto result = jobs::explore(catalogue, settings, job_context(c, progress.callback()));
    progress.finish();
    report::ExploreReportOptions report_options;
    report_options.atlas = shown ? &*shown : nullptr;
    report::write_explore_report(result, dir, report_options, [](const std::string& what) {
      std::cerr << "explore: writing " << what << "\n";
    });
    print_result(Described{"explore"}
                     .number("packings", std::to_string(result.packings.size()))
                     .number("comparisons", std::to_string(result.comparisons.size()))
                     .number("seconds", fmt::format("{:.1f}", result.seconds))
                     .text("report", (dir / "index.html").string()),
                 summary);
    return result.cancelled ? cancelled("the report holds what finished") : 0;
  }
};

class Campaign : public RequestCommand<jobs::CampaignRequest, true> {
 public:
  static constexpr CommandInfo kInfo{
      "campaign",
      "Billiards runs over a range of n as work units (n, seed) on threads, or on MPI ranks "
      "when started by mpirun (rank 0 hands out units and writes); every finished unit goes to "
      "an SQLite database at once, and rerunning continues where it stopped",
      true};

  int run(const Context& c) override {
    // Under mpirun every rank builds the executor (MPI starts there); only rank 0 reports. In a
    // log every recorded unit is one line (what a batch job, or the soak test, checks after a
    // kill).
    const std::unique_ptr<Executor> executor = executor_for_launch(request.threads);
    std::optional<report::ProgressLine> progress;
    if (executor->rank() == 0) progress.emplace(std::cerr, job_line(kInfo.name, 1));
    const auto result = jobs::run_campaign(
        request, *executor, job_context(c, progress ? progress->callback() : ProgressFn{}));
    if (progress) progress->finish();
    if (result.rank != 0) return 0;  // under mpirun only rank 0 reports
    // The database's best of every n in the range, labelled like `db best`.
    const report::CampaignReport report{
        request.n_first, request.n_last,
        request.runs,    request.db,
        result,          jobs::best_table(request.db, request.n_first, request.n_last)};
    print_result(report, out);
    return result.cancelled ? cancelled("every finished unit is recorded; rerun to continue") : 0;
  }
};

class Atlas : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "atlas",
      "The best certified packings of every n: a campaign's database and every builder whose "
      "class contains n, certified anew, polished in MPFR, ranked and labelled; writes "
      "DIR/atlas.csv and DIR/atlas/LABEL.txt",
      true};

 private:
  jobs::AtlasSettings settings;
  std::string db = "data/atlas.db";
  std::string out_dir = "data";
  Output out;

 public:
  void declare(OptionList& o) override {
    o.option("--db", db, "the campaign database");
    o.option("--out", out_dir, "the data directory");
    settings.declare(o);
    out.declare(o);
  }
  int run(const Context& c) override {
    const Catalogue catalogue = load_catalogue(c);
    const std::filesystem::path dir = writable_directory(out_dir);
    report::ProgressLine progress(std::cerr, job_line(kInfo.name, 20));
    const auto atlas =
        jobs::build_atlas(catalogue, db, settings, job_context(c, progress.callback()));
    progress.finish();
    if (atlas.cancelled) return cancelled("nothing written");
    jobs::write_atlas(atlas, dir);
    print_result(atlas, out);
    if (!atlas.errors.empty() || !atlas.missing.empty())
      throw std::runtime_error(fmt::format(
          "the atlas was written, but {} candidate{} failed and {} value{} of n have no "
          "certified packing (listed above)",
          atlas.errors.size(), atlas.errors.size() == 1 ? "" : "s", atlas.missing.size(),
          atlas.missing.size() == 1 ? "" : "s"));
    return 0;
  }
};

class Exact : public RequestCommand<jobs::ExactRequest> {
 public:
  static constexpr CommandInfo kInfo{
      "exact",
      "The minimal polynomial P of d (integer relation from D digits, confirmed from 2D, "
      "proven irreducible, root isolated) and a proof that the exact configuration exists",
      false};

  int run(const Context& c) override {
    const Catalogue catalogue = request.class_id.empty() ? Catalogue{} : load_catalogue(c);
    print_result(jobs::run_exact(catalogue, request), out);
    return 0;
  }
};

class ExactAtlas : public RequestCommand<jobs::ExactAtlasSettings> {
 public:
  static constexpr CommandInfo kInfo{
      "exact-atlas",
      "'exact' on every atlas row: DIR/atlas-exact.csv and DIR/exact/LABEL.gp, resumable (a "
      "rerun skips the rows already in the table)",
      true};

  int run(const Context& c) override {
    if (request.atlas.empty()) request.atlas = data_directory() / "atlas.csv";
    if (request.out.empty()) request.out = request.atlas.parent_path();
    writable_directory(request.out.string());
    report::ProgressLine progress(std::cerr, job_line(kInfo.name, 1));
    const auto result = jobs::build_exact_atlas(request, job_context(c, progress.callback()));
    progress.finish();
    std::map<std::string, int> proofs;
    for (const auto& r : result.done) ++proofs[r.proof];
    print_result(Described{"exact atlas"}
                     .number("rows", std::to_string(result.rows))
                     .number("already_done", std::to_string(result.skipped))
                     .number("done_now", std::to_string(result.done.size()))
                     .number("exact", std::to_string(proofs["exact"]))
                     .number("existence", std::to_string(proofs["existence"]))
                     .number("none", std::to_string(proofs["none"]))
                     .number("seconds", fmt::format("{:.1f}", result.seconds))
                     .text("table", (request.out / "atlas-exact.csv").string()),
                 out);
    return result.cancelled ? cancelled("every finished row is in the table; rerun to continue")
                            : 0;
  }
};

}  // namespace

std::vector<CommandEntry> jobs_commands() {
  return {entry<Explore>(), entry<Campaign>(), entry<Atlas>(), entry<Exact>(), entry<ExactAtlas>()};
}

}  // namespace tripack::commands
