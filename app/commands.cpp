#include "app/commands.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "core/io.hpp"
#include "core/timing.hpp"
#include "exact/certificate.hpp"
#include "jobs/atlas.hpp"
#include "jobs/atlas_files.hpp"
#include "jobs/billiards_search.hpp"
#include "jobs/campaign.hpp"
#include "jobs/compare.hpp"
#include "jobs/exact_atlas.hpp"
#include "jobs/explore.hpp"
#include "jobs/import.hpp"
#include "runner/ranks.hpp"
#include "search/search.hpp"
#include "jobs/stored.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "pipeline/catalogue_checks.hpp"
#include "report/atlas_report.hpp"
#include "report/diagram.hpp"
#include "report/explore_report.hpp"
#include "report/fields.hpp"
#include "report/formats.hpp"
#include "report/plot.hpp"
#include "report/progress_line.hpp"

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

// A positive finite decimal given to `option`.
long double parse_positive_decimal(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  long double v = 0;
  try {
    v = std::stold(text, &used);
  } catch (...) {
    used = 0;
  }
  if (used != text.size() || used == 0 || !(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(option + " must be a positive decimal number, not '" + text + "'");
  return v;
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

// The progress line of a command whose result goes to stdout: on a terminal, and only when the
// result is text (a JSON or CSV consumer reads stderr apart, but a tty wants one clean line).
report::ProgressLineOptions terminal_line(std::string job, const OutputOptions& out,
                                          double quiet_seconds = 0) {
  report::ProgressLineOptions options;
  options.job = std::move(job);
  options.terminal = progress_wanted(out);
  options.quiet_seconds = quiet_seconds;
  return options;
}

// A long job's progress: redrawn on a terminal; in a log, the lines `log` asks for.
report::ProgressLineOptions job_line(std::string job, long long log_every, bool log_stages) {
  report::ProgressLineOptions options;
  options.job = std::move(job);
  options.terminal = isatty(fileno(stderr));
  options.log_every = log_every;
  options.log_stages = log_stages;
  return options;
}

jobs::BilliardsSearch search_from(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  jobs::BilliardsSearch search;
  search.scene = o.scene.empty() ? default_scene(static_cast<int>(o.n)) : load_scene(o.scene);
  jobs::prepare_scene(load_catalogue(g), search.scene, o.n);
  search.runs = o.runs;
  search.seed = o.seed;
  search.threads = o.threads;
  search.certify = o.certify;
  search.cancel = g.cancel;
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

void write_distinct_packings(const jobs::BilliardsSearchResult& result,
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
  // Builds over 2 s show their stage (the LP-free certificate of 4Delta(224) takes 14 s).
  report::ProgressLine progress(std::cerr, terminal_line("build", o.out, 2));
  pipeline::BuildSettings settings{o.digits, o.polish, o.certify, progress.callback()};
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
  report::ProgressLine progress(std::cerr, terminal_line("analyze", o.out, 2));
  request.progress = progress.callback();
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
  auto search = search_from(g, o);
  report::ProgressLine progress(
      std::cerr, terminal_line(fmt::format("billiards n={}", search.scene.n), o.out));
  search.progress = progress.callback();
  const auto result = jobs::search_billiards(search);
  progress.finish();
  // Files first: what was found is kept even if printing fails.
  if (!dir.empty()) write_distinct_packings(result, dir, o.file_format);
  print_result(result, o.out);
  if (!result.packings.empty()) {
    const auto& best = result.packings.front();
    draw_if_asked(o.diagrams, best.pattern, best.label, best.forces);
  }
  return result.runs.size() < static_cast<std::size_t>(result.runs_asked) ? 130 : 0;
}

int cmd_search(const GlobalOptions& g, const SearchOptions& o) {
  search::SearchRequest request;
  request.n = o.n;
  request.seconds = o.seconds;
  request.steps = o.steps;
  request.seed = o.seed;
  request.threads = o.threads;
  request.lattice_starts = o.lattice_starts;
  if (o.method == "restarts")
    request.method = search::SearchMethod::Restarts;
  else if (o.method != "basin-hopping")
    throw std::invalid_argument("--method must be basin-hopping or restarts, not '" + o.method +
                                "'");
  if (!o.target.empty()) request.target = parse_positive_decimal(o.target, "--target");
  request.cancel = g.cancel;
  // With --db: the database is opened (created) before any work, so a bad file costs nothing,
  // and its best packings of N are the starts.
  std::optional<store::ResultsDb> db;
  if (!o.db.empty()) {
    db.emplace(store::ResultsDb::open(o.db));
    request.starts = jobs::stored_starts(*db, o.n, 3);
  }
  report::ProgressLine progress(std::cerr, terminal_line(fmt::format("search n={}", o.n), o.out));
  request.progress = progress.callback();
  const auto result = search::run_search(request);
  progress.finish();
  // Recorded before printing: what was found is kept even if printing fails.
  if (db)
    for (std::size_t c = 0; c < result.chains.size(); ++c)
      if (!db->record(jobs::run_record_of(result, c, "tripack " TRIPACK_VERSION)))
        std::cerr << fmt::format(
            "tripack: note: {} already holds n = {} seed = {} ({}); not recorded again\n", o.db,
            o.n, result.chains[c].seed, search::search_method(result.request));
  print_result(result, o.out);
  if (!result.packings.empty()) {
    const auto& best = result.packings.front();
    draw_if_asked(o.diagrams, best.pattern, best.label, best.forces);
  }
  return result.cancelled ? 130 : 0;
}

int cmd_compare(const GlobalOptions& g, const BilliardsCommandOptions& o) {
  if (o.n < 2) throw std::invalid_argument("compare needs N >= 2");
  const Catalogue catalogue = load_catalogue(g);
  auto search = search_from(g, o);
  report::ProgressLine progress(
      std::cerr, terminal_line(fmt::format("billiards n={}", search.scene.n), o.out));
  search.progress = progress.callback();
  const auto result = jobs::compare_constructed(catalogue, o.n, search, {});
  progress.finish();
  print_result(result, o.out);
  return result.billiards.runs.size() < static_cast<std::size_t>(result.billiards.runs_asked) ? 130
                                                                                              : 0;
}

int cmd_explore(const GlobalOptions& g, const ExploreOptions& o) {
  const Catalogue catalogue = load_catalogue(g);
  jobs::ExploreSettings settings;
  settings.max_n = o.max_n;
  settings.search_steps = o.search_steps;
  settings.discovered_max_n = o.discovered_max_n;
  settings.threads = o.threads;
  settings.seed = o.seed;
  settings.accuracy = o.accuracy;
  report::find_gnuplot();  // before any work: a missing gnuplot is one line, not a lost hour
  const std::filesystem::path dir = writable_directory(o.out);
  const double estimate = jobs::estimated_explore_seconds(catalogue, settings);
  if (estimate > 300)
    std::cerr << fmt::format(
        "tripack: warning: this exploration is estimated at ~{:.0f} minutes on 2 cores (the "
        "defaults take about 6); Ctrl-C stops it with a consistent report of what finished\n",
        estimate / 60);
  // The atlas is read (every file analysed) before the exploration: a bad one costs nothing.
  std::optional<report::ExploreAtlas> atlas;
  const std::filesystem::path atlas_csv = o.atlas.empty() ? TRIPACK_DEFAULT_ATLAS : o.atlas;
  if (o.atlas != "none" && (!o.atlas.empty() || std::filesystem::exists(atlas_csv))) {
    auto rows = jobs::read_atlas(atlas_csv);
    std::cerr << fmt::format("explore: the atlas {}: {} rows, analysing its best packings\n",
                             atlas_csv.string(), rows.size());
    const auto gaps_csv = atlas_csv.parent_path() / "atlas-gaps.csv";
    atlas =
        report::ExploreAtlas{atlas_csv, std::move(rows), jobs::load_atlas(atlas_csv, 1),
                             std::filesystem::exists(gaps_csv) ? jobs::read_atlas_gaps(gaps_csv)
                                                               : std::vector<jobs::AtlasGap>{},
                             jobs::read_exact_atlas(atlas_csv.parent_path() / "atlas-exact.csv")};
  }
  const CancelToken never;
  report::ProgressLine progress(std::cerr, job_line("explore", 0, true));
  const auto result =
      jobs::explore(catalogue, settings, g.cancel ? *g.cancel : never, progress.callback());
  progress.finish();
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
  jobs::AtlasSettings settings;
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
  report::ProgressLine progress(std::cerr, job_line("atlas", 20, false));
  const auto atlas = jobs::build_atlas(catalogue, o.db, settings, g.cancel, progress.callback());
  progress.finish();
  if (atlas.interrupted) throw std::runtime_error("interrupted: nothing written");
  jobs::write_atlas(atlas, dir);
  print_result(atlas, o.out_format);
  if (!atlas.errors.empty() || !atlas.missing.empty())
    throw std::runtime_error(fmt::format(
        "the atlas was written, but {} candidate{} failed and {} value{} of n have no certified "
        "packing (listed above)",
        atlas.errors.size(), atlas.errors.size() == 1 ? "" : "s", atlas.missing.size(),
        atlas.missing.size() == 1 ? "" : "s"));
  return 0;
}

int cmd_exact(const GlobalOptions& g, const ExactOptions& o) {
  if (o.files.empty() == o.class_id.empty())
    throw std::invalid_argument("exact needs packing files or --class C --k A..B, not both");
  const auto dir =
      o.certificates.empty() ? std::filesystem::path() : writable_directory(o.certificates);
  pipeline::ExactSettings settings;
  settings.digits = o.digits;
  settings.first_digits = o.first_digits;
  settings.max_degree = o.max_degree;
  settings.existence = o.existence;
  // Class members as built (polished, not certified: exact_of_packing analyses them itself).
  std::vector<std::pair<std::string, Packing>> members;
  if (!o.class_id.empty()) {
    if (o.k_range.empty()) throw std::invalid_argument("exact --class needs --k A..B");
    const auto [k_first, k_last] = parse_range(o.k_range, "--k");
    const Catalogue catalogue = load_catalogue(g);
    pipeline::BuildSettings build;
    build.certify = false;
    for (long k = k_first; k <= k_last; ++k) {
      const auto built = pipeline::build_and_certify(catalogue, {o.class_id, k, o.p, ""}, build);
      members.emplace_back(pipeline::member_name(built.pattern.provenance),
                           built.record.pattern.packing);
    }
  }
  pipeline::ExactRun run;
  const std::size_t count = o.files.empty() ? members.size() : o.files.size();
  for (std::size_t i = 0; i < count; ++i) {
    run.packings.push_back(o.files.empty() ? pipeline::exact_of_packing(
                                                 members[i].second, members[i].first, {}, settings)
                                           : pipeline::exact_of_file(o.files[i], settings));
    const auto& r = run.packings.back();
    // Certificates first: what was proven is kept even if printing fails.
    if (!dir.empty() && r.configuration && r.configuration->proven) {
      // The certificate names the coordinates its given points come from: the packing file, or
      // for a class member LABEL.txt written beside it (the given points, 30 decimals).
      // A class member's name ("four-delta k=3") as a label the checker accepts: "four-delta_k3".
      std::string label;
      for (char ch : r.label)
        if (ch != '=') label += ch == ' ' ? '_' : ch;
      std::string coordinates;
      if (o.files.empty()) {
        coordinates = label + ".txt";
        report::write_file(dir / coordinates, pipeline::coordinates_text(r, label));
      } else {
        coordinates = std::filesystem::relative(std::filesystem::weakly_canonical(o.files[i]),
                                                std::filesystem::weakly_canonical(dir))
                          .generic_string();
      }
      std::ostringstream text;
      exact::write_certificate(
          text, {label, &r.input, &r.polynomial, &*r.configuration,
                 r.optimality ? &*r.optimality : nullptr, r.given_tolerance, coordinates});
      report::write_file(dir / (label + ".gp"), text.str());
    }
  }
  print_result(run, o.out);
  return 0;
}

int cmd_exact_atlas(const GlobalOptions& g, const ExactAtlasOptions& o) {
  jobs::ExactAtlasSettings settings;
  settings.atlas = o.atlas.empty() ? TRIPACK_DEFAULT_ATLAS : o.atlas;
  settings.out = o.out.empty() ? settings.atlas.parent_path() : std::filesystem::path(o.out);
  writable_directory(settings.out.string());
  settings.exact.digits = o.digits;
  settings.exact.first_digits = o.first_digits;
  settings.exact.max_degree = o.max_degree;
  settings.threads = o.threads;
  settings.retry_none = o.retry_none;
  std::stringstream items(o.n_range);
  for (std::string item; std::getline(items, item, ',');) {
    const auto [a, b] = parse_range(item, "--n");
    for (long n = a; n <= b; ++n) settings.n_values.push_back(n);
  }
  report::ProgressLine progress(std::cerr, job_line("exact-atlas", 1, false));
  const auto result = jobs::build_exact_atlas(settings, g.cancel, progress.callback());
  progress.finish();
  std::map<std::string, int> proofs;
  for (const auto& r : result.done) ++proofs[r.proof];
  std::cout << fmt::format(
      "exact atlas: {} rows, {} already done, {} done now (exact {}, existence {}, none {}) in "
      "{:.1f} s; "
      "table: {}\n",
      result.rows, result.skipped, result.done.size(), proofs["exact"], proofs["existence"],
      proofs["none"], result.seconds, (settings.out / "atlas-exact.csv").string());
  return result.cancelled ? 130 : 0;
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

int cmd_campaign(const GlobalOptions& g, const CampaignOptions& o) {
  const auto [first, last] = parse_range(o.n_range, "--n");
  jobs::CampaignRequest request;
  request.n_first = first;
  request.n_last = last;
  request.runs = o.runs;
  request.seed = o.seed;
  request.threads = o.threads;
  request.db = o.db;
  if (!o.scene.empty()) request.scene = load_scene(o.scene);
  if (o.search_seconds > 0) request.search_seconds = o.search_seconds;
  request.tool_version = "tripack " TRIPACK_VERSION;
  // Under mpirun every rank builds the executor (MPI starts there); only rank 0 reports. In a log
  // every recorded unit is one line (what a batch job, or the soak test, checks after a kill).
  const std::unique_ptr<Executor> executor = executor_for_launch(o.threads);
  std::optional<report::ProgressLine> progress;
  if (executor->rank() == 0) progress.emplace(std::cerr, job_line("campaign", 1, false));
  const auto result = jobs::run_campaign(request, *executor, g.cancel,
                                         progress ? progress->callback() : ProgressFn{});
  if (progress) progress->finish();
  if (result.rank != 0) return 0;  // under mpirun only rank 0 reports
  // The database's best of every n in the range, labelled like `db best`.
  const report::CampaignReport report{first, last,   o.runs,
                                      o.db,  result, jobs::best_table(o.db, first, last)};
  print_result(report, o.out);
  return result.cancelled ? 130 : 0;
}

int cmd_db_best(const DbOptions& o) {
  const auto table = o.n ? jobs::best_table(o.db, o.n, o.n)
                         : jobs::best_table(o.db, 0, std::numeric_limits<long long>::max());
  if (o.n && table.rows.empty())
    throw std::invalid_argument(fmt::format("no packings of n = {} in {}", o.n, o.db));
  print_result(table, o.out);
  return 0;
}

int cmd_db_prune(const DbPruneOptions& o) {
  auto [first, last] = std::pair<long long, long long>{0, std::numeric_limits<long long>::max()};
  if (!o.n_range.empty()) std::tie(first, last) = parse_range(o.n_range, "--n");
  print_result(jobs::prune_database(o.db, o.keep, first, last), o.out);
  return 0;
}

int cmd_db_check(const DbCheckOptions& o) {
  const jobs::DbCheck check = jobs::check_database(o.db);
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
  const auto selected = jobs::select_packings(o.db, o.n, o.rank, o.all);
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
    const std::filesystem::path path = into_directory ? dir / (r.label + chosen.extensions.front())
                                                      : std::filesystem::path(o.output);
    std::ostringstream bytes;
    chosen.write(bytes, r, write_options(r));
    report::write_file(path, bytes.str());
    std::cout << path.string() << "\n";
  }
  return 0;
}

int cmd_db_import(const GlobalOptions& g, const DbImportOptions& o) {
  jobs::ImportRequest request;
  request.files = o.files;
  request.threads = o.threads;
  request.cancel = g.cancel;
  request.db = o.db;
  if (!o.convention.empty()) request.convention = convention_option(o.convention);
  request.tool_version = "tripack " TRIPACK_VERSION;
  report::ProgressLine progress(std::cerr, terminal_line("import", o.out, 2));
  request.progress = progress.callback();
  const auto result = jobs::import_packings(request);
  progress.finish();
  for (const auto& x : result.packings)
    for (const auto& warning : x.warnings)
      std::cerr << "tripack: warning: " << x.file << ": " << warning << "\n";
  print_result(result, o.out);
  return 0;
}

}  // namespace tripack::app
