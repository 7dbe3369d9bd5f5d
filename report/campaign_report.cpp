// Renderers of `tripack campaign` and the `tripack db` commands (conventions in render.hpp).
#include "report/campaign_report.hpp"

#include <fmt/format.h>

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <ostream>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "report/fields.hpp"
#include "report/render.hpp"

namespace tripack::report {

using nlohmann::json;

namespace {

// As json.cpp: invalid UTF-8 (a file name) is replaced, never thrown.
void emit(std::ostream& out, const json& j) {
  out << j.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
}

template <class Int>
std::string integer(Int v) {
  return std::to_string(v);
}

std::string flag(bool b) {
  return b ? "true" : "false";
}

std::string first_seed_text(const PackingRecord& p) {
  return p.has_seed() ? std::to_string(p.first_seed()) : "-";
}

// The database's origin of a packing: "import" (a file) or "campaign" (a run found it first).
std::string origin_of(const PackingRecord& p) {
  return p.origin() == "import" ? "import" : "campaign";
}

// The imported file's name ("" for a campaign's packing).
std::string import_name(const PackingRecord& p) {
  for (const auto& s : p.sources)
    if (s.kind == PackingSource::Kind::Import) return s.name;
  return "";
}

// "campaign" or "file NAME".
std::string source_text(const PackingRecord& p) {
  return origin_of(p) == "import" ? "file " + import_name(p) : origin_of(p);
}

// ----- the best-packing table (db best, campaign) --------------------------------------------

json ranked_json(const PackingRecord& p, const RenderOptions& o) {
  const long double L = 1 / p.d.value();
  json j{{"n", p.n()},
         {"rank", p.rank},
         {"label", p.label},
         {"d", p.d.str(kLongDoubleDigits)},
         {"L", decimal17(L)},
         {"delta", static_cast<double>(oler_delta(p.n(), L))},
         {"bonds", p.bonds()},
         {"rattlers", p.rattlers()},
         {"rattler_indices", p.pattern.rattlers},
         {"certified", p.certified},
         {"runs", p.runs()},
         {"first_seed", p.has_seed() ? json(p.first_seed()) : json(nullptr)},
         {"origin", origin_of(p)},
         {"source", import_name(p).empty() ? json(nullptr) : json(import_name(p))},
         {"graph_hash", p.graph_hash}};
  if (o.points) {
    json points = json::array();
    for (const auto& q : p.pattern.packing.points)
      points.push_back({format_significant(q.x, kLongDoubleRoundTripDigits),
                        format_significant(q.y, kLongDoubleRoundTripDigits)});
    j["points"] = std::move(points);
  }
  return j;
}

json best_json(const jobs::BestTable& t, const RenderOptions& o) {
  json rows = json::array();
  for (const auto& r : t.rows) rows.push_back(ranked_json(r, o));
  return rows;
}

// One line per n: n, d with every stored digit, the label, the runs that ended in it, its first
// seed ("-" for an import no run has found) and where it came from.
void best_text(std::ostream& out, const jobs::BestTable& t) {
  out << fmt::format("{:>6}  {:<22} {:<8} {:>5} {:>10}  {}\n", "n", "d", "label", "runs",
                     "first seed", "source");
  for (const auto& p : t.rows)
    out << fmt::format("{:>6}  {:<22} {:<8} {:>5} {:>10}  {}\n", p.n(), p.d.str(kLongDoubleDigits),
                       p.label, p.runs(), first_seed_text(p), source_text(p));
}

void best_csv(std::ostream& out, const jobs::BestTable& t) {
  csv_row(out, {"n", "rank", "label", "d", "bonds", "rattlers", "certified", "runs", "first_seed",
                "origin", "source", "graph_hash"});
  for (const auto& p : t.rows)
    csv_row(out, {integer(p.n()), integer(p.rank), p.label, p.d.str(kLongDoubleDigits),
                  integer(p.bonds()), integer(p.rattlers()), flag(p.certified), integer(p.runs()),
                  p.has_seed() ? integer(p.first_seed()) : "", origin_of(p), import_name(p),
                  p.graph_hash});
}

}  // namespace

// ----- tripack campaign -----------------------------------------------------------------------

void render_text(std::ostream& out, const CampaignReport& r, const RenderOptions&) {
  const auto& x = r.result;
  out << fmt::format(
      "campaign {}..{} x {} runs: {} units, {} already in {}, {} recorded now ({} certified, {} "
      "errors){}, {:.1f} s\n",
      r.n_first, r.n_last, r.runs, x.units, x.skipped, r.db, x.recorded, x.certified, x.errors,
      x.cancelled ? ", interrupted (rerun to continue)" : "", x.seconds);
  best_text(out, r.best);
}

void render_json(std::ostream& out, const CampaignReport& r, const RenderOptions& o) {
  const auto& x = r.result;
  emit(out, {{"n_first", r.n_first},
             {"n_last", r.n_last},
             {"runs_per_n", r.runs},
             {"db", r.db},
             {"units", x.units},
             {"skipped", x.skipped},
             {"recorded", x.recorded},
             {"certified", x.certified},
             {"errors", x.errors},
             {"cancelled", x.cancelled},
             {"best", best_json(r.best, o)},
             {"seconds", x.seconds}});
}

void render_csv(std::ostream& out, const CampaignReport& r, const RenderOptions&) {
  best_csv(out, r.best);
}

// ----- tripack db best ------------------------------------------------------------------------

void render_text(std::ostream& out, const jobs::BestTable& t, const RenderOptions&) {
  best_text(out, t);
}

void render_json(std::ostream& out, const jobs::BestTable& t, const RenderOptions& o) {
  emit(out, {{"db", t.db}, {"best", best_json(t, o)}, {"seconds", t.seconds}});
}

void render_csv(std::ostream& out, const jobs::BestTable& t, const RenderOptions&) {
  best_csv(out, t);
}

// ----- tripack db check -----------------------------------------------------------------------

void render_text(std::ostream& out, const jobs::DbCheck& c, const RenderOptions&) {
  const auto& s = c.stats;
  out << (s.integrity == "ok" ? std::string("integrity ok") : "integrity FAILED: " + s.integrity)
      << "\n";
  out << fmt::format("runs: {}\nn values: {}\npackings: {} ({} imported)\n", s.runs, s.n_values,
                     s.packings, s.imported);
  out << fmt::format(
      "duplicates: {} ({} runs with a repeated (n, seed), {} packings with a "
      "repeated (n, contact graph, d to 12 digits))\n",
      c.duplicates(), s.duplicate_runs, s.duplicate_packings);
}

void render_json(std::ostream& out, const jobs::DbCheck& c, const RenderOptions&) {
  const auto& s = c.stats;
  emit(out, {{"db", c.db},
             {"schema_version", c.schema_version},
             {"integrity", s.integrity},
             {"runs", s.runs},
             {"n_values", s.n_values},
             {"packings", s.packings},
             {"imported", s.imported},
             {"duplicates", c.duplicates()},
             {"duplicate_runs", s.duplicate_runs},
             {"duplicate_packings", s.duplicate_packings},
             {"seconds", c.seconds}});
}

void render_csv(std::ostream& out, const jobs::DbCheck& c, const RenderOptions&) {
  const auto& s = c.stats;
  csv_row(out, {"db", "integrity", "runs", "n_values", "packings", "imported", "duplicates",
                "duplicate_runs", "duplicate_packings"});
  csv_row(out, {c.db, s.integrity, integer(s.runs), integer(s.n_values), integer(s.packings),
                integer(s.imported), integer(c.duplicates()), integer(s.duplicate_runs),
                integer(s.duplicate_packings)});
}

// ----- tripack db import ----------------------------------------------------------------------

void render_text(std::ostream& out, const jobs::ImportResult& r, const RenderOptions&) {
  for (const auto& x : r.packings)
    out << fmt::format("{}: n = {}, d = {} ({} as read), {} bonds, {} rattlers, certified; {} {}\n",
                       x.file, x.n, x.d, x.d_file, x.bonds, x.rattlers.size(),
                       x.added ? "stored as" : "already stored (nothing changed) as", x.label);
  out << fmt::format("{} file{} into {}: {} stored, {} already there, {:.1f} s\n",
                     r.packings.size(), r.packings.size() == 1 ? "" : "s", r.db, r.added, r.already,
                     r.seconds);
}

void render_json(std::ostream& out, const jobs::ImportResult& r, const RenderOptions&) {
  json files = json::array();
  for (const auto& x : r.packings)
    files.push_back({{"file", x.file},
                     {"source", x.source},
                     {"layout", x.layout},
                     {"convention", std::string(convention_name(x.convention))},
                     {"n", x.n},
                     {"d", x.d},
                     {"d_file", x.d_file},
                     {"bonds", x.bonds},
                     {"rattlers", x.rattlers.size()},
                     {"rattler_indices", x.rattlers},
                     {"certified", true},
                     {"verdict", x.verdict},
                     {"graph_hash", x.graph_hash},
                     {"stored", x.added},
                     {"label", x.label},
                     {"warnings", x.warnings},
                     {"seconds", x.seconds}});
  emit(out, {{"db", r.db},
             {"files", std::move(files)},
             {"stored", r.added},
             {"already", r.already},
             {"seconds", r.seconds}});
}

void render_csv(std::ostream& out, const jobs::ImportResult& r, const RenderOptions&) {
  csv_row(out, {"file", "n", "d", "d_file", "bonds", "rattlers", "stored", "label", "graph_hash"});
  for (const auto& x : r.packings)
    csv_row(out, {x.file, integer(x.n), x.d, x.d_file, integer(x.bonds), integer(x.rattlers.size()),
                  flag(x.added), x.label, x.graph_hash});
}

// ----- tripack db prune -----------------------------------------------------------------------

void render_text(std::ostream& out, const jobs::PruneResult& r, const RenderOptions&) {
  out << fmt::format(
      "{}: kept {} packings (at most {} per n over {} values of n), removed {}; {:.1f} MB -> "
      "{:.1f} MB{}; {:.1f} s\n",
      r.db, r.kept, r.keep, r.n_values, r.removed, static_cast<double>(r.bytes_before) / 1e6,
      static_cast<double>(r.bytes_after) / 1e6,
      r.not_compacted.empty() ? "" : " (not compacted: " + r.not_compacted + ")", r.seconds);
}

void render_json(std::ostream& out, const jobs::PruneResult& r, const RenderOptions&) {
  emit(out, {{"db", r.db},
             {"keep", r.keep},
             {"n_values", r.n_values},
             {"kept", r.kept},
             {"removed", r.removed},
             {"bytes_before", r.bytes_before},
             {"bytes_after", r.bytes_after},
             {"not_compacted", r.not_compacted},
             {"seconds", r.seconds}});
}

void render_csv(std::ostream& out, const jobs::PruneResult& r, const RenderOptions&) {
  csv_row(out, {"db", "keep", "n_values", "kept", "removed", "bytes_before", "bytes_after"});
  csv_row(out, {r.db, integer(r.keep), integer(r.n_values), integer(r.kept), integer(r.removed),
                integer(static_cast<long long>(r.bytes_before)),
                integer(static_cast<long long>(r.bytes_after))});
}

}  // namespace tripack::report
