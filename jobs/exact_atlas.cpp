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

// The labels already in the table (its second column); not those whose proof is "pending" (a
// row whose packing changed in the atlas: docs/exact.md), and with `except_none` not those whose
// proof is "none": they are run again.
std::set<std::string> labels_in(const fs::path& csv, bool except_none) {
  std::set<std::string> labels;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const auto a = line.find(','), b = line.find(',', a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    const auto fields = split_csv(line);
    const std::string proof = fields.size() > 6 ? fields[6] : "";
    if (proof == "pending" || (except_none && proof == "none")) continue;
    labels.insert(line.substr(a + 1, b - a - 1));
  }
  return labels;
}

// The table in the atlas's order (rows of labels the atlas no longer has go last), written to a
// temporary file and renamed over the old one.
void sort_table(const fs::path& csv, const std::vector<std::string>& order,
                const std::string& header) {
  std::map<std::string, std::size_t> rank;
  for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = i;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  // A label's last row wins (a row run again is appended after its old one).
  std::map<std::string, std::string> last;
  std::vector<std::string> labels;
  while (std::getline(in, line)) {
    const auto a = line.find(','), b = line.find(',', a + 1);
    const std::string label = a == std::string::npos ? "" : line.substr(a + 1, b - a - 1);
    if (!last.count(label)) labels.push_back(label);
    last[label] = line;
  }
  std::vector<std::pair<std::size_t, std::string>> rows;
  for (const auto& label : labels)
    rows.emplace_back(rank.count(label) ? rank[label] : order.size(), last[label]);
  std::stable_sort(rows.begin(), rows.end(),
                   [](const auto& x, const auto& y) { return x.first < y.first; });
  const fs::path temporary = csv.string() + ".tmp";
  {
    std::ofstream out(temporary);
    out << header << "\n";
    for (const auto& r : rows) out << r.second << "\n";
    if (!out) throw std::runtime_error("cannot write " + temporary.string());
  }
  fs::rename(temporary, csv);
}

}  // namespace

std::string exact_csv_header() {
  const std::string line = table_header(exact_atlas_table_format());
  return line.substr(0, line.size() - 1);
}

std::string exact_csv_row(const pipeline::ExactResult& r) {
  const auto& p = r.polynomial;
  const std::string line = table_line(
      {std::to_string(r.n), r.label, p.found ? std::to_string(p.polynomial.degree()) : "",
       p.found ? p.polynomial.pari("x") : "", p.found ? p.root.low : "", p.found ? p.root.high : "",
       r.proof, r.reason,
       fmt::format("{:.2f}", r.seconds_polish + r.seconds_polynomial + r.seconds_existence)});
  return line.substr(0, line.size() - 1);
}

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

ExactAtlasResult build_exact_atlas(const ExactAtlasSettings& settings, const CancelToken* cancel,
                                   const ProgressFn& progress) {
  const auto start = Clock::now();
  const std::vector<PackingRecord> rows = read_atlas(settings.atlas);
  fs::create_directories(settings.out / "exact");
  const fs::path csv = settings.out / "atlas-exact.csv";
  const std::string header = exact_csv_header();
  if (!fs::exists(csv)) {
    std::ofstream out(csv);
    out << header << "\n";
    if (!out) throw std::runtime_error("cannot write " + csv.string());
  }
  const std::set<std::string> done = labels_in(csv, settings.retry_none);
  ExactAtlasResult result;
  std::vector<std::size_t> to_run;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& row = rows[i];
    if (!settings.n_values.empty() && std::find(settings.n_values.begin(), settings.n_values.end(),
                                                row.n()) == settings.n_values.end())
      continue;
    order.push_back(row.label);
    ++result.rows;
    if (done.count(row.label))
      ++result.skipped;
    else
      to_run.push_back(i);
  }
  // Largest n first: the slowest start early.
  std::stable_sort(to_run.begin(), to_run.end(),
                   [&](std::size_t a, std::size_t b) { return rows[a].n() > rows[b].n(); });
  std::vector<pipeline::ExactResult> found(rows.size());
  std::ofstream table(csv, std::ios::app);
  ProgressCounter counter("exact", static_cast<long long>(to_run.size()));
  JobItems items;
  items.count = rows.size();
  items.order = to_run;
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
    table << exact_csv_row(r) << "\n" << std::flush;
    if (!table) throw std::runtime_error("cannot append to " + csv.string());
    result.done.push_back(r);
    if (progress)
      progress(counter.finished(fmt::format(
          "{} (n = {}): {}{}", r.label, r.n, r.proof,
          r.polynomial.found ? fmt::format(", degree {}", r.polynomial.polynomial.degree()) : "")));
  };
  result.cancelled = ThreadExecutor(settings.threads).run_items(items, cancel).cancelled;
  table.close();
  sort_table(csv, order, header);
  result.seconds = seconds_since(start);
  return result;
}

pipeline::ExactRun run_exact(const Catalogue& catalogue, const ExactRequest& request) {
  if (request.files.empty() == request.class_id.empty())
    throw std::invalid_argument("exact needs packing files or --class C --k A..B, not both");
  const fs::path dir =
      request.certificates.empty() ? fs::path() : writable_directory(request.certificates);
  // Class members as built (polished, not certified: exact_of_packing analyses them itself).
  std::vector<std::pair<std::string, Packing>> members;
  if (!request.class_id.empty()) {
    if (request.k.second < request.k.first)
      throw std::invalid_argument("exact --class needs --k A..B");
    pipeline::BuildSettings build;
    build.certify = false;
    for (long long k = request.k.first; k <= request.k.second; ++k) {
      const auto built = pipeline::build_and_certify(
          catalogue, {request.class_id, static_cast<long>(k), request.p, ""}, build);
      members.emplace_back(pipeline::member_name(built.pattern.provenance),
                           built.record.pattern.packing);
    }
  }
  pipeline::ExactRun run;
  const bool from_files = !request.files.empty();
  const std::size_t count = from_files ? request.files.size() : members.size();
  for (std::size_t i = 0; i < count; ++i) {
    run.packings.push_back(
        from_files
            ? pipeline::exact_of_file(request.files[i], request.exact)
            : pipeline::exact_of_packing(members[i].second, members[i].first, {}, request.exact));
    const auto& r = run.packings.back();
    if (dir.empty() || !r.configuration || !r.configuration->proven) continue;
    // A class member's name ("four-delta k=3") as a label the checker accepts: "four-delta_k3".
    std::string label;
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
