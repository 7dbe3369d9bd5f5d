#include "jobs/build_scan.hpp"

#include <fmt/format.h>

#include <fstream>
#include <mutex>
#include <stdexcept>
#include <vector>

#include "core/io.hpp"
#include "core/timing.hpp"
#include "runner/runner.hpp"

namespace tripack::jobs {

const TableFormat& build_scan_table_format() {
  static const TableFormat format{
      "build-scan table",
      "build-scan.csv",
      {"n", "member", "d", "bonds", "rattlers", "certified", "seconds", "error"}};
  return format;
}

BuildScanResult scan_builds(const Catalogue& catalogue, const BuildScanRequest& request,
                            const JobContext& job) {
  const auto start = Clock::now();
  const TableFormat& format = build_scan_table_format();
  if (request.n.first < 2 || request.n.second < request.n.first)
    throw std::invalid_argument("build-scan --n needs A..B with 2 <= A <= B");
  // Done: the N already in the table (read through its format: a foreign file is refused).
  const std::set<std::string> done = keys_in_table(request.table, format, 0);
  if (!std::filesystem::exists(request.table))
    write_whole_file(request.table, table_header(format));
  BuildScanResult result;
  result.rows = request.n.second - request.n.first + 1;
  JobItems items;
  items.count = static_cast<std::size_t>(result.rows);
  const auto n_of = [&](std::size_t i) { return request.n.first + static_cast<long long>(i); };
  result.skipped = skip_done(
      items, [&](std::size_t i) { return std::to_string(n_of(i)); }, done);
  std::vector<long double> d(items.count, 0);
  std::vector<char> certified(items.count, 0);
  // A build under way finishes when the scan is cancelled; abandoned (a second Ctrl-C), it stops
  // at its next stage or relax step, and its N stays to do.
  const JobContext build_job{
      nullptr, [&job](const Progress&) { throw_if_abandoned(job.cancel); }, {}};
  items.run = [&](std::size_t i) {
    const auto t0 = Clock::now();
    pipeline::BuildSettings settings = request.build;
    settings.threads = 1;
    try {
      const auto built = pipeline::build_best_for_n(catalogue, n_of(i), settings, build_job);
      const PackingRecord& r = built.best.record;
      d[i] = r.pattern.packing.d;
      certified[i] = r.certified;
      return table_line(
          {std::to_string(n_of(i)), pipeline::member_name(built.best.pattern.provenance),
           r.d.str(kLongDoubleDigits), std::to_string(r.bonds()), std::to_string(r.rattlers()),
           r.certified ? "true" : "false", fmt::format("{:.3f}", seconds_since(t0)), ""});
    } catch (const std::exception& e) {
      return table_line({std::to_string(n_of(i)), "", "", "", "", "false",
                         fmt::format("{:.3f}", seconds_since(t0)), e.what()});
    }
  };
  std::ofstream table(request.table, std::ios::app);
  ProgressCounter counter("build-scan", result.rows - result.skipped);
  items.finished = [&](std::size_t i, const std::string& line) {
    table << line << std::flush;  // each row as its build ends: an interruption keeps it
    if (!table) throw std::runtime_error("cannot append to " + request.table.string());
    ++result.built;
    result.certified += certified[i];
    job.report(counter.finished(fmt::format("n = {}", n_of(i)), d[i]));
  };
  result.cancelled = ThreadExecutor(request.threads).run_items(items, job.cancel).cancelled;
  table.close();
  std::vector<std::string> order;  // the table in order of N, whatever order the builds ended in
  for (std::size_t i = 0; i < items.count; ++i) order.push_back(std::to_string(n_of(i)));
  sort_table(request.table, format, 0, order);
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace tripack::jobs
