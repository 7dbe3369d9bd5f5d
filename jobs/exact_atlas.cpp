#include "jobs/exact_atlas.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/io.hpp"
#include "core/timing.hpp"
#include "exact/certificate.hpp"
#include "formats/tables.hpp"
#include "jobs/atlas_files.hpp"
#include "pipeline/build.hpp"
#include "runner/runner.hpp"

namespace tripack::jobs {

namespace {

namespace fs = std::filesystem;

// The table's columns: n, label, degree, polynomial, root_low, root_high, proof, ...
constexpr std::size_t kLabelColumn = 1, kProofColumn = 6;

// A row of the table (with its line break).
std::string exact_table_line(const pipeline::ExactResult& r) {
  const auto& p = r.polynomial;
  return table_line(
      {std::to_string(r.n), r.label, p.found ? std::to_string(p.polynomial.degree()) : "",
       p.found ? p.polynomial.pari("x") : "", p.found ? p.root.low : "", p.found ? p.root.high : "",
       r.proof, r.reason, fmt::format("{:.2f}", r.seconds())});
}

}  // namespace

std::map<std::string, ExactAtlasRow> read_exact_atlas(const fs::path& csv) {
  std::map<std::string, ExactAtlasRow> rows;
  for (const auto& [number, f] : read_table(csv, exact_atlas_table_format(), true)) {
    ExactAtlasRow r;
    try {
      r.n = std::stoll(f[0]);
    } catch (const std::exception&) {
      throw std::runtime_error(fmt::format("{}:{}: n is not a number", csv.string(), number));
    }
    r.label = f[1];
    r.degree = f[2];
    r.polynomial = f[3];
    r.root_low = f[4];
    r.root_high = f[5];
    r.proof = f[6];
    r.reason = f[7];
    rows[r.label] = r;
  }
  return rows;
}

ExactAtlasResult build_exact_atlas(const ExactAtlasSettings& settings, const JobContext& job) {
  const auto start = Clock::now();
  const std::vector<PackingRecord> rows = read_atlas(settings.atlas);
  fs::create_directories(settings.out / "exact");
  const fs::path csv = settings.out / "atlas-exact.csv";
  if (!fs::exists(csv)) {
    std::ofstream out(csv);
    out << table_header(exact_atlas_table_format());
    if (!out) throw std::runtime_error("cannot write " + csv.string());
  }
  // Done: the labels in the table, except those whose proof is "pending" (a row whose packing
  // changed in the atlas: docs/exact.md) and, with --retry-none, those whose proof is "none".
  const std::set<std::string> done =
      keys_in_table(csv, exact_atlas_table_format(), kLabelColumn, [&](const TableRecord& row) {
        const std::string& proof = row.fields[kProofColumn];
        return proof != "pending" && !(settings.retry_none && proof == "none");
      });
  ExactAtlasResult result;
  std::vector<std::size_t> chosen;  // the rows of the atlas asked for (--n), in its order
  std::vector<std::string> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (!settings.n_values.empty() && std::find(settings.n_values.begin(), settings.n_values.end(),
                                                row.n()) == settings.n_values.end())
      continue;
    order.push_back(row.label);
    chosen.push_back(i);
  }
  result.rows = static_cast<long long>(chosen.size());
  // Largest n first: the slowest start early.
  std::stable_sort(chosen.begin(), chosen.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a].n() > rows[b].n(); });
  std::vector<pipeline::ExactResult> found(rows.size());
  std::ofstream table(csv, std::ios::app);
  JobItems items;
  items.count = rows.size();
  items.order = chosen;
  result.skipped = static_cast<std::size_t>(skip_done(
      items, [&](std::size_t i) { return rows[i].label; }, done));
  ProgressCounter counter("exact", static_cast<long long>(items.order->size()));
  items.run = [&](std::size_t i) {
    const PackingRecord& row = rows[i];
    pipeline::ExactResult& r = found[i];
    try {
      r = pipeline::exact_of_file((settings.atlas.parent_path() / row.file).string(),
                                  settings.exact);
    } catch (const std::exception& e) {
      r.n = static_cast<int>(row.n());
      r.reason = e.what();
    }
    r.label = row.label;
    return std::string();
  };
  items.finished = [&](std::size_t i, const std::string&) {
    const pipeline::ExactResult& r = found[i];
    if (r.configuration && r.configuration->proven) {
      std::ofstream cert(settings.out / "exact" / (r.label + ".gp"));
      const fs::path coordinates = settings.atlas.parent_path() / rows[i].file;
      exact::write_certificate(cert, {r.label, &r.input, &r.polynomial, &*r.configuration,
                                      r.optimality ? &*r.optimality : nullptr, r.given_tolerance,
                                      fs::relative(fs::weakly_canonical(coordinates),
                                                   fs::weakly_canonical(settings.out / "exact"))
                                          .generic_string()});
      if (!cert) throw std::runtime_error("cannot write the certificate of " + r.label);
    }
    table << exact_table_line(r) << std::flush;
    if (!table) throw std::runtime_error("cannot append to " + csv.string());
    result.done.push_back(r);
    job.report(counter.finished(fmt::format(
        "{} (n = {}): {}{}", r.label, r.n, r.proof,
        r.polynomial.found ? fmt::format(", degree {}", r.polynomial.polynomial.degree()) : "")));
  };
  result.cancelled = ThreadExecutor(settings.threads).run_items(items, job.cancel).cancelled;
  table.close();
  sort_table(csv, exact_atlas_table_format(), kLabelColumn, order);
  result.seconds = seconds_since(start);
  return result;
}

pipeline::ExactRun run_exact(const Catalogue& catalogue, const ExactRequest& request) {
  if (request.files.empty() == request.class_id.empty())
    throw std::invalid_argument("exact needs packing files or --class C --k A..B, not both");
  const fs::path dir =
      request.certificates.empty() ? fs::path() : writable_directory(request.certificates);
  // Class members as built (polished, not certified: exact_of_packing analyses them itself).
  struct Member {
    std::string name, file_stem;  // "four-delta k=3", "four-delta-k3" (docs/conventions.md)
    Packing packing;
  };
  std::vector<Member> members;
  if (!request.class_id.empty()) {
    if (request.k.second < request.k.first)
      throw std::invalid_argument("exact --class needs --k A..B");
    pipeline::BuildSettings build;
    build.certify = false;
    for (long long k = request.k.first; k <= request.k.second; ++k) {
      const auto built = pipeline::build_and_certify(
          catalogue, {request.class_id, static_cast<long>(k), request.p, ""}, build);
      members.push_back({pipeline::member_name(built.pattern.provenance),
                         pipeline::member_file_stem(built.pattern.provenance),
                         built.record.pattern.packing});
    }
  }
  pipeline::ExactRun run;
  const bool from_files = !request.files.empty();
  const std::size_t count = from_files ? request.files.size() : members.size();
  for (std::size_t i = 0; i < count; ++i) {
    run.packings.push_back(
        from_files
            ? pipeline::exact_of_file(request.files[i], request.exact)
            : pipeline::exact_of_packing(members[i].packing, members[i].name, {}, request.exact));
    const auto& r = run.packings.back();
    if (dir.empty() || !r.configuration || !r.configuration->proven) continue;
    // The certificate's label, which the checker takes as a file name: a member's file stem
    // ("four-delta-k3"); a file's label without spaces or '='.
    std::string label = from_files ? "" : members[i].file_stem;
    if (from_files)
      for (char ch : r.label)
        if (ch != '=') label += ch == ' ' ? '_' : ch;
    std::string coordinates;
    if (from_files) {
      coordinates = fs::relative(fs::weakly_canonical(request.files[i]), fs::weakly_canonical(dir))
                        .generic_string();
    } else {
      coordinates = label + ".txt";
      write_whole_file(dir / coordinates, pipeline::coordinates_text(r, label));
    }
    std::ostringstream text;
    exact::write_certificate(
        text, {label, &r.input, &r.polynomial, &*r.configuration,
               r.optimality ? &*r.optimality : nullptr, r.given_tolerance, coordinates});
    write_whole_file(dir / (label + ".gp"), text.str());
  }
  return run;
}

}  // namespace tripack::jobs
