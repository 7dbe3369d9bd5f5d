#include "app/commands.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <tuple>

#include "campaign/atlas.hpp"
#include "campaign/atlas_files.hpp"
#include "campaign/campaign.hpp"
#include "campaign/import.hpp"
#include "campaign/stored.hpp"
#include "report/formats.hpp"
#include "core/io.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/billiards_search.hpp"
#include "pipeline/build.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "pipeline/compare.hpp"
#include "pipeline/explore.hpp"
#include "core/timing.hpp"
#include "report/atlas_report.hpp"
#include "report/diagram.hpp"
#include "report/explore_report.hpp"
#include "report/fields.hpp"
#include "report/packing_file.hpp"
#include "report/plot.hpp"

namespace tripack::app {

namespace {

Catalogue load_catalogue(const GlobalOptions& g) {
  return Catalogue::load(g.catalogue.empty() ? Catalogue::default_path() : g.catalogue);
}

// Renders into a buffer first, so that a formatting failure cannot leave half a result: then the
// text rendering (which cannot fail on content) is printed instead, and the error reported.
template <class Result>
void print_result(const Result& result, const OutputOptions& out) {
  std::ostringstream buffer;
  try {
    report::render(buffer, result, out.format(), {out.points});
  } catch (const std::exception& e) {
    std::ostringstream text;
    report::render(text, result, report::OutputFormat::Text, {out.points});
    std::cout << text.str() << std::flush;
    throw std::runtime_error(std::string("could not format the result (printed as text): ") +
                             e.what());
  }
  std::cout << buffer.str() << std::flush;
}

// "K" or "A..B" given to `option` (named in the errors).
std::pair<long, long> parse_range(const std::string& s, const std::string& option) {
  auto to_long = [&](const std::string& t) {
    std::size_t used = 0;
    long v = 0;
    try {
      v = std::stol(t, &used);
    } catch (...) {
      used = 0;
    }
    if (used == 0 || used != t.size())
      throw std::invalid_argument(option + " expects a number or A..B, got '" + s + "'");
    return v;
  };
  const auto dots = s.find("..");
  if (dots == std::string::npos) {
    const long k = to_long(s);
    return {k, k};
  }
  const long a = to_long(s.substr(0, dots)), b = to_long(s.substr(dots + 2));
  if (b < a) throw std::invalid_argument(option + " range " + s + " is empty");
  return {a, b};
}

bool progress_wanted(const OutputOptions& out) {
  return !out.json && !out.csv && isatty(fileno(stderr));
}

// A live line on a terminal for long searches.
std::function<void(const pipeline::SearchProgress&)> search_progress_line(int n) {
  return [n](const pipeline::SearchProgress& p) {
    if (p.live)
      std::cerr << fmt::format(
          "\rbilliards n={}: {}/{} runs done; run {}: {:.3g} events, {:.2f} M events/s, d = "
          "{:.10Lg}, gap ~{:.1e}      ",
          n, p.runs_done, p.runs, p.run, static_cast<double>(p.live->events),
          p.live->seconds > 0 ? static_cast<double>(p.live->events) / p.live->seconds / 1e6 : 0.0,
          d_from_diameter(p.live->diameter), p.live->relative_gap);
    else
      std::cerr << fmt::format(
          "\rbilliards n={}: {}/{} runs, last d = {:.12Lg}, {:.2f} M events/s      ", n,
          p.runs_done, p.runs, p.finished_d.value_or(0), p.events_per_second / 1e6);
    std::cerr << std::flush;
  };
}

// A live line on a terminal for an analysis or build that has run over 2 s: the elapsed time,
// the stage, its step and d, redrawn five times a second by a ticker thread (one stage can
// last long without reporting: the LP-free certificate of 4Delta(224) takes 14 s). Shorter runs
// print nothing. finish() stops the ticker and ends the line.
class StageProgressLine {
 public:
  explicit StageProgressLine(std::string what) : what_(std::move(what)) {}
  ~StageProgressLine() { finish(); }
  pipeline::AnalysisProgressFn callback() {
    if (!ticker_.joinable()) ticker_ = std::thread([this] { tick(); });
    return [this](const pipeline::AnalysisProgress& p) {
      std::lock_guard<std::mutex> lock(mutex_);
      latest_ = p;
    };
  }
  void finish() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stopped_) return;
      stopped_ = true;
    }
    wake_.notify_all();
    if (ticker_.joinable()) ticker_.join();
    if (width_ > 0) std::cerr << "\n";
  }

 private:
  void tick() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stopped_; })) {
      const double now = seconds_since(start_);
      if (now < 2) continue;
      std::string line = fmt::format("\r{}: {:.1f} s, {}", what_, now, latest_.stage);
      if (latest_.step > 0) line += fmt::format(" step {}", latest_.step);
      if (latest_.d > 0) line += fmt::format(", d = {:.15Lg}", latest_.d);
      const std::size_t length = line.size();
      line.append(width_ > length ? width_ - length : 0, ' ');
      width_ = length;
      std::cerr << line << std::flush;
    }
  }
  std::string what_;
  Clock::time_point start_ = Clock::now();
  std::mutex mutex_;
  std::condition_variable wake_;
  pipeline::AnalysisProgress latest_;
  bool stopped_ = false;
  std::size_t width_ = 0;
  std::thread ticker_;
};

pipeline::BilliardsSearch search_from(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  pipeline::BilliardsSearch search;
  search.scene = o.scene.empty() ? default_scene(static_cast<int>(o.n)) : load_scene(o.scene);
  pipeline::prepare_scene(load_catalogue(g), search.scene, o.n);
  search.runs = o.runs;
  search.seed = o.seed;
  search.threads = o.threads;
  search.certify = o.certify;
  if (progress_wanted(o.out)) search.progress = search_progress_line(search.scene.n);
  return search;
}

// The directory, created if needed; checked before any work so a long run cannot end in an
// unwritable place.
std::filesystem::path writable_directory(const std::string& name) {
  const std::filesystem::path dir(name);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir) || access(dir.c_str(), W_OK) != 0)
    throw std::runtime_error("cannot write to directory '" + name + "'");
  return dir;
}

// -o DIR is checked before the runs (a search must not end in an unwritable directory).
std::filesystem::path prepare_output_dir(const BilliardsCommandOptions& o) {
  if (!find_format(o.file_format))
    throw std::invalid_argument("--format must be one of " + format_names() + ", not '" +
                                o.file_format + "'");
  return writable_directory(o.output_dir);
}

void write_distinct_packings(const pipeline::BilliardsSearchResult& result,
                             const std::filesystem::path& dir, const std::string& format) {
  const std::string extension = find_format(format)->extensions.front();
  for (const auto& x : result.packings)
    write_packing_file((dir / (x.label + extension)).string(), x, WriteOptions{});
}

// -o FILE of build and analyze: the format by extension, the coordinates with --digits
// significant digits (never fewer than a long double's round trip, so no file is rounded).
WriteOptions file_digits(int digits) {
  WriteOptions options;
  options.digits = options.d_digits = std::max(digits, kLongDoubleRoundTripDigits);
  return options;
}

// The diagrams asked for with --svg/--png/--pdf.
void draw_if_asked(const DiagramTargets& targets, const Pattern& pattern, const std::string& label,
                   const std::vector<long double>& forces) {
  report::Diagram diagram{pattern, label, format_significant(pattern.packing.d, 15), forces};
  report::DiagramOptions options;
  options.forces = targets.forces;
  for (const auto* path : {&targets.svg, &targets.png, &targets.pdf})
    if (!path->empty()) report::draw_packing(diagram, *path, options);
}

std::vector<long double> forces_of(const std::optional<pipeline::Analysis>& analysis) {
  return analysis ? analysis->stress.forces : std::vector<long double>{};
}

}  // namespace

int cmd_classes(const GlobalOptions& g, const OutputOptions& out) {
  print_result(load_catalogue(g), out);
  return 0;
}

int cmd_classify(const GlobalOptions& g, long long n, const OutputOptions& out) {
  print_result(pipeline::classify(load_catalogue(g), n), out);
  return 0;
}

int cmd_build(const GlobalOptions& g, const BuildOptions& o) {
  const Catalogue catalogue = load_catalogue(g);
  StageProgressLine progress("build");
  pipeline::BuildSettings settings{o.digits, o.polish, o.certify, {}};
  if (progress_wanted(o.out)) settings.progress = progress.callback();
  pipeline::BestBuild result;
  if (o.n) {
    if (!o.class_id.empty() || o.k != kUnsetK || o.p)
      throw std::invalid_argument("build --n N takes no class, --k or --p");
    result = pipeline::build_best_for_n(catalogue, o.n, settings);
  } else {
    if (o.class_id.empty()) throw std::invalid_argument("build needs a class (or --n N)");
    if (o.k == kUnsetK) throw std::invalid_argument("build needs --k K");
    result.best =
        pipeline::build_and_certify(catalogue, {o.class_id, o.k, o.p, o.variant}, settings);
  }
  progress.finish();
  print_result(result, o.out);
  const PackingRecord& built = result.best.record;
  if (!o.output.empty()) write_packing_file(o.output, built, file_digits(o.digits));
  draw_if_asked(o.diagrams, built.pattern, pipeline::member_name(built.pattern.provenance),
                built.forces);
  return 0;
}

int cmd_check_formula(const GlobalOptions& g, const CheckFormulaOptions& o) {
  const auto [k_first, k_last] = parse_range(o.k_range, "--k");
  const auto check = pipeline::check_formula(load_catalogue(g), o.class_id, k_first, k_last, o.p);
  print_result(check, o.out);
  if (!check.all_ok) throw std::runtime_error("check-formula found mismatches");
  return 0;
}

int cmd_table(const GlobalOptions& g, long k_count, const OutputOptions& out) {
  const auto table = pipeline::catalogue_table(load_catalogue(g), k_count);
  print_result(table, out);
  if (!table.all_ok) throw std::runtime_error("the table has rows that are not verified");
  return 0;
}

int cmd_analyze(const AnalyzeOptions& o) {
  pipeline::AnalyzeRequest request;
  request.file = o.file;
  if (!o.convention.empty()) {
    request.convention = parse_convention(o.convention);
    if (!request.convention)
      throw std::invalid_argument("unknown convention '" + o.convention +
                                  "' (unit-triangle, radius, unit-disk-side)");
  }
  request.digits = o.digits;
  if (o.n) request.expected_n = o.n;
  request.lp_any_size = o.lp_any_size;
  StageProgressLine progress("analyze");
  if (progress_wanted(o.out)) request.progress = progress.callback();
  const auto result = pipeline::analyze_file(request);
  progress.finish();
  for (const auto& warning : result.warnings) std::cerr << "tripack: warning: " << warning << "\n";
  print_result(result, o.out);
  if (!o.output.empty())
    write_packing_file(o.output, pipeline::record_of(result.analysis), file_digits(o.digits));
  draw_if_asked(o.diagrams, result.analysis.pattern,
                std::filesystem::path(o.file).filename().string(), result.analysis.stress.forces);
  return 0;
}

int cmd_billiards(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  if (o.n == 0 && o.scene.empty()) throw std::invalid_argument("billiards needs N or --scene FILE");
  const auto dir = o.output_dir.empty() ? std::filesystem::path() : prepare_output_dir(o);
  const auto search = search_from(g, o);
  const auto result = pipeline::search_billiards(search);
  if (search.progress) std::cerr << "\n";
  // Files first: what was found is kept even if printing fails.
  if (!dir.empty()) write_distinct_packings(result, dir, o.file_format);
  print_result(result, o.out);
  if (!result.packings.empty()) {
    const auto& best = result.packings.front();
    draw_if_asked(o.diagrams, best.pattern, best.label, best.forces);
  }
  return 0;
}

int cmd_compare(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  if (o.n < 2) throw std::invalid_argument("compare needs N >= 2");
  const Catalogue catalogue = load_catalogue(g);
  auto search = search_from(g, o);
  const auto result = pipeline::compare_constructed(catalogue, o.n, search, {});
  if (search.progress) std::cerr << "\n";
  print_result(result, o.out);
  return 0;
}

namespace {

// Ctrl-C asks the explorer to stop between items; a second Ctrl-C ends the program at once.
std::atomic<bool> explore_cancel{false};
extern "C" void on_interrupt(int) {
  if (explore_cancel.exchange(true)) std::_Exit(130);
}

// A progress bar with ETA on a terminal; elsewhere one line per stage.
std::function<void(const pipeline::ExploreProgress&)> explore_progress_line() {
  const bool tty = isatty(fileno(stderr));
  return [tty, last_stage = std::string()](const pipeline::ExploreProgress& p) mutable {
    if (!tty) {
      if (p.stage != last_stage)
        std::cerr << fmt::format("explore: {} ({:.0f} s)\n", p.stage, p.elapsed);
      last_stage = p.stage;
      return;
    }
    const int width = 30;
    const int filled = static_cast<int>(p.fraction * width + 0.5);
    const double eta = p.fraction > 0.02 ? p.elapsed * (1 - p.fraction) / p.fraction : -1;
    std::cerr << fmt::format("\r[{}{}] {:3.0f}% {:>5.0f} s, ETA {:>5}  {}: {:<40.40}",
                             std::string(static_cast<std::size_t>(filled), '#'),
                             std::string(static_cast<std::size_t>(width - filled), '.'),
                             p.fraction * 100, p.elapsed,
                             eta < 0 ? std::string("?") : fmt::format("{:.0f} s", eta), p.stage,
                             p.item)
              << std::flush;
  };
}

}  // namespace

int cmd_explore(const GlobalOptions& g, const ExploreOptions& o) {
  const Catalogue catalogue = load_catalogue(g);
  pipeline::ExploreSettings settings;
  settings.max_n = o.max_n;
  settings.runs = o.runs;
  settings.threads = o.threads;
  settings.seed = o.seed;
  settings.accuracy = o.accuracy;
  report::find_gnuplot();  // before any work: a missing gnuplot is one line, not a lost hour
  const std::filesystem::path dir = writable_directory(o.out);
  const double estimate = pipeline::estimated_explore_seconds(catalogue, settings);
  if (estimate > 300)
    std::cerr << fmt::format(
        "tripack: warning: this exploration is estimated at ~{:.0f} minutes on 2 cores (the "
        "defaults take about 5); Ctrl-C stops it with a consistent report of what finished\n",
        estimate / 60);
  // The atlas is read (every file analysed) before the exploration: a bad one costs nothing.
  std::optional<report::ExploreAtlas> atlas;
  const std::filesystem::path atlas_csv = o.atlas.empty() ? TRIPACK_DEFAULT_ATLAS : o.atlas;
  if (o.atlas != "none" && (!o.atlas.empty() || std::filesystem::exists(atlas_csv))) {
    auto rows = campaign::read_atlas(atlas_csv);
    std::cerr << fmt::format("explore: the atlas {}: {} rows, analysing its best packings\n",
                             atlas_csv.string(), rows.size());
    const auto gaps_csv = atlas_csv.parent_path() / "atlas-gaps.csv";
    atlas =
        report::ExploreAtlas{atlas_csv, std::move(rows), campaign::load_atlas(atlas_csv, 1),
                             std::filesystem::exists(gaps_csv) ? campaign::read_atlas_gaps(gaps_csv)
                                                               : std::vector<campaign::AtlasGap>{}};
  }
  explore_cancel = false;
  std::signal(SIGINT, on_interrupt);
  const auto result =
      pipeline::explore(catalogue, settings, explore_cancel, explore_progress_line());
  std::signal(SIGINT, SIG_DFL);
  if (isatty(fileno(stderr))) std::cerr << "\n";
  report::ExploreReportOptions report_options;
  report_options.atlas = atlas ? &*atlas : nullptr;
  report::write_explore_report(result, dir, report_options, [](const std::string& what) {
    std::cerr << "explore: writing " << what << "\n";
  });
  std::cout << fmt::format("{} packings, {} comparisons in {:.1f} s; report: {}\n",
                           result.packings.size(), result.comparisons.size(), result.seconds,
                           (dir / "index.html").string());
  if (result.interrupted) throw std::runtime_error("interrupted: the report holds what finished");
  return 0;
}

int cmd_atlas(const GlobalOptions& g, const AtlasOptions& o) {
  const Catalogue catalogue = load_catalogue(g);
  campaign::AtlasSettings settings;
  // "A..B", "N" or a comma-separated list of them.
  settings.n_first = std::numeric_limits<long long>::max();
  settings.n_last = 0;
  std::stringstream items(o.n_range);
  for (std::string item; std::getline(items, item, ',');) {
    const auto [a, b] = parse_range(item, "--n");
    settings.n_first = std::min<long long>(settings.n_first, a);
    settings.n_last = std::max<long long>(settings.n_last, b);
    for (long n = a; n <= b; ++n) settings.n_values.push_back(n);
  }
  if (settings.n_values.empty()) throw std::invalid_argument("--n is empty");
  std::tie(settings.ranked_first, settings.ranked_last) = parse_range(o.ranked, "--ranked");
  settings.ranked_count = o.ranked_count;
  settings.digits = o.digits;
  settings.threads = o.threads;
  const std::filesystem::path dir = writable_directory(o.out);
  const bool tty = isatty(fileno(stderr));
  explore_cancel = false;
  std::signal(SIGINT, on_interrupt);
  const auto atlas = campaign::build_atlas(
      catalogue, o.db, settings, &explore_cancel, [tty](const campaign::AtlasProgress& p) {
        const std::string line =
            fmt::format("atlas: n = {} done ({} of {}), {:.0f} s", p.n, p.done, p.total, p.elapsed);
        if (tty)
          std::cerr << "\r" << line << "\033[K" << std::flush;
        else if (p.done % 20 == 0 || p.done == p.total)
          std::cerr << line << "\n";
      });
  std::signal(SIGINT, SIG_DFL);
  if (tty) std::cerr << "\n";
  if (atlas.interrupted) throw std::runtime_error("interrupted: nothing written");
  campaign::write_atlas(atlas, dir);
  print_result(atlas, o.out_format);
  if (!atlas.errors.empty() || !atlas.missing.empty())
    throw std::runtime_error(fmt::format(
        "the atlas was written, but {} candidate{} failed and {} value{} of n have no certified "
        "packing (listed above)",
        atlas.errors.size(), atlas.errors.size() == 1 ? "" : "s", atlas.missing.size(),
        atlas.missing.size() == 1 ? "" : "s"));
  return 0;
}

int cmd_draw(const GlobalOptions& g, const DrawOptions& o) {
  if (o.output.empty()) throw std::invalid_argument("draw needs -o FILE (.svg, .png or .pdf)");
  report::Diagram diagram;
  if (std::filesystem::is_regular_file(o.what)) {
    pipeline::AnalyzeRequest request;
    request.file = o.what;
    if (!o.convention.empty()) {
      request.convention = parse_convention(o.convention);
      if (!request.convention)
        throw std::invalid_argument("unknown convention '" + o.convention + "'");
    }
    const auto result = pipeline::analyze_file(request);
    for (const auto& warning : result.warnings)
      std::cerr << "tripack: warning: " << warning << "\n";
    diagram = {result.analysis.pattern, std::filesystem::path(o.what).stem().string(),
               format_significant(result.analysis.pattern.packing.d, 15),
               result.analysis.stress.forces};
  } else {
    if (o.k == kUnsetK)
      throw std::invalid_argument("draw: '" + o.what + "' is not a file; a class needs --k K");
    const auto b =
        pipeline::build_and_certify(load_catalogue(g), {o.what, o.k, o.p, o.variant}, {});
    diagram = {b.analysis ? b.analysis->pattern : b.pattern,
               pipeline::member_name(b.pattern.provenance),
               format_significant(b.pattern.packing.d, 15), forces_of(b.analysis)};
  }
  report::DiagramOptions options;
  options.forces = o.forces;
  options.disk_labels = o.disk_labels;
  options.width_pixels = o.width;
  report::draw_packing(diagram, o.output, options);
  std::cout << o.output << "\n";
  return 0;
}

int cmd_campaign(const GlobalOptions&, const CampaignOptions& o) {
  const auto [first, last] = parse_range(o.n_range, "--n");
  campaign::CampaignRequest request;
  request.n_first = first;
  request.n_last = last;
  request.runs = o.runs;
  request.seed = o.seed;
  request.threads = o.threads;
  request.db = o.db;
  if (!o.scene.empty()) request.scene = load_scene(o.scene);
  request.tool_version = "tripack " TRIPACK_VERSION;
  const bool tty = isatty(fileno(stderr));
  explore_cancel = false;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);       // mpirun passes a Ctrl-C on to the ranks as SIGTERM
  std::map<long long, long double> best_d;  // best certified d per n found in this call
  const auto result = campaign::run_campaign(
      request, &explore_cancel, [tty, &best_d](const campaign::CampaignProgress& p) {
        if (p.d > 0 && p.d > best_d[p.n]) best_d[p.n] = p.d;
        const double eta = p.done > 0 ? p.elapsed / static_cast<double>(p.done) *
                                            static_cast<double>(p.total - p.done)
                                      : 0.0;
        const auto best = best_d.find(p.n);
        if (tty) {
          std::cerr << fmt::format(
                           "\rcampaign: {}/{} units ({} already recorded), n = {}: best d {}, ETA "
                           "{:.0f} s     ",
                           p.done, p.total, p.skipped, p.n,
                           best != best_d.end() ? fmt::format("{:.15Lg}", best->second)
                                                : "none yet",
                           eta)
                    << std::flush;
        } else {
          // A log line per recorded unit: what a batch job (or the soak test) can check against
          // the database after a kill.
          std::cerr << fmt::format("campaign: recorded n = {} seed = {}: {}\n", p.n, p.seed,
                                   p.d > 0 ? fmt::format("d = {:.15Lg}", p.d) : "not certified")
                    << std::flush;
        }
      });
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (result.rank != 0) return 0;  // under mpirun only rank 0 reports
  if (tty) std::cerr << "\n";
  // The database's best of every n in the range, labelled like `db best`.
  const report::CampaignReport report{first, last,   o.runs,
                                      o.db,  result, campaign::best_table(o.db, first, last)};
  print_result(report, o.out);
  return result.cancelled ? 130 : 0;
}

int cmd_db_best(const DbOptions& o) {
  const auto table = o.n ? campaign::best_table(o.db, o.n, o.n)
                         : campaign::best_table(o.db, 0, std::numeric_limits<long long>::max());
  if (o.n && table.rows.empty())
    throw std::invalid_argument(fmt::format("no packings of n = {} in {}", o.n, o.db));
  print_result(table, o.out);
  return 0;
}

int cmd_db_prune(const DbPruneOptions& o) {
  auto [first, last] = std::pair<long long, long long>{0, std::numeric_limits<long long>::max()};
  if (!o.n_range.empty()) std::tie(first, last) = parse_range(o.n_range, "--n");
  print_result(campaign::prune_database(o.db, o.keep, first, last), o.out);
  return 0;
}

int cmd_db_check(const DbCheckOptions& o) {
  const campaign::DbCheck check = campaign::check_database(o.db);
  if (check.stats.integrity != "ok")
    throw std::runtime_error("database " + o.db +
                             " fails the integrity check: " + check.stats.integrity);
  print_result(check, o.out);
  if (check.duplicates() > 0) {
    // The result is printed (one JSON object with --json); the failure is one line on stderr.
    std::cerr << fmt::format(
        "tripack: error: database {} holds duplicates: {} runs with a repeated (n, seed), {} "
        "packings with a repeated (n, contact graph, d to 12 digits)\n",
        o.db, check.stats.duplicate_runs, check.stats.duplicate_packings);
    return 1;
  }
  return 0;
}

namespace {

Convention convention_option(const std::string& name) {
  const auto c = parse_convention(name);
  if (!c)
    throw std::invalid_argument("unknown convention '" + name +
                                "' (unit-triangle, radius, unit-disk-side)");
  return *c;
}

// The format a path's extension names, if it names one.
const PackingFormat* format_of_extension(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  for (const auto& f : packing_formats())
    for (const auto& e : f.extensions)
      if (e == ext) return &f;
  return nullptr;
}

}  // namespace

int cmd_db_export(const DbExportOptions& o) {
  // Everything the command line decides is checked before the database is read.
  const PackingFormat* format = nullptr;
  if (!o.format.empty()) {
    format = find_format(o.format);
    if (!format)
      throw std::invalid_argument("--format must be one of " + format_names() + ", not '" +
                                  o.format + "'");
  }
  const Convention convention = convention_option(o.convention);
  const bool into_directory =
      !o.output.empty() && (o.all || std::filesystem::is_directory(o.output));
  if (!o.output.empty() && !into_directory) {
    const auto* named = format_of_extension(o.output);
    if (format && named && format != named)
      throw std::invalid_argument("-o " + o.output + " names another format than --format " +
                                  o.format);
    if (!format) format = named;
  }
  const PackingFormat& chosen = format ? *format : packing_formats().front();
  const auto selected = campaign::select_packings(o.db, o.n, o.rank, o.all);
  auto write_options = [&](const PackingRecord& r) {
    WriteOptions w;
    w.convention = convention;
    w.digits = o.digits;
    w.d_digits = std::min(o.digits, kLongDoubleDigits);  // the digits the database keeps of d
    w.label = r.label;
    return w;
  };
  if (o.output.empty()) {
    // Rendered whole before printing. Several packings follow one another (JSON: an array).
    std::ostringstream buffer;
    const bool array = chosen.name == "json" && selected.size() > 1;
    if (array) buffer << "[\n";
    for (std::size_t i = 0; i < selected.size(); ++i) {
      if (i > 0) buffer << (array ? ",\n" : "\n");
      chosen.write(buffer, selected[i], write_options(selected[i]));
    }
    if (array) buffer << "]\n";
    std::cout << buffer.str() << std::flush;
    return 0;
  }
  const auto dir = into_directory ? writable_directory(o.output) : std::filesystem::path();
  for (const auto& r : selected) {
    const std::filesystem::path path = into_directory
                                           ? dir / (r.label + chosen.extensions.front())
                                           : std::filesystem::path(o.output);
    std::ostringstream bytes;
    chosen.write(bytes, r, write_options(r));
    report::write_file(path, bytes.str());
    std::cout << path.string() << "\n";
  }
  return 0;
}

int cmd_db_import(const DbImportOptions& o) {
  campaign::ImportRequest request;
  request.files = o.files;
  request.db = o.db;
  if (!o.convention.empty()) request.convention = convention_option(o.convention);
  request.tool_version = "tripack " TRIPACK_VERSION;
  const auto result = campaign::import_packings(request);
  for (const auto& x : result.packings)
    for (const auto& warning : x.warnings)
      std::cerr << "tripack: warning: " << x.file << ": " << warning << "\n";
  print_result(result, o.out);
  return 0;
}

}  // namespace tripack::app
