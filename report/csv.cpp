// CSV renderers: a header row, then one row per item; high-precision numbers as 17-digit
// decimals, strings quoted when they hold a comma or a quote (RFC 4180).
#include <initializer_list>
#include <ostream>
#include <string>

#include "core/conventions.hpp"
#include "core/io.hpp"
#include "report/fields.hpp"
#include "report/render.hpp"

namespace tripack::report {

using namespace pipeline;
using namespace jobs;
using namespace search;

namespace {

std::string num(long double v) {
  return decimal17(v);
}
std::string num(double v) {
  return format_significant(v, 6);
}
template <class Int>
std::string integer(Int v) {
  return std::to_string(v);
}
std::string flag(bool b) {
  return b ? "true" : "false";
}
std::string optional_flag(const std::optional<bool>& b) {
  return b ? flag(*b) : "";
}
std::string optional_count(const std::optional<long long>& c) {
  return c ? std::to_string(*c) : "";
}

void packing_header(std::ostream& out) {
  csv_row(out, {"n", "rank", "label", "d", "L", "delta", "bonds", "rattlers", "certified", "runs",
                "first_seed"});
}

void packing_rows(std::ostream& out, const BilliardsSearchResult& r) {
  for (std::size_t i = 0; i < r.packings.size(); ++i) {
    const auto& x = r.packings[i];
    const long double d = x.pattern.packing.d;
    csv_row(out, {integer(r.scene.n), integer(i + 1), x.label, num(d), num(1 / d),
                  num(oler_delta(r.scene.n, 1 / d)), integer(x.bonds()), integer(x.rattlers()),
                  flag(x.certified), integer(x.runs()), integer(x.first_seed())});
  }
}

}  // namespace

void render_csv(std::ostream& out, const Catalogue& catalogue, const RenderOptions&) {
  csv_row(out,
          {"id", "display", "n", "k_min", "k_max", "p_min", "L", "bonds", "rattlers", "claim"});
  for (const auto& c : catalogue.classes())
    csv_row(out, {c.id, c.display, c.n.text(), integer(c.k_min), c.k_max ? integer(c.k_max) : "",
                  c.has_p ? integer(c.p_min) : "", c.L.text(), c.bonds.text(), c.rattlers.text(),
                  c.claim_status});
}

void render_csv(std::ostream& out, const Classification& c, const RenderOptions&) {
  csv_row(out, {"n", "class", "k", "p"});
  for (const auto& m : c.members)
    csv_row(out, {integer(c.n), m.cls->id, integer(m.k), m.cls->has_p ? integer(m.p) : ""});
}

void render_csv(std::ostream& out, const BestBuild& b, const RenderOptions&) {
  const BuildResult& r = b.best;
  const auto& pk = r.pattern.packing;
  const auto& m = r.pattern.provenance;
  const long long n = static_cast<long long>(pk.size());
  csv_row(out, {"class", "k", "p", "variant", "n", "d", "L", "delta", "bonds", "rattlers",
                "certified", "exact_check", "seconds"});
  csv_row(out, {m.class_id, integer(m.k), m.p ? integer(m.p) : "", m.variant, integer(n),
                r.d_string(std::max(r.digits, 17)), num(1 / pk.d), num(oler_delta(n, 1 / pk.d)),
                integer(r.record.pattern.bonds.size()), integer(r.record.pattern.rattlers.size()),
                r.analysis ? flag(r.analysis->certified()) : "", r.exact ? flag(r.exact->ok) : "",
                num(r.seconds())});
}

void render_csv(std::ostream& out, const FormulaCheck& c, const RenderOptions&) {
  csv_row(out, {"class", "k", "p", "variant", "n", "d_built", "d_formula", "relative_difference",
                "bonds", "bonds_expected", "exact_check", "ok"});
  for (const auto& r : c.rows)
    csv_row(out,
            {r.class_id, integer(r.k), r.p ? integer(r.p) : "", r.variant, integer(r.n),
             num(r.d_built), r.d_formula ? num(*r.d_formula) : "",
             r.d_formula ? num(static_cast<double>(r.relative_difference)) : "", integer(r.bonds),
             optional_count(r.bonds_expected), optional_flag(r.exact_ok), flag(r.ok)});
}

void render_csv(std::ostream& out, const CatalogueTable& t, const RenderOptions&) {
  csv_row(out, {"class", "k", "p", "variant", "n", "d", "L", "delta", "bonds", "rattlers",
                "geometry_matches_builder", "certified", "exact_check", "ok", "seconds"});
  for (const auto& r : t.rows)
    csv_row(out,
            {r.member.class_id, integer(r.member.k), r.member.p ? integer(r.member.p) : "",
             r.member.variant, integer(r.n), num(r.d), num(1 / r.d), num(oler_delta(r.n, 1 / r.d)),
             integer(r.bonds), integer(r.rattlers), flag(r.geometry_match), flag(r.certified),
             optional_flag(r.exact_ok), flag(r.ok), num(r.seconds)});
}

void render_csv(std::ostream& out, const FileAnalysis& f, const RenderOptions&) {
  const Analysis& a = f.analysis;
  const long long n = static_cast<long long>(a.pattern.packing.size());
  csv_row(out, {"file", "n", "d", "L", "delta", "convention", "value_in_convention", "bonds",
                "rattlers", "certified", "seconds"});
  const int digits = std::max(f.digits, 17);
  csv_row(out,
          {f.file, integer(n), f.d_string(digits), f.L_string(digits),
           num(oler_delta(n, 1 / a.pattern.packing.d)), std::string(convention_name(f.convention)),
           f.value_string(digits), integer(a.pattern.bonds.size()),
           integer(a.pattern.rattlers.size()), flag(a.certified()), num(f.seconds())});
}

void render_csv(std::ostream& out, const BilliardsSearchResult& r, const RenderOptions&) {
  packing_header(out);
  packing_rows(out, r);
}

void render_csv(std::ostream& out, const SearchResult& r, const RenderOptions&) {
  csv_row(out, {"n", "rank", "label", "d", "L", "delta", "bonds", "rattlers", "certified", "chains",
                "first_seed"});
  for (const auto& x : r.packings)
    csv_row(out, {integer(r.request.n), integer(x.rank), x.label, x.d.str(kLongDoubleDigits),
                  x.L.str(kLongDoubleDigits), num(oler_delta(r.request.n, x.L.value())),
                  integer(x.bonds()), integer(x.rattlers()), flag(x.certified), integer(x.runs()),
                  integer(x.first_seed())});
}

void render_csv(std::ostream& out, const ConstructedVsBilliards& c, const RenderOptions&) {
  csv_row(out, {"n", "constructed", "d_constructed", "bonds_constructed", "rattlers_constructed",
                "billiards_label", "d_billiards", "bonds_billiards", "rattlers_billiards",
                "d_relative_difference", "same_contact_graph", "same_packing", "symmetry"});
  const BuildResult* b = c.constructed ? &c.constructed->best : nullptr;
  const PackingRecord* x = c.billiards.packings.empty() ? nullptr : &c.billiards.packings.front();
  csv_row(out, {integer(c.n), b ? member_name(b->pattern.provenance) : "",
                b ? num(b->pattern.packing.d) : "", b ? integer(b->pattern.bonds.size()) : "",
                b ? integer(b->pattern.rattlers.size()) : "", x ? x->label : "",
                x ? num(x->pattern.packing.d) : "", x ? integer(x->bonds()) : "",
                x ? integer(x->rattlers()) : "",
                c.comparison ? num(static_cast<double>(c.d_relative_difference)) : "",
                c.comparison ? flag(c.comparison->isomorphic) : "",
                c.comparison ? flag(c.comparison->same) : "",
                c.comparison && c.comparison->symmetry
                    ? std::string(symmetry_name(*c.comparison->symmetry))
                    : ""});
}

}  // namespace tripack::report
