#include "constructors/catalogue.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "constructors/chain.hpp"
#include "core/data_directory.hpp"

namespace tripack {

namespace {

std::string where(const YAML::Node& n) {
  const auto m = n.Mark();
  return m.line >= 0 ? "line " + std::to_string(m.line + 1) : "?";
}

std::string req_string(const YAML::Node& node, const char* key, const std::string& ctx) {
  const YAML::Node v = node[key];
  if (!v || !v.IsScalar())
    throw CatalogueError(ctx + ": missing or non-scalar '" + key + "' (" + where(node) + ")");
  return v.as<std::string>();
}

std::string opt_string(const YAML::Node& node, const char* key) {
  const YAML::Node v = node[key];
  return (v && v.IsScalar()) ? v.as<std::string>() : std::string();
}

Expression expr(const std::string& text, const std::string& ctx) {
  try {
    return Expression::parse(text);
  } catch (const ExpressionError& e) {
    throw CatalogueError(ctx + ": " + e.what());
  }
}

Expression opt_expr(const YAML::Node& node, const char* key, const std::string& ctx) {
  const std::string s = opt_string(node, key);
  return s.empty() ? Expression() : expr(s, ctx + "." + key);
}

long opt_long(const YAML::Node& node, const char* key, long fallback, const std::string& ctx) {
  const YAML::Node v = node[key];
  if (!v) return fallback;
  try {
    return v.as<long>();
  } catch (const YAML::Exception&) {
    throw CatalogueError(ctx + ": '" + key + "' must be an integer (" + where(v) + ")");
  }
}

// The entries of the list `key` (none when it is absent), each about the members it names by k
// and p (0: any): read_rest reads what else an entry holds.
template <class Entry, class ReadRest>
void read_members(const YAML::Node& node, const char* key, const std::string& ctx,
                  std::vector<Entry>& out, ReadRest read_rest) {
  const YAML::Node list = node[key];
  if (!list) return;
  for (const auto& x : list) {
    Entry e;
    e.k = opt_long(x, "k", 0, ctx);
    e.p = opt_long(x, "p", 0, ctx);
    read_rest(x, e);
    out.push_back(std::move(e));
  }
}

ClassInfo parse_class(const YAML::Node& node) {
  if (!node.IsMap())
    throw CatalogueError("classes.yaml: every class must be a mapping (" + where(node) + ")");
  ClassInfo c;
  c.id = req_string(node, "id", "class");
  const std::string ctx = "class '" + c.id + "'";
  c.display = req_string(node, "display", ctx);
  c.n = expr(req_string(node, "n", ctx), ctx + ".n");
  for (const auto& v : c.n.variables())
    if (v != "k" && v != "p") throw CatalogueError(ctx + ".n: unknown variable '" + v + "'");
  c.k_min = opt_long(node, "k_min", 1, ctx);
  c.k_max = opt_long(node, "k_max", 0, ctx);
  c.p_min = opt_long(node, "p_min", 1, ctx);
  c.k_min_reason = opt_string(node, "k_min_reason");
  c.k_max_reason = opt_string(node, "k_max_reason");
  const auto vars = c.n.variables();
  c.has_p = std::find(vars.begin(), vars.end(), "p") != vars.end();
  if (c.k_min < 1 || (c.k_max && c.k_max < c.k_min))
    throw CatalogueError(ctx + ": invalid k range");
  const YAML::Node b = node["builder"];
  if (!b || !b.IsMap()) throw CatalogueError(ctx + ": missing 'builder' mapping");
  c.builder = req_string(b, "name", ctx + ".builder");
  for (const auto& kv : b) {
    const auto key = kv.first.as<std::string>();
    if (key != "name")
      c.builder_args[key] = expr(kv.second.as<std::string>(), ctx + ".builder." + key);
  }
  c.L = opt_expr(node, "L", ctx);
  c.closed_form = node["closed_form"] && node["closed_form"].as<bool>();
  c.bonds = opt_expr(node, "bonds", ctx);
  c.rattlers = opt_expr(node, "rattlers", ctx);
  c.rigid = !node["rigid"] || node["rigid"].as<bool>();
  c.note = opt_string(node, "note");
  if (const YAML::Node cl = node["claim"]; cl && cl.IsMap()) {
    c.claim_status = opt_string(cl, "status");
    c.claim_best = opt_string(cl, "best");
    c.claim_tight = opt_string(cl, "tight");
    c.claim_source = opt_string(cl, "source");
  }
  if (const YAML::Node vs = node["variants"]) {
    if (!vs.IsSequence()) throw CatalogueError(ctx + ": 'variants' must be a list");
    for (const auto& v : vs) {
      VariantInfo vi;
      vi.id = req_string(v, "id", ctx + " variant");
      const std::string vctx = ctx + " variant '" + vi.id + "'";
      if (vi.id.size() > 2 && vi.id.substr(vi.id.size() - 2) == "-m") {
        vi.is_family = true;
        vi.prefix = vi.id.substr(0, vi.id.size() - 1);
        vi.m_min = expr(req_string(v, "m_min", vctx), vctx + ".m_min");
        vi.m_max = expr(req_string(v, "m_max", vctx), vctx + ".m_max");
      }
      vi.bonds = opt_expr(v, "bonds", vctx);
      vi.rattlers = opt_expr(v, "rattlers", vctx);
      vi.is_default = v["default"] && v["default"].as<bool>();
      vi.k_min = opt_long(v, "k_min", 0, vctx);
      if (vi.k_min && vi.k_min < c.k_min)
        throw CatalogueError(vctx + ": k_min " + std::to_string(vi.k_min) +
                             " is below the class's k_min " + std::to_string(c.k_min));
      c.variants.push_back(std::move(vi));
    }
  }
  read_members(node, "closed_form_L", ctx, c.closed_form_L,
               [&](const YAML::Node& x, ClosedFormL& e) {
                 e.L = expr(req_string(x, "L", ctx + ".closed_form_L"), ctx + ".closed_form_L");
                 e.source = opt_string(x, "source");
               });
  read_members(node, "references", ctx, c.references,
               [&](const YAML::Node& r, ReferenceValue& ref) {
                 ref.n = opt_long(r, "n", 0, ctx);
                 ref.variant = opt_string(r, "variant");
                 ref.label = opt_string(r, "label");
                 ref.source = opt_string(r, "source");
                 if (r["d"]) ref.d = r["d"].as<std::string>();
                 if (r["bonds"]) ref.bonds = opt_long(r, "bonds", 0, ctx);
                 if (r["rattlers"]) ref.rattlers = opt_long(r, "rattlers", 0, ctx);
               });
  return c;
}

}  // namespace

ExpressionEnv<long long> integer_env(long k, long p, long m) {
  ExpressionEnv<long long> env;
  env.variable = [k, p, m](std::string_view name) -> std::optional<long long> {
    if (name == "k") return k;
    if (name == "p") return p;
    if (name == "m") return m;
    return std::nullopt;
  };
  return env;
}

ExpressionEnv<long double> real_env(long k, long p) {
  ExpressionEnv<long double> env;
  env.variable = [k, p](std::string_view name) -> std::optional<long double> {
    if (name == "k") return static_cast<long double>(k);
    if (name == "p") return static_cast<long double>(p);
    return std::nullopt;
  };
  env.function = [](std::string_view name,
                    std::span<const long double> a) -> std::optional<long double> {
    if (a.size() != 1) return std::nullopt;
    // A chain length the solver can take (fuzzing: ripple(1e300) overflowed the cast,
    // ripple(100000000) asked for 3.2 GB; the catalogue needs k up to thousands).
    if (!(a[0] >= 0 && a[0] <= 100000) || a[0] != std::floor(a[0]))
      throw ExpressionError("ripple/sparse chain length must be an integer in [0, 100000]");
    const int q = static_cast<int>(a[0]);
    if (name == "ripple") return solve_ripple_chain(q, 2).L;
    if (name == "sparse") return solve_ripple_chain(q, 1).L;
    return std::nullopt;
  };
  return env;
}

Catalogue Catalogue::parse(const std::string& text) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw CatalogueError(std::string("classes.yaml is not valid YAML: ") + e.what());
  }
  if (!root.IsMap() || !root["classes"] || !root["classes"].IsSequence())
    throw CatalogueError("classes.yaml has no 'classes' list");
  Catalogue cat;
  try {
    for (const auto& c : root["classes"]) cat.classes_.push_back(parse_class(c));
  } catch (const YAML::Exception& e) {
    throw CatalogueError(std::string("classes.yaml: ") + e.what());
  }
  for (std::size_t i = 0; i < cat.classes_.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (cat.classes_[i].id == cat.classes_[j].id)
        throw CatalogueError("classes.yaml: duplicate class id '" + cat.classes_[i].id + "'");
  return cat;
}

Catalogue Catalogue::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw CatalogueError("cannot read catalogue '" + path + "'");
  std::stringstream ss;
  ss << in.rdbuf();
  try {
    return parse(ss.str());
  } catch (const CatalogueError& e) {
    throw CatalogueError(path + ": " + e.what());
  }
}

std::string Catalogue::default_path() {
  if (const char* env = std::getenv("TRIPACK_CATALOGUE"); env && *env) return env;
  return (data_directory() / "classes.yaml").string();
}

const ClassInfo& Catalogue::find(const std::string& id) const {
  for (const auto& c : classes_)
    if (c.id == id) return c;
  std::string ids;
  for (const auto& c : classes_) ids += (ids.empty() ? "" : ", ") + c.id;
  throw MemberError("unknown class '" + id + "' (known: " + ids + ")");
}

void Catalogue::check_parameters(const ClassInfo& c, long k, long p) const {
  if (k < c.k_min)
    throw MemberError(c.id + ": k = " + std::to_string(k) +
                      " is below the valid range k >= " + std::to_string(c.k_min) +
                      (c.k_min_reason.empty() ? "" : " (" + c.k_min_reason + ")"));
  if (c.k_max && k > c.k_max)
    throw MemberError(c.id + ": k = " + std::to_string(k) +
                      " is above the valid range k <= " + std::to_string(c.k_max) +
                      (c.k_max_reason.empty() ? "" : " (" + c.k_max_reason + ")"));
  if (c.has_p && p == 0)
    throw MemberError(c.id + " needs --p (p >= " + std::to_string(c.p_min) + ")");
  if (c.has_p && p < c.p_min)
    throw MemberError(c.id + ": p = " + std::to_string(p) +
                      " is below the valid range p >= " + std::to_string(c.p_min));
  if (!c.has_p && p != 0) throw MemberError(c.id + " takes no --p");
}

long long Catalogue::n_of(const ClassInfo& c, long k, long p) const {
  check_parameters(c, k, p);
  try {
    return c.n.eval<long long>(integer_env(k, p));
  } catch (const ExpressionError& e) {
    throw CatalogueError(c.id + ".n: " + e.what());
  }
}

void Catalogue::check_scan_step(const ClassInfo& c, char var, long at,
                                std::optional<long long> previous, long long n) {
  const std::string v(1, var);
  if (n < 1)
    throw CatalogueError(c.id + ".n is " + std::to_string(n) + " at " + v + " = " +
                         std::to_string(at) + " (a class's n must be at least 1)");
  if (previous && n <= *previous)
    throw CatalogueError(c.id + ".n does not grow with " + v + ": " + std::to_string(*previous) +
                         " at " + v + " = " + std::to_string(at - 1) + ", " + std::to_string(n) +
                         " at " + v + " = " + std::to_string(at));
}

std::vector<Member> Catalogue::classify(long long N) const {
  std::vector<Member> out;
  for (const auto& c : classes_) {
    auto n_at = [&](long k, long p) { return c.n.eval<long long>(integer_env(k, p)); };
    // n grows strictly with k (and with p), so each scan stops once it passes N.
    std::optional<long long> first_n;  // n(k_min, p - 1)
    for (long p = c.has_p ? c.p_min : 0;; ++p) {
      if (c.has_p) {
        const long long first = n_at(c.k_min, p);
        check_scan_step(c, 'p', p, first_n, first);
        first_n = first;
        if (first > N) break;
      }
      std::optional<long long> previous;
      for (long k = c.k_min; !c.k_max || k <= c.k_max; ++k) {
        const long long n = n_at(k, p);
        check_scan_step(c, 'k', k, previous, n);
        previous = n;
        if (n == N) out.push_back({&c, k, p, n});
        if (n >= N) break;
      }
      if (!c.has_p) break;
    }
  }
  return out;
}

const VariantInfo* Catalogue::variant_info(const ClassInfo& c, long k, const std::string& v) const {
  for (const auto& vi : c.variants) {
    if (k < vi.k_min) continue;
    if (!vi.is_family) {
      if (vi.id == v) return &vi;
      continue;
    }
    if (v.rfind(vi.prefix, 0) != 0) continue;
    const std::string tail = v.substr(vi.prefix.size());
    if (tail.empty() || tail.find_first_not_of("0123456789") != std::string::npos) continue;
    const long m = std::stol(tail);
    const auto env = integer_env(k, 0);
    if (m >= vi.m_min.eval<long long>(env) && m <= vi.m_max.eval<long long>(env)) return &vi;
  }
  return nullptr;
}

std::vector<std::string> Catalogue::variants_at(const ClassInfo& c, long k) const {
  std::vector<std::string> out;
  for (const auto& vi : c.variants) {
    if (k < vi.k_min) continue;
    if (!vi.is_family) {
      out.push_back(vi.id);
      continue;
    }
    const auto env = integer_env(k, 0);
    for (long long m = vi.m_min.eval<long long>(env); m <= vi.m_max.eval<long long>(env); ++m)
      out.push_back(vi.prefix + std::to_string(m));
  }
  return out;
}

std::string Catalogue::resolve_variant(const ClassInfo& c, long k,
                                       const std::string& requested) const {
  if (c.variants.empty()) {
    if (!requested.empty()) throw MemberError(c.id + " has no variants (got '" + requested + "')");
    return "";
  }
  if (requested.empty()) {  // the default, else the first variant that exists at this k
    for (const auto& vi : c.variants)
      if (vi.is_default && k >= vi.k_min) return vi.id;
    const auto here = variants_at(c, k);
    if (here.empty()) throw MemberError(c.id + " has no variant at k = " + std::to_string(k));
    return here.front();
  }
  if (variant_info(c, k, requested)) return requested;
  std::string list;
  for (const auto& v : variants_at(c, k)) list += (list.empty() ? "" : ", ") + v;
  throw MemberError(c.id + " at k = " + std::to_string(k) + " has no variant '" + requested +
                    "' (valid: " + list + ")");
}

namespace {

// A member's count (bonds or rattlers): the variant's own expression when it has one, else the
// class's; none when neither has one.
std::optional<long long> member_count(const Expression* of_variant, const Expression& of_class,
                                      long k, long p) {
  const Expression& e = (of_variant && !of_variant->empty()) ? *of_variant : of_class;
  if (e.empty()) return std::nullopt;
  return e.eval<long long>(integer_env(k, p));
}

}  // namespace

std::optional<long long> Catalogue::bonds_of(const ClassInfo& c, long k, long p,
                                             const std::string& v) const {
  const VariantInfo* vi = v.empty() ? nullptr : variant_info(c, k, v);
  return member_count(vi ? &vi->bonds : nullptr, c.bonds, k, p);
}

std::optional<long long> Catalogue::rattlers_of(const ClassInfo& c, long k, long p,
                                                const std::string& v) const {
  const VariantInfo* vi = v.empty() ? nullptr : variant_info(c, k, v);
  return member_count(vi ? &vi->rattlers : nullptr, c.rattlers, k, p);
}

std::optional<long double> Catalogue::L_of(const ClassInfo& c, long k, long p) const {
  if (c.L.empty()) return std::nullopt;
  return c.L.eval<long double>(real_env(k, p));
}

const Expression* Catalogue::closed_form_L_of(const ClassInfo& c, long k, long p) const {
  if (c.closed_form) return &c.L;
  for (const auto& e : c.closed_form_L) {
    const bool k_ok = (e.k == 0 || e.k == k);
    const bool p_ok = (e.p == 0 || e.p == p);
    if (k_ok && p_ok) return &e.L;
  }
  return nullptr;
}

}  // namespace tripack
