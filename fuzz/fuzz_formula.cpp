// libFuzzer target: the catalogue's formula language (core/expression): parse, list the
// variables, evaluate in long long (integer_env: counts) and long double (real_env: lengths).
// The first byte picks k in 1..8 and p in 1..4; the rest is the formula.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string_view>

#include "constructors/catalogue.hpp"
#include "core/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tripack;
  if (size < 1) return 0;
  const long k = 1 + (data[0] & 7), p = 1 + ((data[0] >> 3) & 3);
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  Expression e;
  try {
    e = Expression::parse(text);
    (void)e.variables();
  } catch (const std::exception&) {
    return 0;
  }
  try {
    (void)e.eval(integer_env(k, p, 1));
  } catch (const std::exception&) {
  }
  try {
    (void)e.eval(real_env(k, p));
  } catch (const std::exception&) {
  }
  return 0;
}
