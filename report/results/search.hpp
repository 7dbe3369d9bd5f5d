// A basin-hopping search (`tripack search`): the best packing, the distinct packings by rank,
// the chains.
#pragma once

#include "report/results/common.hpp"
#include "search/search.hpp"

namespace tripack::report {

template <>
struct View<search::SearchResult> {
  static Description describe(const search::SearchResult& r, const DescribeOptions& o) {
    using namespace results;
    Tree j;
    j["n"] = r.request.n;
    j["method"] = method_name(r.request.method);
    j["seconds"] = r.seconds;
    j["budget_seconds"] = r.request.seconds;
    j["budget_steps"] = r.request.steps;
    j["seed"] = r.request.seed;
    j["threads"] = r.request.threads;
    j["steps"] = r.steps();
    j["cancelled"] = r.cancelled;
    j["target"] = r.request.target ? Tree(decimal17(*r.request.target)) : Tree(nullptr);
    if (r.builder)
      j["builder"] = {
          {"member", r.builder->member.empty() ? Tree(nullptr) : Tree(r.builder->member)},
          {"d", r.builder->d.empty() ? Tree(nullptr) : Tree(r.builder->d)},
          {"certified", r.builder->certified},
          {"candidates", r.builder->candidates},
          {"seconds", r.builder->seconds},
          {"cpu_seconds", r.builder->cpu_seconds},
          {"error", r.builder->error.empty() ? Tree(nullptr) : Tree(r.builder->error)}};
    else
      j["builder"] = nullptr;
    Tree packings = Tree::array();
    for (const auto& x : r.packings) {
      Tree p{{"rank", x.rank},
             {"label", x.label},
             {"d", x.d.str(kLongDoubleDigits)},
             {"L", x.L.str(kLongDoubleDigits)},
             {"delta", static_cast<double>(oler_delta(r.request.n, 1 / x.pattern.packing.d))},
             {"certified", x.certified},
             {"chains", x.runs()},
             {"first_seed", x.first_seed()}};
      add_counts(p, x.pattern);
      if (o.points) p["points"] = points_tree(x.pattern.packing);
      packings.push_back(p);
    }
    if (r.packings.empty()) {
      j["best"] = nullptr;
    } else {
      j["best"] = packings.front();
      j["best"]["seconds_to_best"] = r.seconds_to_best;
      j["best"]["cpu_seconds_to_best"] = r.cpu_seconds_to_best;
    }
    j["packings"] = packings;
    Tree chains = Tree::array();
    for (const auto& c : r.chains)
      chains.push_back(
          {{"seed", c.seed},
           {"steps", c.steps},
           {"analyses", c.analyses},
           {"analysis_cpu_seconds", c.analysis_cpu_seconds},
           {"seconds", c.seconds},
           {"cpu_seconds", c.cpu_seconds},
           {"best_d", c.best_d.empty() ? Tree(nullptr) : Tree(c.best_d)},
           {"seconds_to_best", c.seconds_to_best},
           {"cpu_seconds_to_best", c.cpu_seconds_to_best},
           {"target_reached", c.target_reached},
           {"cpu_seconds_to_target",
            c.target_reached ? Tree(c.cpu_seconds_to_target) : Tree(nullptr)},
           {"base",
            c.base_n == 0
                ? Tree(nullptr)
                : Tree{{"n", c.base_n},
                       {"steps", c.base_steps},
                       {"best_d", c.base_best_d.empty() ? Tree(nullptr) : Tree(c.base_best_d)}}}});
    j["chains"] = chains;
    return {Tree(j),
            "packings",
            {"n", "method", "seconds", "budget_seconds", "budget_steps", "seed", "threads", "steps",
             "cancelled", "target", "builder", "best", "packings", "chains"}};
  }

  static void text(std::ostream& out, const search::SearchResult& r) {
    using namespace results;
    out << fmt::format("search n = {} ({}, seed {}, {} chain{}): {} steps in {:.2f} s{}\n",
                       r.request.n, method_name(r.request.method), r.request.seed,
                       r.request.threads, r.request.threads == 1 ? "" : "s", r.steps(), r.seconds,
                       r.cancelled ? " (interrupted)" : "");
    if (r.builder)
      out << (r.builder->member.empty()
                  ? fmt::format("started from no builder: {}\n", r.builder->error)
                  : fmt::format("started from {} (d = {}, {}; {} candidate{}) built in {:.2f} s "
                                "({:.2f} CPU s)\n",
                                r.builder->member, r.builder->d,
                                r.builder->certified ? "certified" : "NOT certified",
                                r.builder->candidates, r.builder->candidates == 1 ? "" : "s",
                                r.builder->seconds, r.builder->cpu_seconds));
    if (r.packings.empty()) {
      out << "no certified packing found\n";
      return;
    }
    const auto& best = r.packings.front();
    out << fmt::format(
        "best: {} d = {}  bonds {}  rattlers {}  {}; first reached after {:.3f} s "
        "({:.3f} CPU s)\n",
        best.label, best.d.str(kLongDoubleDigits), best.bonds(), best.rattlers(),
        best.certified ? "certified" : "NOT certified", r.seconds_to_best, r.cpu_seconds_to_best);
    if (r.request.target)
      for (const auto& c : r.chains)
        out << fmt::format(
            "chain {}: target {} {}\n", c.seed, format_significant(*r.request.target, 18),
            c.target_reached ? fmt::format("reached after {:.3f} CPU s", c.cpu_seconds_to_target)
                             : "not reached");
    for (const auto& c : r.chains)
      if (c.base_n > 0)
        out << fmt::format(
            "chain {}: {} of its {} steps searched n = {} (best d = {}) to inflate\n", c.seed,
            c.base_steps, c.steps, c.base_n, c.base_best_d.empty() ? "none" : c.base_best_d);
    out << fmt::format("distinct packings ({}):\n", r.packings.size());
    packing_rows(out, r.packings, [&](const PackingRecord& x) {
      return fmt::format("({} of {} chains)", x.runs(), r.chains.size());
    });
  }
};

}  // namespace tripack::report
