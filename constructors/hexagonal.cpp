// Class 1: Delta(k) (Oler 1961) and Delta(k) - 1 (Newman's conjecture).
#include <stdexcept>

#include "constructors/blocks.hpp"
#include "constructors/builders.hpp"
#include "constructors/registry.hpp"

namespace tripack {

namespace {
using E = Sqrt3Directions;
}

Pattern build_hexagonal(long k) {
  if (k < 2) throw std::invalid_argument("Delta(k) needs k >= 2");
  DiskUnitsPattern pat(HalfSurd3::integer(k - 1));
  pat.add_triangle(Sqrt3Point{}, E::e0, E::e60, k);
  return pat.finish({});
}

Pattern build_hexagonal_minus_one(long k) {
  if (k < 2) throw std::invalid_argument("Delta(k)-1 needs k >= 2");
  DiskUnitsPattern pat(HalfSurd3::integer(k - 1));
  pat.add_triangle(Sqrt3Point{}, E::e0, E::e60, k);
  pat.erase(0);  // the bottom-left corner disk
  return pat.finish({});
}

namespace {
const BuilderRegistration kHexagonal{"hexagonal",
                                     [](const BuilderCall& c) { return build_hexagonal(c.k); }};
const BuilderRegistration kHexagonalMinusOne{
    "hexagonal-minus-one", [](const BuilderCall& c) { return build_hexagonal_minus_one(c.k); }};
}  // namespace

}  // namespace tripack
