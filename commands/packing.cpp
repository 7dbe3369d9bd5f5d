// The commands on one packing: build (a class member), analyze (a file), draw.
#include <filesystem>
#include <memory>

#include "commands/common.hpp"
#include "formats/formats.hpp"
#include "jobs/build_scan.hpp"
#include "pipeline/analyze.hpp"
#include "pipeline/build.hpp"
#include "report/diagram.hpp"
#include "report/results/build.hpp"
#include "report/results/summary.hpp"

namespace tripack::commands {

namespace {

// -o FILE of build and analyze: the format by extension, the coordinates with --digits
// significant digits (never fewer than a long double's round trip, so no file is rounded).
WriteOptions file_digits(int digits) {
  WriteOptions options;
  options.digits = options.d_digits = std::max(digits, kLongDoubleRoundTripDigits);
  return options;
}

class Build : public Command {
 public:
  static constexpr CommandInfo kInfo{"build", "Construct, polish and certify a class member", true,
                                     "nothing was built"};

 private:
  BuildRequest member{"", pipeline::kUnsetK, 0, ""};
  long long n = 0;  // --n: the best builder for n
  pipeline::BuildSettings settings;
  std::string output;
  Output out;
  Diagrams diagrams;

 public:
  void declare(OptionList& o) override {
    pipeline::declare_member(o, member, false);
    o.option("--n", n,
             "number of disks: build every catalogue member and variant containing n and certify "
             "the densest (no class, --k, --p); the candidates are listed");
    settings.declare(o);
    o.option("-o,--output", output, "write the coordinates (" + format_names() + ", by extension)");
    out.declare(o, true);
    diagrams.declare(o);
  }
  int run(const Context& c) override {
    const Catalogue catalogue = load_catalogue(c);
    // Builds over 2 s show their stage (the LP-free certificate of 4Delta(224) takes 14 s).
    report::ProgressLine progress(std::cerr, terminal_line(kInfo.name, out, 2));
    const JobContext job = job_context(c, progress.callback());
    pipeline::BestBuild result;
    try {
      result = pipeline::build_requested(catalogue, member, n, settings, job);
    } catch (const Cancelled&) {
      claim_ending(c);
      progress.finish();
      return cancelled(kInfo.one_item_lost);
    }
    claim_ending(c);
    progress.finish();
    // A request that came after the last check: the build stops as if it had reached one.
    if (c.cancel && c.cancel->cancelled()) return cancelled(kInfo.one_item_lost);
    print_result(result, out);
    const PackingRecord& built = result.best.record;
    if (!output.empty()) write_packing_file(output, built, file_digits(settings.digits));
    diagrams.draw(built.pattern, pipeline::member_name(built.pattern.provenance), built.forces);
    return 0;
  }
};

class Analyze : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "analyze",
      "Relax, find bonds and rattlers, test rigidity, certify a file of points.\n"
      "Layouts (one point per line unless JSON; '#' lines are comments; indices are 0-based):\n"
      "  x y        centres (default convention: unit-triangle, the side-1 triangle with\n"
      "             vertices (0,0) (1,0) (1/2,sqrt3/2))\n"
      "  x y r      circles of radius r (implies --convention radius)\n"
      "  i x y      the record tables' style (i = 0..n-1 or 1..n, any order)\n"
      "  CSV        with a header naming x, y (and index, r, rattler), or bare x,y rows\n"
      "  JSON       {\"points\": [[x, y], ...]} or a bare list [[x, y], ...]",
      false};

 private:
  pipeline::AnalyzeRequest request;
  std::string output;
  Output out;
  Diagrams diagrams;

 public:
  void declare(OptionList& o) override {
    request.declare(o);
    o.option("-o,--output", output,
             "write the certified packing (" + format_names() + ", by extension)");
    out.declare(o, true);
    diagrams.declare(o);
  }
  int run(const Context&) override {
    report::ProgressLine progress(std::cerr, terminal_line(kInfo.name, out, 2));
    request.progress = progress.callback();
    const auto result = pipeline::analyze_file(request);
    progress.finish();
    for (const auto& warning : result.warnings)
      std::cerr << "tripack: warning: " << warning << "\n";
    print_result(result, out);
    if (!output.empty()) {
      PackingRecord record = pipeline::record_of(result.analysis);
      record.label = result.label;  // the label read is the label written
      write_packing_file(output, record, file_digits(request.digits));
    }
    diagrams.draw(result.analysis.pattern, std::filesystem::path(request.file).filename().string(),
                  result.analysis.stress.forces);
    return 0;
  }
};

class Draw : public Command {
 public:
  static constexpr CommandInfo kInfo{
      "draw",
      "Diagram of a packing (a points file, analysed; or a class member, built), like the "
      "paper's figures: shaded disks, unshaded rattlers, bond dots, labels, d",
      false};

 private:
  std::string what;  // a points file, or a class id
  BuildRequest member{"", pipeline::kUnsetK, 0, ""};
  std::optional<Convention> convention;
  std::string output;
  report::DiagramOptions options;

 public:
  void declare(OptionList& o) override {
    o.option("what", what, "a points file (any layout of 'analyze') or a class id").required();
    o.option("--k", member.k, "class index k").shown_default("");
    o.option("--p", member.p, "matrix row p").range(1, 1e9);
    o.option("--variant", member.variant, "variant");
    o.parsed(
        "--convention", [this](const std::string& s) { convention = convention_from_option(s); },
        "as the file declares", "of the points file (see analyze)");
    o.option("-o,--output", output, "the picture: .svg, .png or .pdf").required();
    o.flag("--forces", options.forces, "bond forces of the stress certificate as line widths");
    o.flag("!--no-labels", options.disk_labels, "no disk indices");
    o.option("--width", options.width_pixels, "PNG width in pixels").range(100, 20000);
  }
  int run(const Context& c) override {
    report::Diagram diagram;
    if (std::filesystem::is_regular_file(what)) {
      pipeline::AnalyzeRequest request;
      request.file = what;
      request.convention = convention;
      const auto result = pipeline::analyze_file(request);
      for (const auto& warning : result.warnings)
        std::cerr << "tripack: warning: " << warning << "\n";
      diagram = {result.analysis.pattern, std::filesystem::path(what).stem().string(),
                 format_significant(result.analysis.pattern.packing.d, 15),
                 result.analysis.stress.forces};
    } else {
      if (member.k == pipeline::kUnsetK)
        throw std::invalid_argument("draw: '" + what + "' is not a file; a class needs --k K");
      member.class_id = what;
      const auto b = pipeline::build_and_certify(load_catalogue(c), member, {});
      diagram = {b.analysis ? b.analysis->pattern : b.pattern,
                 pipeline::member_name(b.pattern.provenance),
                 format_significant(b.pattern.packing.d, 15),
                 b.analysis ? b.analysis->stress.forces : std::vector<long double>{}};
    }
    report::draw_packing(diagram, output, options);
    std::cout << output << "\n";
    return 0;
  }
};

class BuildScan : public RequestCommand<jobs::BuildScanRequest> {
 public:
  static constexpr CommandInfo kInfo{
      "build-scan",
      "'build --n' for every N of a range, a row per N appended to --table; resumable (a rerun "
      "skips the N already in the table)",
      true};

  int run(const Context& c) override {
    report::ProgressLine progress(std::cerr, job_line(kInfo.name, 1));
    const auto result =
        jobs::scan_builds(load_catalogue(c), request, job_context(c, progress.callback()));
    progress.finish();
    print_result(Described{"build scan"}
                     .number("rows", std::to_string(result.rows))
                     .number("already_done", std::to_string(result.skipped))
                     .number("built_now", std::to_string(result.built))
                     .number("certified_now", std::to_string(result.certified))
                     .number("seconds", fmt::format("{:.1f}", result.seconds))
                     .text("table", request.table.string()),
                 out);
    return result.cancelled ? cancelled("the table holds the rows that finished") : 0;
  }
};

}  // namespace

std::vector<CommandEntry> packing_commands() {
  return {entry<Build>(), entry<BuildScan>(), entry<Analyze>(), entry<Draw>()};
}

}  // namespace tripack::commands
