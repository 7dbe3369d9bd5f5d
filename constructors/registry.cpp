#include "constructors/registry.hpp"

#include "constructors/builders.hpp"

namespace tripack {

namespace {

long arg(const ClassInfo& c, const char* name, long k, long p) {
  const auto it = c.builder_args.find(name);
  if (it == c.builder_args.end())
    throw CatalogueError(c.id + ": builder '" + c.builder + "' needs argument '" + name + "'");
  return static_cast<long>(it->second.eval<long long>(integer_env(k, p)));
}

}  // namespace

Pattern build_pattern(const Catalogue& catalogue, const BuildRequest& req) {
  const ClassInfo& c = catalogue.find(req.class_id);
  catalogue.check_parameters(c, req.k, req.p);
  const std::string variant = catalogue.resolve_variant(c, req.k, req.variant);
  Pattern pat;
  if (c.builder == "hexagonal") {
    pat = build_hexagonal(req.k);
  } else if (c.builder == "hexagonal-minus-one") {
    pat = build_hexagonal_minus_one(req.k);
  } else if (c.builder == "four-delta") {
    pat = build_four_delta(req.k);
  } else if (c.builder == "twin") {
    long cavity = 0;
    if (variant == "full")
      cavity = req.k;
    else if (variant.rfind("cavity-", 0) == 0)
      cavity = std::stol(variant.substr(7));
    pat = build_twin(req.k, cavity);
  } else if (c.builder == "chain-family") {
    ChainFamilyShape shape;
    shape.q = arg(c, "q", req.k, req.p);
    shape.block = arg(c, "block", req.k, req.p);
    shape.separator = static_cast<int>(arg(c, "separator", req.k, req.p));
    pat = build_chain_family(shape);
  } else if (c.builder == "odd-ripple") {
    pat = variant == "other" ? build_odd_ripple_other(req.k) : build_odd_ripple_depressed(req.k);
  } else if (c.builder == "sparse-corner") {
    pat = build_sparse_corner(req.k);
  } else {
    throw CatalogueError(c.id + ": unknown builder '" + c.builder + "' in the catalogue");
  }
  pat.provenance = {c.id, req.k, req.p, variant};
  return pat;
}

}  // namespace tripack
