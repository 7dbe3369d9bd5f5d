// Billiards runs (`tripack billiards`) and a builder's packing beside them (`tripack compare`).
#pragma once

#include <fmt/ranges.h>

#include "jobs/billiards_runs.hpp"
#include "jobs/compare.hpp"
#include "report/results/build.hpp"

namespace tripack::report::results {

using namespace jobs;

inline Tree billiards_tree(const BilliardsRunsResult& r, const DescribeOptions& o) {
  Tree j;
  j["n"] = r.scene.n;
  j["runs_asked"] = r.runs_asked;
  j["runs_done"] = r.runs.size();  // fewer when interrupted
  j["effects"] = describe_effects(r.scene);
  j["seconds"] = r.seconds;
  j["runs"] = Tree::array();
  for (const auto& run : r.runs) {
    Tree x{{"seed", run.seed},
           {"events", run.sim.events},
           {"collisions", run.sim.collisions},
           {"seconds", run.sim.seconds},
           {"d_billiards", decimal17(run.sim.packing.d)},
           {"stop", run.sim.stop_reason},
           {"label", run.label}};
    if (run.analysis) x.update(analysis_tree(*run.analysis));
    if (r.scene.shake)
      x["shake"] = {{"collisions", run.sim.shake_collisions},
                    {"seconds", run.sim.shake_seconds},
                    {"rattler_indices", run.sim.shake_rattlers}};
    if (!run.error.empty()) x["error"] = run.error;
    j["runs"].push_back(x);
  }
  j["packings"] = Tree::array();
  for (std::size_t i = 0; i < r.packings.size(); ++i) {
    const auto& x = r.packings[i];
    Tree p{{"rank", i + 1},
           {"label", x.label},
           {"d", decimal17(x.pattern.packing.d)},
           {"L", decimal17(1 / x.pattern.packing.d)},
           {"delta", static_cast<double>(oler_delta(r.scene.n, 1 / x.pattern.packing.d))},
           {"certified", x.certified},
           {"verdict", x.verdict},
           {"runs", x.runs()},
           {"first_seed", x.first_seed()}};
    add_counts(p, x.pattern);
    if (o.points) p["points"] = points_tree(x.pattern.packing);
    j["packings"].push_back(p);
  }
  return j;
}

inline void billiards_lines(std::ostream& out, const BilliardsRunsResult& r) {
  out << fmt::format("{:>6} {:>12} {:>12} {:>9} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n", "seed",
                     "events", "collisions", "seconds", "d (billiards)", "d (polished)", "bonds",
                     "ratt", "certified", "packing");
  for (const auto& run : r.runs) {
    if (!run.error.empty()) {
      out << fmt::format("{:>6} error: {}\n", run.seed, run.error);
      continue;
    }
    const auto* a = run.analysis ? &*run.analysis : nullptr;
    out << fmt::format("{:>6} {:>12} {:>12} {:>9.3f} {:>20} {:>20} {:>6} {:>4} {:>9} {}\n",
                       run.seed, run.sim.events, run.sim.collisions, run.sim.seconds,
                       format_significant(run.sim.packing.d, 15),
                       a ? format_significant(a->pattern.packing.d, 15) : "-",
                       a ? std::to_string(a->pattern.bonds.size()) : "-",
                       a ? std::to_string(a->pattern.rattlers.size()) : "-",
                       a ? (a->certified() ? "yes" : "no") : "-", run.label);
  }
  if (const auto effects = describe_effects(r.scene); !effects.empty())
    out << fmt::format("effects: {}\n", fmt::join(effects, "; "));
  if (r.scene.shake) {
    out << fmt::format(
        "shaking at fixed size ({} collisions per disk): rattlers = disks colliding {}x less "
        "often than the median\n",
        r.scene.shake->per_disk, r.scene.shake->rattler_factor);
    for (const auto& run : r.runs)
      if (run.error.empty())
        out << fmt::format(
            "{:>6} shake: {} collisions in {:.3f} s, rattlers [{}]{}\n", run.seed,
            run.sim.shake_collisions, run.sim.shake_seconds, fmt::join(run.sim.shake_rattlers, " "),
            run.analysis ? fmt::format("; analysis rattlers [{}]",
                                       fmt::join(run.analysis->pattern.rattlers, " "))
                         : "");
  }
  const std::size_t ran = r.runs.size();
  if (ran < static_cast<std::size_t>(r.runs_asked))
    out << fmt::format("distinct packings ({} of {} runs: interrupted, {:.2f} s):\n", ran,
                       r.runs_asked, r.seconds);
  else
    out << fmt::format("distinct packings ({} runs, {:.2f} s):\n", ran, r.seconds);
  packing_rows(out, r.packings, [&](const PackingRecord& x) {
    return fmt::format("({} of {} runs, first seed {})", x.runs(), ran, x.first_seed());
  });
}

}  // namespace tripack::report::results

namespace tripack::report {

template <>
struct View<jobs::BilliardsRunsResult> {
  static Description describe(const jobs::BilliardsRunsResult& r, const DescribeOptions& o) {
    using namespace results;
    return {Tree(billiards_tree(r, o)),
            "packings",
            {"n", "runs_asked", "runs_done", "effects", "seconds", "runs", "packings"}};
  }

  static void text(std::ostream& out, const jobs::BilliardsRunsResult& r) {
    using namespace results;
    billiards_lines(out, r);
  }
};

template <>
struct View<jobs::ConstructedVsBilliards> {
  static Description describe(const jobs::ConstructedVsBilliards& c, const DescribeOptions& o) {
    using namespace results;
    Tree j;
    j["n"] = c.n;
    j["seconds"] = c.seconds;
    j["constructed"] = c.constructed ? build_tree(c.constructed->best, o) : Tree(nullptr);
    j["billiards"] = billiards_tree(c.billiards, o);
    if (c.comparison) {
      const auto& best = c.billiards.packings.front();
      j["comparison"] = {
          {"billiards_label", best.label},
          {"d_relative_difference", static_cast<double>(c.d_relative_difference)},
          {"same_packing", c.comparison->same},
          {"same_d", c.comparison->same_d},
          {"same_contact_graph", c.comparison->isomorphic},
          {"symmetry", c.comparison->symmetry
                           ? Tree(std::string(symmetry_name(*c.comparison->symmetry)))
                           : Tree(nullptr)},
          {"reason", c.comparison->reason}};
    } else {
      j["comparison"] = nullptr;
    }
    return {Tree(j), "", {"n", "seconds", "constructed", "billiards", "comparison"}};
  }

  static void text(std::ostream& out, const jobs::ConstructedVsBilliards& c) {
    using namespace results;
    billiards_lines(out, c.billiards);
    if (c.constructed) {
      out << "constructed:\n";
      build_lines(out, c.constructed->best);
    } else {
      out << fmt::format("constructed: no class of the catalogue contains n = {}\n", c.n);
    }
    if (!c.comparison) {
      out << "comparison: -\n";
      return;
    }
    const auto& best = c.billiards.packings.front();
    line(out, "compare",
         fmt::format("{} vs {}: d relative difference {:.3g}; {}", best.label,
                     member_name(c.constructed->best.pattern.provenance),
                     static_cast<double>(c.d_relative_difference),
                     c.comparison->same ? "the same packing (" + c.comparison->reason + ")"
                                        : "different: " + c.comparison->reason));
  }
};

}  // namespace tripack::report
