// The campaign's and the database commands' results: `tripack campaign` (the run's counts and the
// best of every n in its range), `db best`, `db check`, `db import`, `db prune`. `db export`
// writes packing files (formats/formats.hpp), not a result.
#pragma once

#include <iosfwd>
#include <string>

#include "jobs/campaign.hpp"
#include "jobs/import.hpp"
#include "jobs/stored.hpp"
#include "report/results/common.hpp"

namespace tripack::report {

// What `tripack campaign` prints: the request's range and the run's result, with the database's
// best packing of every n in the range, labelled (jobs::best_table).
struct CampaignReport {
  long long n_first = 0, n_last = 0;
  int runs = 0;  // seeds per n
  std::string db;
  jobs::CampaignResult result;
  jobs::BestTable best;
};

namespace results {

inline std::string first_seed_text(const PackingRecord& p) {
  return p.has_seed() ? std::to_string(p.first_seed()) : "-";
}

// The database's origin of a packing: "import" (a file) or "campaign" (a run found it first).
inline std::string origin_of(const PackingRecord& p) {
  return p.origin() == "import" ? "import" : "campaign";
}

// The imported file's name ("" for a campaign's packing).
inline std::string import_name(const PackingRecord& p) {
  for (const auto& s : p.sources)
    if (s.kind == PackingSource::Kind::Import) return s.name;
  return "";
}

// "campaign" or "file NAME".
inline std::string source_text(const PackingRecord& p) {
  return origin_of(p) == "import" ? "file " + import_name(p) : origin_of(p);
}

// ----- the best-packing table (db best, campaign) --------------------------------------------

inline Tree ranked_tree(const PackingRecord& p, const DescribeOptions& o) {
  const long double L = 1 / p.d.value();
  Tree j{{"n", p.n()},
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
         {"first_seed", p.has_seed() ? Tree(p.first_seed()) : Tree(nullptr)},
         {"origin", origin_of(p)},
         {"source", import_name(p).empty() ? Tree(nullptr) : Tree(import_name(p))},
         {"graph_hash", p.graph_hash}};
  if (o.points) {
    Tree points = Tree::array();
    for (const auto& q : p.pattern.packing.points)
      points.push_back({format_significant(q.x, kLongDoubleRoundTripDigits),
                        format_significant(q.y, kLongDoubleRoundTripDigits)});
    j["points"] = std::move(points);
  }
  return j;
}

inline Tree best_tree(const jobs::BestTable& t, const DescribeOptions& o) {
  Tree rows = Tree::array();
  for (const auto& r : t.rows) rows.push_back(ranked_tree(r, o));
  return rows;
}

// One line per n: n, d with every stored digit, the label, the runs that ended in it, its first
// seed ("-" for an import no run has found) and where it came from.
inline void best_text(std::ostream& out, const jobs::BestTable& t) {
  out << fmt::format("{:>6}  {:<22} {:<8} {:>5} {:>10}  {}\n", "n", "d", "label", "runs",
                     "first seed", "source");
  for (const auto& p : t.rows)
    out << fmt::format("{:>6}  {:<22} {:<8} {:>5} {:>10}  {}\n", p.n(), p.d.str(kLongDoubleDigits),
                       p.label, p.runs(), first_seed_text(p), source_text(p));
}

}  // namespace results

template <>
struct View<CampaignReport> {
  static Description describe(const CampaignReport& r, const DescribeOptions& o) {
    using namespace results;
    const auto& x = r.result;
    return {Tree({{"n_first", r.n_first},
                  {"n_last", r.n_last},
                  {"runs_per_n", r.runs},
                  {"db", r.db},
                  {"units", x.units},
                  {"skipped", x.skipped},
                  {"recorded", x.recorded},
                  {"certified", x.certified},
                  {"errors", x.errors},
                  {"cancelled", x.cancelled},
                  {"best", best_tree(r.best, o)},
                  {"seconds", x.seconds}}),
            "best",
            {"n_first", "n_last", "runs_per_n", "db", "units", "skipped", "recorded", "certified",
             "errors", "cancelled", "best", "seconds"}};
  }

  static void text(std::ostream& out, const CampaignReport& r) {
    using namespace results;
    const auto& x = r.result;
    out << fmt::format(
        "campaign {}..{} x {} runs: {} units, {} already in {}, {} recorded now ({} certified, {} "
        "errors){}, {:.1f} s\n",
        r.n_first, r.n_last, r.runs, x.units, x.skipped, r.db, x.recorded, x.certified, x.errors,
        x.cancelled ? ", interrupted (rerun to continue)" : "", x.seconds);
    best_text(out, r.best);
  }
};

template <>
struct View<jobs::BestTable> {
  static Description describe(const jobs::BestTable& t, const DescribeOptions& o) {
    using namespace results;
    return {Tree({{"db", t.db}, {"best", best_tree(t, o)}, {"seconds", t.seconds}}),
            "best",
            {"db", "best", "seconds"}};
  }

  static void text(std::ostream& out, const jobs::BestTable& t) {
    using namespace results;
    best_text(out, t);
  }
};

template <>
struct View<jobs::DbCheck> {
  static Description describe(const jobs::DbCheck& c, const DescribeOptions&) {
    using namespace results;
    const auto& s = c.stats;
    return {Tree({{"db", c.db},
                  {"schema_version", c.schema_version},
                  {"integrity", s.integrity},
                  {"runs", s.runs},
                  {"n_values", s.n_values},
                  {"packings", s.packings},
                  {"imported", s.imported},
                  {"duplicates", c.duplicates()},
                  {"duplicate_runs", s.duplicate_runs},
                  {"duplicate_packings", s.duplicate_packings},
                  {"seconds", c.seconds}}),
            "",
            {"db", "schema_version", "integrity", "runs", "n_values", "packings", "imported",
             "duplicates", "duplicate_runs", "duplicate_packings", "seconds"}};
  }

  static void text(std::ostream& out, const jobs::DbCheck& c) {
    using namespace results;
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
};

template <>
struct View<jobs::ImportResult> {
  static Description describe(const jobs::ImportResult& r, const DescribeOptions&) {
    using namespace results;
    Tree files = Tree::array();
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
    return {Tree({{"db", r.db},
                  {"files", std::move(files)},
                  {"stored", r.added},
                  {"already", r.already},
                  {"seconds", r.seconds}}),
            "files",
            {"db", "files", "stored", "already", "seconds"}};
  }

  static void text(std::ostream& out, const jobs::ImportResult& r) {
    using namespace results;
    for (const auto& x : r.packings)
      out << fmt::format(
          "{}: n = {}, d = {} ({} as read), {} bonds, {} rattlers, certified; {} {}\n", x.file, x.n,
          x.d, x.d_file, x.bonds, x.rattlers.size(),
          x.added ? "stored as" : "already stored (nothing changed) as", x.label);
    out << fmt::format("{} file{} into {}: {} stored, {} already there, {:.1f} s\n",
                       r.packings.size(), r.packings.size() == 1 ? "" : "s", r.db, r.added,
                       r.already, r.seconds);
  }
};

template <>
struct View<jobs::PruneResult> {
  static Description describe(const jobs::PruneResult& r, const DescribeOptions&) {
    using namespace results;
    return {Tree({{"db", r.db},
                  {"keep", r.keep},
                  {"n_values", r.n_values},
                  {"kept", r.kept},
                  {"removed", r.removed},
                  {"bytes_before", r.bytes_before},
                  {"bytes_after", r.bytes_after},
                  {"not_compacted", r.not_compacted},
                  {"seconds", r.seconds}}),
            "",
            {"db", "keep", "n_values", "kept", "removed", "bytes_before", "bytes_after",
             "not_compacted", "seconds"}};
  }

  static void text(std::ostream& out, const jobs::PruneResult& r) {
    using namespace results;
    out << fmt::format(
        "{}: kept {} packings (at most {} per n over {} values of n), removed {}; {:.1f} MB -> "
        "{:.1f} MB{}; {:.1f} s\n",
        r.db, r.kept, r.keep, r.n_values, r.removed, static_cast<double>(r.bytes_before) / 1e6,
        static_cast<double>(r.bytes_after) / 1e6,
        r.not_compacted.empty() ? "" : " (not compacted: " + r.not_compacted + ")", r.seconds);
  }
};

}  // namespace tripack::report
