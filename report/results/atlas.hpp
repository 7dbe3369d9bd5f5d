// The atlas (`tripack atlas`): a row per packing, the builders below the best, the errors.
#pragma once

#include "jobs/atlas.hpp"
#include "jobs/atlas_files.hpp"
#include "report/results/common.hpp"

namespace tripack::report::results {

inline Tree row_tree(const PackingRecord& r, const jobs::AtlasResult& a) {
  const auto provenance = a.provenance.find(r.label);
  return {{"n", r.n()},
          {"rank", r.rank},
          {"label", r.label},
          {"d", r.d.str()},
          {"L", r.L.str()},
          {"delta", jobs::atlas_delta(r)},
          {"bonds", r.pattern.bonds.size()},
          {"rattlers", r.pattern.rattlers.size()},
          {"rattler_indices", r.pattern.rattlers},
          {"certified", r.certified},
          {"verdict", r.verdict},
          {"source", r.source_text()},
          {"runs", r.runs()},
          {"confirmations", r.confirmations()},
          {"provenance", provenance == a.provenance.end() ? "" : provenance->second},
          {"file", r.file}};
}

}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<jobs::AtlasResult> {
  static Description describe(const jobs::AtlasResult& a, const DescribeOptions&) {
    using namespace results;
    Tree rows = Tree::array(), builders = Tree::array();
    for (const auto& r : a.rows) rows.push_back(row_tree(r, a));
    for (const auto& b : a.builders)
      builders.push_back({{"n", b.n},
                          {"member", b.member},
                          {"d", b.d},
                          {"certified", b.certified},
                          {"verdict", b.verdict},
                          {"label", b.label},
                          {"rank", b.rank}});
    Tree j{{"n_first", a.settings.n_first},
           {"n_last", a.settings.n_last},
           {"db", a.db},
           {"digits", a.settings.digits},
           {"rows", rows},
           {"builders", builders},
           {"missing", a.missing},
           {"errors", a.errors},
           {"cancelled", a.cancelled},
           {"seconds", a.seconds}};
    return {j,
            "rows",
            {"n_first", "n_last", "db", "digits", "rows", "builders", "missing", "errors",
             "cancelled", "seconds"}};
  }

  static void text(std::ostream& out, const jobs::AtlasResult& a) {
    using namespace results;
    out << fmt::format("{:>5}  {:<12} {:<34} {:>6} {:>5} {:>6}  {}\n", "n", "label", "d", "bonds",
                       "ratt.", "conf.", "source");
    for (const auto& r : a.rows)
      if (r.rank == 1)
        out << fmt::format("{:>5}  {:<12} {:<34} {:>6} {:>5} {:>6}  {}\n", r.n(), r.label,
                           r.d.str(), r.bonds(), r.rattlers(), r.confirmations(), r.source_text());
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
        a.missing.size(), a.errors.size(), a.cancelled ? " (interrupted)" : "", a.seconds);
  }
};

}  // namespace tripack::report
