#include "report/explore_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "formats/formats.hpp"
#include "report/diagram.hpp"
#include "report/fields.hpp"
#include "report/plot.hpp"

namespace tripack::report {

namespace fs = std::filesystem;
using namespace pipeline;
using namespace jobs;

namespace {

std::string class_of(const PackingRecord& r) {
  return r.pattern.provenance.class_id;
}

std::string packings_csv(const ExploreResult& result) {
  std::ostringstream out;
  out << "n,rank,label,class,p,k,variant,d,L,delta,bonds,rattlers,certified,source,seconds,file\n";
  for (const auto& r : result.packings) {
    const long double d = r.pattern.packing.d;
    out << fmt::format(
        "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{:.6g},{}\n", r.n(), r.rank, csv_field(r.label),
        class_of(r), r.pattern.provenance.p ? std::to_string(r.pattern.provenance.p) : "",
        r.pattern.provenance.class_id.empty() ? "" : std::to_string(r.pattern.provenance.k),
        csv_field(r.pattern.provenance.variant), decimal17(d), decimal17(1 / d),
        decimal17(oler_delta(r.n(), 1 / d)), r.pattern.bonds.size(), r.pattern.rattlers.size(),
        r.certified ? "true" : "false", r.origin(), r.seconds, packing_file_name(r));
  }
  return out.str();
}

std::string packings_json(const ExploreResult& result) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : result.packings) {
    const long double d = r.pattern.packing.d;
    rows.push_back(
        {{"n", r.n()},
         {"rank", r.rank},
         {"label", r.label},
         {"class", r.pattern.provenance.class_id.empty()
                       ? nlohmann::json(nullptr)
                       : nlohmann::json(r.pattern.provenance.class_id)},
         {"p", r.pattern.provenance.p ? nlohmann::json(r.pattern.provenance.p)
                                      : nlohmann::json(nullptr)},
         {"k", r.pattern.provenance.class_id.empty() ? nlohmann::json(nullptr)
                                                     : nlohmann::json(r.pattern.provenance.k)},
         {"variant", r.pattern.provenance.variant.empty()
                         ? nlohmann::json(nullptr)
                         : nlohmann::json(r.pattern.provenance.variant)},
         {"d", decimal17(d)},
         {"L", decimal17(1 / d)},
         {"delta", decimal17(oler_delta(r.n(), 1 / d))},
         {"bonds", r.pattern.bonds.size()},
         {"rattlers", r.pattern.rattlers.size()},
         {"rattler_indices", r.pattern.rattlers},
         {"certified", r.certified},
         {"verdict", r.verdict},
         {"proven_optimal", r.proven_optimal},
         {"source", r.origin()},
         {"seconds", r.seconds},
         {"file", packing_file_name(r)}});
  }
  nlohmann::json j{{"packings", rows},
                   {"cancelled", result.cancelled},
                   {"stages_done", result.stages_done},
                   {"errors", result.errors},
                   {"seconds", result.seconds}};
  return j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string compare_csv(const ExploreResult& result) {
  std::ostringstream out;
  out << "n,builder,billiards_label,d_builder,d_billiards,d_relative_difference,bonds_builder,"
         "bonds_billiards,rattlers_builder,rattlers_billiards,same_contact_graph,same_packing,"
         "symmetry,reason\n";
  for (const auto& c : result.comparisons)
    out << fmt::format("{},{},{},{},{},{:.3g},{},{},{},{},{},{},{},{}\n", c.n, csv_field(c.builder),
                       c.billiards_label, decimal17(c.d_builder), decimal17(c.d_billiards),
                       static_cast<double>(c.d_relative_difference), c.bonds_builder,
                       c.bonds_billiards, c.rattlers_builder, c.rattlers_billiards,
                       c.same_contact_graph, c.same_packing, c.symmetry, csv_field(c.reason));
  return out.str();
}

std::string classes_csv(const ExploreResult& result) {
  std::ostringstream out;
  out << "class,p,k,n,L_n,L_n_plus_1,difference,n_plus_1_from,paper_tight\n";
  for (const auto& g : result.class_gaps)
    out << fmt::format("{},{},{},{},{},{},{},{},{}\n", g.class_id, g.p ? std::to_string(g.p) : "",
                       g.k, g.n, decimal17(g.L_n), decimal17(g.L_next), decimal17(g.L_next - g.L_n),
                       csv_field(g.next_source), csv_field(g.claim_tight));
  return out.str();
}

std::vector<DeltaPoint> delta_points(const ExploreResult& result, const ExploreAtlas* atlas) {
  std::vector<DeltaPoint> points;
  std::set<std::pair<std::string, long long>> seen;
  std::map<long long, const PackingRecord*> billiards_best;
  std::set<long long> in_class;
  for (const auto& r : result.packings) {
    if (r.from_builder()) in_class.insert(r.n());
    if (!r.from_builder() && r.rank == 1) billiards_best[r.n()] = &r;
  }
  for (const auto& r : result.packings) {
    if (!r.from_builder() ||
        !seen.insert(
                 {r.pattern.provenance.class_id + std::to_string(r.pattern.provenance.p), r.n()})
             .second)
      continue;
    const double delta = static_cast<double>(oler_delta(r.n(), 1 / r.pattern.packing.d));
    // The matrix class is two-parametric: one line per row p (GL1995: rows are tight).
    const std::string line =
        r.pattern.provenance.p
            ? fmt::format("{} p={}", r.pattern.provenance.class_id, r.pattern.provenance.p)
            : r.pattern.provenance.class_id;
    points.push_back({r.n(), delta, line, r.proven_optimal, false});
  }
  for (const auto& [n, r] : billiards_best) {
    const double delta = static_cast<double>(oler_delta(n, 1 / r->pattern.packing.d));
    points.push_back({n, delta, "", r->proven_optimal, true});
    if (!in_class.count(n)) points.push_back({n, delta, "", r->proven_optimal, false});
  }
  if (atlas)
    for (const auto& e : atlas->best) {
      const double delta = std::stod(jobs::atlas_delta(e));
      points.push_back({e.n(), delta, "", false, false, true});
      // n in no class that the exploration did not search: its open square from the atlas.
      if (!in_class.count(e.n()) && !billiards_best.count(e.n()))
        points.push_back({e.n(), delta, "", false, false});
    }
  return points;
}

std::string accuracy_csv(const AccuracyStudy& study) {
  std::ostringstream out;
  out << "n,label,method,target,seconds,digits,reference\n";
  for (const auto& r : study.rows)
    out << fmt::format("{},{},{},{},{:.6g},{},{}\n", r.n, csv_field(r.label), csv_field(r.method),
                       csv_field(r.target), r.seconds,
                       std::isfinite(r.digits) ? fmt::format("{:.2f}", r.digits) : "", r.reference);
  out << "\n# hard cases (docs/accuracy.md): name,stable,what,evidence\n";
  for (const auto& h : study.hard_cases)
    out << fmt::format("# {},{},{},{}\n", csv_field(h.name), h.stable, csv_field(h.what),
                       csv_field(h.evidence));
  return out.str();
}

// One curve per n: digits against the cumulative time of billiards (each gap), then the long
// double polish and MPFR from the billiards end state.
std::vector<AccuracyPoint> accuracy_points(const AccuracyStudy& study) {
  std::vector<AccuracyPoint> points;
  std::map<long long, double> billiards_end, polished_at;
  for (const auto& r : study.rows) {
    const std::string series = fmt::format("n = {}", r.n);
    double at = r.seconds;
    if (r.method == "billiards") {
      billiards_end[r.n] = std::max(billiards_end[r.n], r.seconds);
    } else if (r.method.rfind("polish", 0) == 0) {
      at = billiards_end[r.n] + r.seconds;
      polished_at[r.n] = at;
    } else {
      at = polished_at[r.n] + r.seconds;
    }
    if (std::isfinite(r.digits) && at > 0) points.push_back({series, at, r.digits});
  }
  return points;
}

std::string html_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// Report size: Cairo's SVG of a diagram grows ~1.5 kB a disk (a forces SVG ~8 kB a disk: 6.9 MB
// at n = 820), so forces diagrams are PNGs for builder packings up to n = 100, and rows beyond
// the explored max n (the large terms) get a PNG only. Measured on the default explore: 377 MB
// of diagrams before these limits.
constexpr long long kForcesMaxN = 100;

bool forces_drawn(const PackingRecord& r) {
  return r.from_builder() && r.certified && r.n() <= kForcesMaxN &&
         r.forces.size() == r.pattern.bonds.size();
}

// One raster per diagram (the report's size: an SVG and a PNG of each of ~860 packings weighed
// ~200 MB, mostly the SVGs' glyphs): PNGs at 1.5x the page's 220 px, forces at 2x.
constexpr int kDiagramPixels = 330;
constexpr int kForcesPixels = 440;

// A file of the installed data into the report: hard-linked where the file system allows (the
// exact certificates are 175 MB together and never change), else copied.
void link_or_copy(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::remove(to, ec);
  fs::create_hard_link(from, to, ec);
  if (ec) fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

std::string atlas_diagram(const PackingRecord& e) {
  return "diagrams/atlas-" + e.label + ".png";
}

// The atlas beside the exploration: where it beats every certified builder of n, its best row of
// every n with a diagram, and the files (copied into atlas/).
std::string html_atlas(const ExploreResult& result, const ExploreAtlas& atlas, bool diagrams) {
  std::ostringstream h;
  std::map<long long, const PackingRecord*> best_builder;
  for (const auto& r : result.packings)
    if (r.from_builder() && r.certified &&
        (!best_builder.count(r.n()) ||
         r.pattern.packing.d > best_builder[r.n()]->pattern.packing.d))
      best_builder[r.n()] = &r;
  long long first = 0, last = 0;
  std::size_t count = 0;
  for (const auto& e : atlas.best) {
    first = count ? std::min(first, e.n()) : e.n();
    last = std::max(last, e.n());
    ++count;
  }
  h << fmt::format(
      "<h2 id=\"atlas\">Atlas: the best certified packing of every n = {}..{}</h2>\n<p>From "
      "<a href=\"atlas/atlas.csv\">atlas.csv</a> ({} rows; copied from {}): "
      "billiards campaigns "
      "and every builder whose class contains n, each certified again from its coordinates and "
      "polished in MPFR to 30 digits; every file is in <a href=\"atlas/atlas/\">atlas/atlas/</a>. "
      "In the &delta;(n) plot above its values are the grey dots.</p>\n",
      first, last, atlas.rows.size(),
      atlas.csv.parent_path().filename() == "tripack" &&
              atlas.csv.parent_path().parent_path().filename() == "share"
          ? std::string("the installed share/tripack/atlas.csv, the repository's data/atlas.csv")
          : html_escape(atlas.csv.string()));
  h << "<h3>Where the atlas beats every builder of n</h3>\n<table><tr><th>n</th><th>best "
       "builder</th><th>d builder</th><th>atlas</th><th>d atlas</th><th>gain</th><th>bonds</th>"
       "<th>rattlers</th><th>source</th></tr>\n";
  for (const auto& e : atlas.best) {
    if (!best_builder.count(e.n())) continue;
    const auto* b = best_builder[e.n()];
    const long double d_atlas = e.d.value(), d_builder = b->pattern.packing.d;
    if (d_atlas <= d_builder * (1 + 1e-12L)) continue;
    h << fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.3g}</td><td>{}</td>"
        "<td>{}</td><td>{}</td></tr>\n",
        e.n(), html_escape(member_name(b->pattern.provenance)), format_significant(d_builder, 15),
        html_escape(e.label), e.d.str().substr(0, 17), static_cast<double>(d_atlas / d_builder - 1),
        e.bonds(), e.rattlers(), html_escape(e.source_text()));
  }
  h << "</table>\n<h3>Best of every n</h3>\n";
  if (!atlas.exact.empty())
    h << "<p>Exact d(n) (docs/exact.md, <a href=\"atlas/atlas-exact.csv\">atlas-exact.csv</a>): "
         "the "
         "degree of d's minimal polynomial P and the proof: <em>exact</em> (the exact "
         "configuration "
         "exists and is a strict local optimum), <em>existence</em> (it exists), <em>none</em>; "
         "each "
         "proof links to its certificate, which checker/check_exact.sh re-checks with "
         "PARI/GP.</p>\n";
  h << "<table><tr><th>n</th><th>label</th><th>d (30 digits)</th><th>&delta;</th><th>bonds</th>"
       "<th>rattlers</th><th>source</th>"
    << (atlas.exact.empty() ? "" : "<th>deg P</th><th>proof</th>") << "<th>files</th></tr>\n";
  for (const auto& e : atlas.best) {
    std::string exact_cells;
    if (!atlas.exact.empty()) {
      const auto it = atlas.exact.find(e.label);
      if (it == atlas.exact.end())
        exact_cells = "<td></td><td>not run</td>";
      else if (it->second.proof == "none")
        exact_cells = fmt::format("<td>{}</td><td title=\"{}\">none</td>", it->second.degree,
                                  html_escape(it->second.reason));
      else if (fs::exists(atlas.csv.parent_path() / "exact" / (e.label + ".gp")))
        exact_cells =
            fmt::format("<td title=\"{}\">{}</td><td><a href=\"atlas/exact/{}.gp\">{}</a></td>",
                        html_escape(it->second.polynomial), it->second.degree, html_escape(e.label),
                        it->second.proof);
      else  // a proof whose certificate the installation lacks: no link to a missing file
        exact_cells =
            fmt::format("<td title=\"{}\">{}</td><td>{}</td>", html_escape(it->second.polynomial),
                        it->second.degree, it->second.proof);
    }
    h << fmt::format(
        "<tr id=\"atlas-{0}\"><td>{1}</td><td>{0}</td><td>{2}</td><td>{3}</td><td>{4}</td>"
        "<td>{5}</td><td style=\"text-align:left\">{6}</td>{9}<td><a href=\"atlas/{7}\">coordinates"
        "</a>{8}</td></tr>\n",
        html_escape(e.label), e.n(), e.d.str(), jobs::atlas_delta(e).substr(0, 12), e.bonds(),
        e.rattlers(), html_escape(e.source_text()), html_escape(e.file),
        diagrams ? fmt::format(" <a href=\"{}\">diagram</a>", atlas_diagram(e)) : "", exact_cells);
  }
  h << "</table>\n";
  if (!atlas.gaps.empty()) {
    h << "<h3 id=\"atlas-gaps\">Tight or loose: L(n(k)+1) &minus; L(n(k)) between the atlas's "
         "best packings</h3>\n<p>GL1995 sec. 6: a class is tight when this step stays away from "
         "0 as k grows, loose when &delta;(n(k)+1) &minus; &delta;(n(k)) tends to 0 (<a "
         "href=\"atlas/atlas-gaps.csv\">atlas-gaps.csv</a>).</p>\n<table><tr><th>class</th>"
         "<th>p</th><th>k</th><th>n</th><th>n+1</th><th>L(n+1) &minus; L(n)</th><th>&delta; "
         "step</th><th>paper: tight</th></tr>\n";
    for (const auto& g : atlas.gaps)
      h << fmt::format(
          "<tr><td>{}</td><td>{}</td><td>{}</td><td>{} ({})</td><td>{}</td><td>{:.6g}</td>"
          "<td>{:.6g}</td><td>{}</td></tr>\n",
          html_escape(g.class_id), g.p ? std::to_string(g.p) : "", g.k, g.n, html_escape(g.label_n),
          html_escape(g.label_next), static_cast<double>(g.L_next - g.L_n),
          static_cast<double>(g.delta_difference), html_escape(g.claim_tight));
    h << "</table>\n";
  }
  if (diagrams) {
    h << "<h3>Diagrams</h3>\n<div class=\"grid\">\n";
    for (const auto& p : atlas.best)
      h << fmt::format(
          "<figure><a href=\"{0}\"><img src=\"{0}\" loading=\"lazy\" alt=\"{1}\"></a>"
          "<figcaption>{1} (n = {2}, d = {3}, {4} bonds, {5} rattlers)</figcaption></figure>\n",
          atlas_diagram(p), html_escape(p.label), p.n(), p.d.str().substr(0, 17), p.bonds(),
          p.rattlers());
    h << "</div>\n";
  }
  return h.str();
}

std::string html_page(const ExploreResult& result, bool diagrams, bool forces,
                      const ExploreAtlas* atlas) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
       "<title>tripack explore</title>\n<style>\n"
       "body{font-family:sans-serif;margin:1.5em;max-width:1200px}"
       "table{border-collapse:collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 6px;"
       "text-align:right}th{background:#eee}.warn{background:#fdd;padding:.5em;border:1px solid "
       "#c00}"
       ".grid{display:flex;flex-wrap:wrap;gap:8px}.grid figure{margin:0;width:220px;font-size:11px}"
       ".grid img{width:220px}\n</style></head><body>\n";
  h << "<h1>Dense packings of n equal disks in an equilateral triangle</h1>\n";
  if (result.cancelled)
    h << "<p class=\"warn\" id=\"interrupted\">This exploration was interrupted: the report shows "
         "what finished (stages done: "
      << html_escape(fmt::format("{}", fmt::join(result.stages_done, ", "))) << ").</p>\n";
  h << fmt::format(
      "<p>max n {} (discovered classes: {}), search for n &le; {} and class members &le; {} ({} "
      "basin-hopping steps per chain, one chain per thread; stress set: {} billiards runs), seed "
      "{}; {} packings, {} comparisons; {:.1f} s.</p>\n",
      result.settings.max_n, result.settings.discovered_max_n, result.settings.billiards_max_n,
      result.settings.class_billiards_max_n, result.settings.search_steps,
      result.settings.large_runs, result.settings.seed, result.packings.size(),
      result.comparisons.size(), result.seconds);
  for (const auto& e : result.errors) h << "<p class=\"warn\">" << html_escape(e) << "</p>\n";
  h << "<h2>&delta;(n) = L(n) &minus; t(n)</h2>\n<p><img src=\"delta.svg\" alt=\"delta(n) plot\" "
       "width=\"900\"></p>\n<p>Data: <a href=\"delta.csv\">delta.csv</a>, script: <a "
       "href=\"delta.gp\">delta.gp</a>; all packings: <a href=\"packings.csv\">packings.csv</a>, "
       "<a href=\"packings.json\">packings.json</a>; <a href=\"compare.csv\">compare.csv</a>, <a "
       "href=\"classes.csv\">classes.csv</a>.</p>\n";
  if (atlas) h << html_atlas(result, *atlas, diagrams);
  h << "<h2>Constructed vs billiards</h2>\n<table><tr><th>n</th><th>builder</th><th>billiards"
       "</th><th>d builder</th><th>d billiards</th><th>rel. diff</th><th>bonds</th><th>rattlers"
       "</th><th>same graph</th></tr>\n";
  for (const auto& c : result.comparisons)
    h << fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.2g}</td><td>{} / {}"
        "</td><td>{} / {}</td><td>{}</td></tr>\n",
        c.n, html_escape(c.builder), html_escape(c.billiards_label),
        format_significant(c.d_builder, 15), format_significant(c.d_billiards, 15),
        static_cast<double>(c.d_relative_difference), c.bonds_builder, c.bonds_billiards,
        c.rattlers_builder, c.rattlers_billiards,
        c.same_packing ? "yes (" + c.symmetry + ")" : (c.same_contact_graph ? "graph only" : "no"));
  h << "</table>\n";
  if (result.accuracy) {
    h << "<h2>Accuracy against time</h2>\n<p><img src=\"accuracy-plot.svg\" alt=\"accuracy plot\" "
         "width=\"900\"></p>\n<p>Digits of d against seconds: billiards alone to a relative gap "
         "of 1e-3 .. 1e-12, then the long double polish and MPFR to 30, 50, 100 digits (<a "
         "href=\"accuracy.csv\">accuracy.csv</a>).</p>\n<table><tr><th>n</th><th>packing</th>"
         "<th>method</th><th>target</th><th>seconds</th><th>digits</th></tr>\n";
    for (const auto& r : result.accuracy->rows)
      h << fmt::format(
          "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.3g}</td><td>{}"
          "</td></tr>\n",
          r.n, html_escape(r.label), html_escape(r.method), html_escape(r.target), r.seconds,
          std::isfinite(r.digits) ? fmt::format("{:.1f}", r.digits) : "-");
    h << "</table>\n<h3>Hard cases</h3>\n<table><tr><th>case</th><th>what</th><th>stable</th>"
         "<th>how we know</th></tr>\n";
    for (const auto& c : result.accuracy->hard_cases)
      h << fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                       html_escape(c.name), html_escape(c.what), c.stable ? "yes" : "NO",
                       html_escape(c.evidence));
    h << "</table>\n";
  }
  h << "<h2>Class gaps L(n(k)+1) &minus; L(n(k))</h2>\n<table><tr><th>class</th><th>p"
       "</th><th>k</th><th>n</th><th>difference</th><th>n+1 from</th><th>paper: tight</th></tr>\n";
  for (const auto& g : result.class_gaps)
    h << fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.6g}</td><td>{}</td>"
        "<td>{}</td></tr>\n",
        g.class_id, g.p ? std::to_string(g.p) : "", g.k, g.n, static_cast<double>(g.L_next - g.L_n),
        html_escape(g.next_source), html_escape(g.claim_tight));
  h << "</table>\n<h2>Packings</h2>\n<table><tr><th>n</th><th>label</th><th>source</th><th>d</th>"
       "<th>&delta;</th><th>bonds</th><th>rattlers</th><th>certified</th><th>file</th></tr>\n";
  for (const auto& r : result.packings) {
    const long double d = r.pattern.packing.d;
    h << fmt::format(
        "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{:.6f}</td><td>{}</td><td>{}</td>"
        "<td>{}</td><td><a href=\"{}\">coordinates</a></td></tr>\n",
        r.n(), html_escape(r.label), r.origin(), format_significant(d, 15),
        static_cast<double>(oler_delta(r.n(), 1 / d)), r.pattern.bonds.size(),
        r.pattern.rattlers.size(), r.certified ? "yes" : "no", packing_file_name(r));
  }
  h << "</table>\n";
  if (diagrams) {
    h << "<h2>Diagrams</h2>\n<div class=\"grid\">\n";
    for (const auto& r : result.packings) {
      const std::string stem = packing_file_name(r);
      const std::string base = "diagrams/" + fs::path(stem).stem().string();
      h << fmt::format(
          "<figure><a href=\"{0}.png\"><img src=\"{0}.png\" loading=\"lazy\" alt=\"{1}\"></a>"
          "<figcaption>{1} (n = {2}, d = {3}){4}</figcaption></figure>\n",
          base, html_escape(r.label), r.n(), format_significant(r.pattern.packing.d, 15),
          forces && forces_drawn(r) ? fmt::format(" <a href=\"{}-forces.png\">forces</a>", base)
                                    : "");
    }
    h << "</div>\n";
  }
  h << "<p>tripack: d(n) is the largest minimum distance of n points in the side-1 equilateral "
       "triangle; L = 1/d; Oler's bound t(n) = (&minus;3 + &radic;(8n+1))/2. Every value above was "
       "polished and certified (rigid with a strictly positive stress) unless marked.</p>\n";
  h << "</body></html>\n";
  return h.str();
}

}  // namespace

std::string packing_file_name(const PackingRecord& row) {
  const std::string name =
      row.from_builder()
          ? fmt::format("n{:04d}-{}", row.n(), pipeline::member_file_stem(row.pattern.provenance))
          : fmt::format("n{:04d}-{}", row.n(), row.label);
  return "packings/" + name + ".txt";
}

void write_explore_report(const ExploreResult& result, const fs::path& dir,
                          const ExploreReportOptions& options,
                          const std::function<void(const std::string&)>& progress) {
  auto say = [&](const std::string& what) {
    if (progress) progress(what);
  };
  std::error_code ec;
  fs::create_directories(dir / "packings", ec);
  if (!ec) fs::create_directories(dir / "diagrams", ec);
  if (ec) throw std::runtime_error("cannot write to directory '" + dir.string() + "'");
  say("data: packings.csv, packings.json, compare.csv, classes.csv, coordinates");
  write_whole_file(dir / "packings.csv", packings_csv(result));
  write_whole_file(dir / "packings.json", packings_json(result));
  write_whole_file(dir / "compare.csv", compare_csv(result));
  write_whole_file(dir / "classes.csv", classes_csv(result));
  for (const auto& r : result.packings)
    write_packing_file((dir / packing_file_name(r)).string(), r, WriteOptions{});
  if (options.diagrams) {
    say(fmt::format("diagrams: {} packings", result.packings.size()));
    for (const auto& r : result.packings) {
      Diagram diagram{r.pattern, r.label, format_significant(r.pattern.packing.d, 15), r.forces};
      const fs::path base = dir / "diagrams" / fs::path(packing_file_name(r)).stem();
      draw_packing(diagram, base.string() + ".png", {kDiagramPixels, true, false});
      if (options.forces && forces_drawn(r))
        draw_packing(diagram, base.string() + "-forces.png", {kForcesPixels, true, true});
    }
  }
  if (options.atlas) {
    say(fmt::format("atlas: {} rows, {} diagrams", options.atlas->rows.size(),
                    options.diagrams ? options.atlas->best.size() : 0));
    const fs::path from = options.atlas->csv.parent_path();
    fs::create_directories(dir / "atlas" / "atlas");
    fs::copy_file(options.atlas->csv, dir / "atlas" / "atlas.csv",
                  fs::copy_options::overwrite_existing);
    if (fs::exists(from / "atlas-gaps.csv"))
      fs::copy_file(from / "atlas-gaps.csv", dir / "atlas" / "atlas-gaps.csv",
                    fs::copy_options::overwrite_existing);
    for (const auto& e : options.atlas->rows)
      fs::copy_file(from / e.file, dir / "atlas" / e.file, fs::copy_options::overwrite_existing);
    if (!options.atlas->exact.empty()) {
      fs::copy_file(from / "atlas-exact.csv", dir / "atlas" / "atlas-exact.csv",
                    fs::copy_options::overwrite_existing);
      fs::create_directories(dir / "atlas" / "exact");
      for (const auto& e : options.atlas->best) {
        const fs::path certificate = from / "exact" / (e.label + ".gp");
        if (fs::exists(certificate))
          link_or_copy(certificate, dir / "atlas" / "exact" / certificate.filename());
      }
    }
    if (options.diagrams)
      for (const auto& p : options.atlas->best) {
        Diagram diagram{p.pattern, p.label, p.d.str().substr(0, 17), p.forces};
        draw_packing(diagram, (dir / atlas_diagram(p)).string(),
                     {kDiagramPixels, p.n() <= 60, false});
      }
  }
  say("plot: delta.svg, delta.png, delta.pdf");
  plot_delta(delta_points(result, options.atlas), dir);
  if (result.accuracy) {
    say("accuracy: accuracy.csv, accuracy.svg, accuracy.png, accuracy.pdf");
    const auto points = accuracy_points(*result.accuracy);
    if (!points.empty()) plot_accuracy(points, dir, "accuracy-plot");
    write_whole_file(dir / "accuracy.csv", accuracy_csv(*result.accuracy));
  }
  say("index.html");
  write_whole_file(dir / "index.html",
                   html_page(result, options.diagrams, options.forces, options.atlas));
}

}  // namespace tripack::report
