// JSON renderers (conventions in render.hpp).
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "report/fields.hpp"
#include "report/render.hpp"

namespace tripack::report {

using nlohmann::json;
using namespace pipeline;
using namespace jobs;
using namespace search;

namespace {

// Invalid UTF-8 (a label or a file name) is replaced, never thrown: a formatting problem must not
// discard computed results.
void emit(std::ostream& out, const json& j) {
  out << j.dump(-1, ' ', false, json::error_handler_t::replace) << "\n";
}

json optional_string(const std::string& s) {
  return s.empty() ? json(nullptr) : json(s);
}

json points_json(const Packing& packing) {
  json points = json::array();
  for (const auto& p : packing.points)
    points.push_back({format_significant(p.x, 21), format_significant(p.y, 21)});
  return points;
}

// The counts and indices every packing-carrying object has.
void add_counts(json& j, const Pattern& pattern) {
  j["bonds"] = pattern.bonds.size();
  j["rattlers"] = pattern.rattlers.size();
  j["rattler_indices"] = pattern.rattlers;
}

// The multiprecision certificate's object (docs/certified.md): null when it did not run.
json precise_json(const Analysis& a) {
  if (!a.precise) return nullptr;
  const auto& p = *a.precise;
  const auto& id = p.identification;
  const auto& c = p.certificate;
  auto number = [](long double v) {
    return std::isfinite(v) ? json(static_cast<double>(v)) : json(nullptr);
  };
  return {{"certified", p.certified},
          {"reason", p.reason},
          {"declined", optional_string(p.declined)},
          {"digits", p.digits},
          {"deep_relax_steps", p.deep_relaxed ? json(p.deep_relax.iterations) : json(nullptr)},
          {"deep_relax_d", p.deep_relaxed ? json(decimal17(p.deep_relax.d_end)) : json(nullptr)},
          {"bonds", id.found ? json(id.bonds.size()) : json(nullptr)},
          {"rattlers", id.found ? json(id.rattlers.size()) : json(nullptr)},
          {"contacts", p.contacts > 0 ? json(p.contacts) : json(nullptr)},
          {"next_gap", p.contacts > 0 ? number(p.next_gap) : json(nullptr)},
          {"candidates", id.candidates},
          {"dropped", id.dropped},
          {"implied", id.implied},
          {"smallest_gap", id.found ? number(p.smallest_gap) : json(nullptr)},
          {"gap_floor", id.found ? number(p.gap_floor) : json(nullptr)},
          {"min_force", c.stress.exists ? number(c.stress.min_force) : json(nullptr)},
          {"force_error", c.stress.exists ? number(c.force_error) : json(nullptr)},
          {"balance_residual", c.stress.exists ? number(c.stress.residual) : json(nullptr)},
          {"min_eigenvalue", id.found ? number(c.min_eigenvalue) : json(nullptr)},
          {"eigenvalue_error", id.found ? number(c.eigenvalue_error) : json(nullptr)},
          {"reference_open", p.reference_open >= 0 ? json(p.reference_open) : json(nullptr)},
          {"seconds", p.seconds}};
}

json certificate_json(const Analysis& a) {
  long double smallest_gap = std::numeric_limits<long double>::infinity();
  for (const auto& g : a.gaps)
    if (!g.rattler) {
      smallest_gap = g.gap;
      break;
    }
  return {{"rigid", a.rigidity.rigid},
          {"smallest_gap",
           std::isfinite(smallest_gap) ? json(static_cast<double>(smallest_gap)) : json(nullptr)},
          {"multiprecision", precise_json(a)},
          {"stress_exists", a.stress.exists},
          {"stress_strictly_positive", a.stress.strictly_positive},
          {"min_force", static_cast<double>(a.stress.min_force)},
          {"balance_residual", static_cast<double>(a.stress.residual)},
          {"certified", a.certified()},
          {"verdict", a.status()},
          {"relax_iterations", a.relax.iterations},
          {"relax_method", a.relax.interior || a.lps_skipped ? "interior point"
                           : a.relax.fast_path               ? "start certified"
                                                             : "linear programs"},
          {"lps_skipped", a.lps_skipped},
          {"interior_d", a.interior ? json(decimal17(a.interior->d_end)) : json(nullptr)}};
}

json analysis_stage_seconds(const Analysis& a) {
  return {{"relax", a.times.relax},
          {"bonds", a.times.bonds},
          {"rigidity", a.times.rigidity},
          {"stress", a.times.stress},
          {"multiprecision", a.times.multiprecision},
          {"multiprecision_certificate", a.times.certificate_mp}};
}

json member_json(const Provenance& m) {
  return {{"class", m.class_id},
          {"k", m.k},
          {"p", m.p ? json(m.p) : json(nullptr)},
          {"variant", optional_string(m.variant)}};
}

json build_json(const BuildResult& b, const RenderOptions& o) {
  const auto& pk = b.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  const long double L = 1.0L / pk.d;
  json j = member_json(b.pattern.provenance);
  j["n"] = n;
  j["d"] = b.digits > kLongDoubleDigits ? b.d_string(b.digits) : decimal17(pk.d);
  // L to the digits of d (the MPFR polish's L); delta stays a number (a double's digits).
  j["L"] = b.digits > kLongDoubleDigits && b.record.L.multiprecision() ? b.record.L.str(b.digits)
                                                                       : decimal17(L);
  j["delta"] = static_cast<double>(oler_delta(n, L));
  add_counts(j, b.record.pattern);  // the certified geometry's where certified (BuildResult)
  j["bonds_expected"] = b.bonds_expected ? json(*b.bonds_expected) : json(nullptr);
  j["rattlers_expected"] = b.rattlers_expected ? json(*b.rattlers_expected) : json(nullptr);
  j["seconds"] = b.seconds();
  j["stage_seconds"] = {
      {"construct", b.times.construct}, {"polish", b.polish_seconds}, {"exact", b.times.exact}};
  if (b.analysis) {
    j["stage_seconds"].update(analysis_stage_seconds(*b.analysis));
    j["certificate"] = certificate_json(*b.analysis);
    j["certificate"]["bonds_match_builder"] = b.bonds_match();
    j["certificate"]["rattlers_match_builder"] = b.rattlers_match();
  } else {
    j["stage_seconds"]["multiprecision"] = b.times.multiprecision;
    j["certificate"] = nullptr;
    j["certify_skipped"] = b.certify_skipped;
    if (!b.certify_error.empty()) j["certify_error"] = b.certify_error;
  }
  if (b.exact) j["exact_check"] = b.exact->ok;
  if (b.polished) j["polish_residual"] = static_cast<double>(b.polish.max_residual);
  if (o.points) j["points"] = points_json(pk);
  return j;
}

json analysis_json(const Analysis& a) {
  json j;
  j["d"] = decimal17(a.pattern.packing.d);
  add_counts(j, a.pattern);
  j["certificate"] = certificate_json(a);
  return j;
}

json billiards_json(const BilliardsSearchResult& r, const RenderOptions& o) {
  json j;
  j["n"] = r.scene.n;
  j["runs_asked"] = r.runs_asked;
  j["runs_done"] = r.runs.size();  // fewer when interrupted
  j["effects"] = describe_effects(r.scene);
  j["seconds"] = r.seconds;
  j["runs"] = json::array();
  for (const auto& run : r.runs) {
    json x{{"seed", run.seed},
           {"events", run.sim.events},
           {"collisions", run.sim.collisions},
           {"seconds", run.sim.seconds},
           {"d_billiards", decimal17(run.sim.packing.d)},
           {"stop", run.sim.stop_reason},
           {"label", run.label}};
    if (run.analysis) x.update(analysis_json(*run.analysis));
    if (r.scene.shake)
      x["shake"] = {{"collisions", run.sim.shake_collisions},
                    {"seconds", run.sim.shake_seconds},
                    {"rattler_indices", run.sim.shake_rattlers}};
    if (!run.error.empty()) x["error"] = run.error;
    j["runs"].push_back(x);
  }
  j["packings"] = json::array();
  for (std::size_t i = 0; i < r.packings.size(); ++i) {
    const auto& x = r.packings[i];
    json p{{"rank", i + 1},
           {"label", x.label},
           {"d", decimal17(x.pattern.packing.d)},
           {"L", decimal17(1 / x.pattern.packing.d)},
           {"delta", static_cast<double>(oler_delta(r.scene.n, 1 / x.pattern.packing.d))},
           {"certified", x.certified},
           {"verdict", x.verdict},
           {"runs", x.runs()},
           {"first_seed", x.first_seed()}};
    add_counts(p, x.pattern);
    if (o.points) p["points"] = points_json(x.pattern.packing);
    j["packings"].push_back(p);
  }
  return j;
}

}  // namespace

void render_json(std::ostream& out, const Catalogue& catalogue, const RenderOptions&) {
  json classes = json::array();
  for (const auto& c : catalogue.classes()) {
    json j{{"id", c.id},
           {"display", c.display},
           {"n", c.n.text()},
           {"k_min", c.k_min},
           {"k_max", c.k_max ? json(c.k_max) : json(nullptr)},
           {"p_min", c.has_p ? json(c.p_min) : json(nullptr)},
           {"L", c.L.empty() ? json(nullptr) : json(c.L.text())},
           {"bonds", c.bonds.empty() ? json(nullptr) : json(c.bonds.text())},
           {"rattlers", c.rattlers.empty() ? json(nullptr) : json(c.rattlers.text())},
           {"builder", c.builder}};
    json variants = json::array();
    for (const auto& v : c.variants) variants.push_back(v.id);
    j["variants"] = variants;
    j["claim"] = {{"status", c.claim_status},
                  {"best", c.claim_best},
                  {"tight", c.claim_tight},
                  {"source", c.claim_source}};
    classes.push_back(j);
  }
  emit(out, {{"classes", classes}, {"seconds", 0.0}});
}

void render_json(std::ostream& out, const Classification& c, const RenderOptions&) {
  json members = json::array();
  for (const auto& m : c.members)
    members.push_back({{"class", m.cls->id},
                       {"k", m.k},
                       {"p", m.cls->has_p ? json(m.p) : json(nullptr)},
                       {"display", m.cls->display}});
  emit(out, {{"n", c.n}, {"members", members}, {"seconds", 0.0}});
}

void render_json(std::ostream& out, const BestBuild& b, const RenderOptions& o) {
  json j = build_json(b.best, o);
  if (!b.candidates.empty()) {
    j["candidates"] = json::array();
    for (const auto& c : b.candidates) {
      json x = member_json(c.member);
      if (c.error.empty())
        x["d"] = decimal17(c.d);
      else
        x["error"] = c.error;
      j["candidates"].push_back(x);
    }
  }
  emit(out, j);
}

void render_json(std::ostream& out, const FormulaCheck& c, const RenderOptions&) {
  json rows = json::array();
  for (const auto& r : c.rows)
    rows.push_back(
        {{"class", r.class_id},
         {"k", r.k},
         {"p", r.p ? json(r.p) : json(nullptr)},
         {"variant", optional_string(r.variant)},
         {"n", r.n},
         {"d_built", decimal17(r.d_built)},
         {"d_formula", r.d_formula ? json(decimal17(*r.d_formula)) : json(nullptr)},
         {"relative_difference",
          r.d_formula ? json(static_cast<double>(r.relative_difference)) : json(nullptr)},
         {"bonds", r.bonds},
         {"bonds_expected", r.bonds_expected ? json(*r.bonds_expected) : json(nullptr)},
         {"exact_check", r.exact_ok ? json(*r.exact_ok) : json(nullptr)},
         {"source", r.source},
         {"ok", r.ok}});
  emit(out, {{"rows", rows}, {"all_ok", c.all_ok}, {"seconds", c.seconds}});
}

void render_json(std::ostream& out, const CatalogueTable& t, const RenderOptions&) {
  json rows = json::array();
  for (const auto& r : t.rows) {
    json x = member_json(r.member);
    x.update({{"n", r.n},
              {"d", decimal17(r.d)},
              {"L", decimal17(1 / r.d)},
              {"delta", static_cast<double>(oler_delta(r.n, 1 / r.d))},
              {"bonds", r.bonds},
              {"rattlers", r.rattlers},
              {"counts_match_catalogue", r.counts_match},
              {"geometry_matches_builder", r.geometry_match},
              {"certified", r.certified},
              {"exact_check", r.exact_ok ? json(*r.exact_ok) : json(nullptr)},
              {"ok", r.ok},
              {"seconds", r.seconds}});
    rows.push_back(x);
  }
  emit(out, {{"rows", rows}, {"all_ok", t.all_ok}, {"seconds", t.seconds}});
}

void render_json(std::ostream& out, const FileAnalysis& f, const RenderOptions& o) {
  const Analysis& a = f.analysis;
  const auto& pk = a.pattern.packing;
  const long long n = static_cast<long long>(pk.size());
  json j;
  j["file"] = f.file;
  j["layout"] = f.layout;
  if (!f.label.empty()) j["label"] = f.label;
  j["n"] = n;
  const int digits = std::max(f.digits, 17);
  j["d"] = f.d_string(digits);
  j["L"] = f.L_string(digits);
  j["delta"] = static_cast<double>(oler_delta(n, 1 / pk.d));
  j["convention"] = convention_name(f.convention);
  j["value_in_convention"] = f.value_string(digits);
  if (f.convention == Convention::Radius) j["r"] = f.value_string(digits);
  if (f.convention == Convention::UnitDiskSide) j["S"] = f.value_string(digits);
  j["d_start"] = decimal17(a.relax.d_start);
  add_counts(j, a.pattern);
  j["certificate"] = certificate_json(a);
  j["warnings"] = f.warnings;
  j["seconds"] = f.seconds();
  j["stage_seconds"] = analysis_stage_seconds(a);
  j["stage_seconds"]["read"] = f.read_seconds;
  if (o.points) j["points"] = points_json(pk);
  emit(out, j);
}

void render_json(std::ostream& out, const BilliardsSearchResult& r, const RenderOptions& o) {
  emit(out, billiards_json(r, o));
}

void render_json(std::ostream& out, const SearchResult& r, const RenderOptions& o) {
  json j;
  j["n"] = r.request.n;
  j["method"] = method_name(r.request.method);
  j["seconds"] = r.seconds;
  j["budget_seconds"] = r.request.seconds;
  j["budget_steps"] = r.request.steps;
  j["seed"] = r.request.seed;
  j["threads"] = r.request.threads;
  j["steps"] = r.steps();
  j["cancelled"] = r.cancelled;
  j["target"] = r.request.target ? json(decimal17(*r.request.target)) : json(nullptr);
  if (r.builder)
    j["builder"] = {{"member", r.builder->member.empty() ? json(nullptr) : json(r.builder->member)},
                    {"d", r.builder->d.empty() ? json(nullptr) : json(r.builder->d)},
                    {"certified", r.builder->certified},
                    {"candidates", r.builder->candidates},
                    {"seconds", r.builder->seconds},
                    {"cpu_seconds", r.builder->cpu_seconds},
                    {"error", r.builder->error.empty() ? json(nullptr) : json(r.builder->error)}};
  else
    j["builder"] = nullptr;
  json packings = json::array();
  for (const auto& x : r.packings) {
    json p{{"rank", x.rank},
           {"label", x.label},
           {"d", x.d.str(kLongDoubleDigits)},
           {"L", x.L.str(kLongDoubleDigits)},
           {"delta", static_cast<double>(oler_delta(r.request.n, 1 / x.pattern.packing.d))},
           {"certified", x.certified},
           {"chains", x.runs()},
           {"first_seed", x.first_seed()}};
    add_counts(p, x.pattern);
    if (o.points) p["points"] = points_json(x.pattern.packing);
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
  json chains = json::array();
  for (const auto& c : r.chains)
    chains.push_back(
        {{"seed", c.seed},
         {"steps", c.steps},
         {"analyses", c.analyses},
         {"analysis_cpu_seconds", c.analysis_cpu_seconds},
         {"seconds", c.seconds},
         {"cpu_seconds", c.cpu_seconds},
         {"best_d", c.best_d.empty() ? json(nullptr) : json(c.best_d)},
         {"seconds_to_best", c.seconds_to_best},
         {"cpu_seconds_to_best", c.cpu_seconds_to_best},
         {"target_reached", c.target_reached},
         {"cpu_seconds_to_target",
          c.target_reached ? json(c.cpu_seconds_to_target) : json(nullptr)},
         {"base", c.base_n == 0 ? json(nullptr)
                                : json{{"n", c.base_n},
                                       {"steps", c.base_steps},
                                       {"best_d", c.base_best_d.empty() ? json(nullptr)
                                                                        : json(c.base_best_d)}}}});
  j["chains"] = chains;
  emit(out, j);
}

void render_json(std::ostream& out, const ConstructedVsBilliards& c, const RenderOptions& o) {
  json j;
  j["n"] = c.n;
  j["seconds"] = c.seconds;
  j["constructed"] = c.constructed ? build_json(c.constructed->best, o) : json(nullptr);
  j["billiards"] = billiards_json(c.billiards, o);
  if (c.comparison) {
    const auto& best = c.billiards.packings.front();
    j["comparison"] = {{"billiards_label", best.label},
                       {"d_relative_difference", static_cast<double>(c.d_relative_difference)},
                       {"same_packing", c.comparison->same},
                       {"same_d", c.comparison->same_d},
                       {"same_contact_graph", c.comparison->isomorphic},
                       {"symmetry", c.comparison->symmetry
                                        ? json(std::string(symmetry_name(*c.comparison->symmetry)))
                                        : json(nullptr)},
                       {"reason", c.comparison->reason}};
  } else {
    j["comparison"] = nullptr;
  }
  emit(out, j);
}

void render_error_json(std::ostream& out, const std::string& message) {
  emit(out, {{"error", message}});
}

}  // namespace tripack::report
