// The atlas files and the `tripack atlas` renderers (conventions in render.hpp).
#include "report/atlas_report.hpp"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/io.hpp"
#include "report/fields.hpp"
#include "report/render.hpp"

namespace tripack::report {

using nlohmann::json;

namespace {

const std::vector<std::string> kColumns{"n",     "rank",     "label",     "d",      "L",   "delta",
                                        "bonds", "rattlers", "certified", "source", "file"};

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += csv_field(fields[i]);
  }
  return line + "\n";
}

std::vector<std::string> fields_of(const campaign::AtlasRow& r) {
  return {std::to_string(r.n),
          std::to_string(r.rank),
          r.label,
          r.d,
          r.L,
          r.delta,
          std::to_string(r.pattern.bonds.size()),
          std::to_string(r.pattern.rattlers.size()),
          r.certified ? "true" : "false",
          r.source,
          r.file};
}

// RFC 4180 fields of one line (no line breaks inside fields: the atlas writes none).
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

json row_json(const campaign::AtlasRow& r) {
  return {{"n", r.n},
          {"rank", r.rank},
          {"label", r.label},
          {"d", r.d},
          {"L", r.L},
          {"delta", r.delta},
          {"bonds", r.pattern.bonds.size()},
          {"rattlers", r.pattern.rattlers.size()},
          {"rattler_indices", r.pattern.rattlers},
          {"certified", r.certified},
          {"verdict", r.verdict},
          {"source", r.source},
          {"runs", r.runs},
          {"file", r.file}};
}

}  // namespace

void write_atlas(const campaign::AtlasResult& atlas, const std::filesystem::path& dir) {
  const auto files = dir / "atlas";
  std::filesystem::create_directories(files);
  std::set<std::string> written;
  for (const auto& row : atlas.rows) {
    WriteOptions options;
    options.label = row.label;
    options.exact_d = row.d;
    options.exact_points = &row.points;
    options.comments = {
        "rank: " + std::to_string(row.rank), "L: " + row.L, "delta: " + row.delta,
        "source: " + row.source,
        std::string("certified: ") + (row.certified ? "yes" : "no") + " (" + row.verdict + ")"};
    if (!row.pattern.rattlers.empty())
      options.comments.push_back(
          "the rattlers' places (free in their cages) are the analysis' long double ones");
    std::ostringstream text;
    write_text(text, row.pattern, options);
    write_file(dir / row.file, text.str());
    written.insert((dir / row.file).filename().string());
  }
  // A rerun over the same range replaces the table: files of rows that left it go too.
  for (const auto& entry : std::filesystem::directory_iterator(files))
    if (entry.path().extension() == ".txt" && !written.count(entry.path().filename().string()))
      std::filesystem::remove(entry.path());
  std::string table = csv_line(kColumns);
  for (const auto& row : atlas.rows) table += csv_line(fields_of(row));
  write_file(dir / "atlas.csv", table);
}

std::vector<AtlasEntry> read_atlas(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  if (!in) throw std::runtime_error("cannot read the atlas " + csv.string());
  std::string line;
  std::vector<AtlasEntry> entries;
  long long number = 0;
  auto fail = [&](const std::string& why) {
    throw std::runtime_error(fmt::format("{}:{}: {}", csv.string(), number, why));
  };
  while (std::getline(in, line)) {
    ++number;
    const auto f = split_csv(line);
    if (number == 1) {
      if (f != kColumns) fail("not an atlas table (its header is not " + csv_line(kColumns) + ")");
      continue;
    }
    if (line.empty()) continue;
    if (f.size() != kColumns.size())
      fail(fmt::format("{} fields, expected {}", f.size(), kColumns.size()));
    AtlasEntry e;
    try {
      e.n = std::stoll(f[0]);
      e.rank = std::stoll(f[1]);
      e.bonds = std::stoll(f[6]);
      e.rattlers = std::stoll(f[7]);
      (void)std::stold(f[3]);
      (void)std::stold(f[4]);
      (void)std::stold(f[5]);
    } catch (const std::exception&) {
      fail("a number field is not a number");
    }
    e.label = f[2];
    e.d = f[3];
    e.L = f[4];
    e.delta = f[5];
    e.certified = f[8] == "true";
    e.source = f[9];
    e.file = f[10];
    entries.push_back(std::move(e));
  }
  if (number == 0) fail("empty file");
  return entries;
}

void render_text(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions&) {
  out << fmt::format("{:>5}  {:<12} {:<34} {:>6} {:>5}  {}\n", "n", "label", "d", "bonds", "ratt.",
                     "source");
  for (const auto& r : a.rows)
    if (r.rank == 1)
      out << fmt::format("{:>5}  {:<12} {:<34} {:>6} {:>5}  {}\n", r.n, r.label, r.d,
                         r.pattern.bonds.size(), r.pattern.rattlers.size(), r.source);
  for (const auto& b : a.builders)
    if (b.rank != 1)
      out << fmt::format("builder {} (n = {}): d = {}, {}\n", b.member, b.n, b.d,
                         b.certified ? fmt::format("rank {} ({})", b.rank, b.label)
                                     : "not certified: " + b.verdict);
  for (const auto& n : a.missing) out << fmt::format("n = {}: no certified packing\n", n);
  for (const auto& e : a.errors) out << "error: " << e << "\n";
  out << fmt::format(
      "atlas {}..{} from {}: {} rows, {} builders, {} without a packing, {} "
      "errors{}; {:.1f} s\n",
      a.settings.n_first, a.settings.n_last, a.db, a.rows.size(), a.builders.size(),
      a.missing.size(), a.errors.size(), a.interrupted ? " (interrupted)" : "", a.seconds);
}

void render_json(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions&) {
  json rows = json::array(), builders = json::array();
  for (const auto& r : a.rows) rows.push_back(row_json(r));
  for (const auto& b : a.builders)
    builders.push_back({{"n", b.n},
                        {"member", b.member},
                        {"d", b.d},
                        {"certified", b.certified},
                        {"verdict", b.verdict},
                        {"label", b.label},
                        {"rank", b.rank}});
  json j{{"n_first", a.settings.n_first},
         {"n_last", a.settings.n_last},
         {"db", a.db},
         {"digits", a.settings.digits},
         {"rows", rows},
         {"builders", builders},
         {"missing", a.missing},
         {"errors", a.errors},
         {"interrupted", a.interrupted},
         {"seconds", a.seconds}};
  out << j.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
}

void render_csv(std::ostream& out, const campaign::AtlasResult& a, const RenderOptions&) {
  out << csv_line(kColumns);
  for (const auto& r : a.rows) out << csv_line(fields_of(r));
}

}  // namespace tripack::report
