// libFuzzer target: the catalogue loader (Catalogue::parse on classes.yaml text), then the
// queries that evaluate its formulas at small parameters.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "constructors/catalogue.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tripack;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Catalogue cat;
  try {
    cat = Catalogue::parse(text);
  } catch (const std::exception&) {
    return 0;
  }
  for (long long N : {1LL, 5LL, 22LL}) {
    try {
      (void)cat.classify(N);
    } catch (const std::exception&) {
    }
  }
  for (const ClassInfo& c : cat.classes()) {
    for (long k = 1; k <= 3; ++k) {
      const long p = c.has_p ? 1 : 0;
      try {
        (void)cat.n_of(c, k, p);
        for (const std::string& v : cat.variants_at(c, k)) {
          (void)cat.bonds_of(c, k, p, v);
          (void)cat.rattlers_of(c, k, p, v);
        }
        (void)cat.resolve_variant(c, k, "");
        (void)cat.L_of(c, k, p);
        if (const Expression* e = cat.closed_form_L_of(c, k, p)) (void)e->eval(real_env(k, p));
      } catch (const std::exception&) {
      }
    }
  }
  return 0;
}
