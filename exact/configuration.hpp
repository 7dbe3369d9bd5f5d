// Statement (I) of docs/exact.md, by the algebraic route: a number field K = Q(t) holding d,
// sqrt(3) and every coordinate of the packing's non-rattlers (each found by an integer relation
// and confirmed from twice the digits), every bond verified as an identity in K, and at the real
// embedding t0 (an isolated root of K's polynomial) the exact points within 10^-25 of the given
// packing, every non-bond pair farther than d and every centre inside the triangle, checked in
// Arb ball arithmetic.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/packing.hpp"
#include "exact/algebraic.hpp"

namespace tripack::exact {

struct ConfigurationInput {
  int n = 0;
  std::vector<Bond> bonds;                         // disk pairs and walls (core/packing.hpp)
  std::vector<int> rattlers;                       // 0-based
  std::string d;                                   // d to 2D digits
  std::vector<std::array<std::string, 2>> points;  // unit-triangle coordinates to 2D digits
  std::vector<std::array<std::string, 2>> given;   // the packing as given (e.g. an atlas file)
  int digits = 0;                                  // D
};

struct ExactConfiguration {
  bool proven = false;
  std::string reason;       // what stopped it
  IntegerPolynomial field;  // K(t), irreducible over Q (checked)
  IsolatedRoot embedding;   // t0
  RationalPolynomial d_in_field, sqrt3_in_field;
  // Non-rattlers: polynomials in t; rattlers: constants (their given centred place, 40 digits).
  std::vector<std::array<RationalPolynomial, 2>> points;
  double largest_offset = 0;   // max |exact - given| over the coordinates at t0 (upper bound)
  double smallest_margin = 0;  // min over non-bonds of (distance - d) / d and of wall clearances
                               // / d at t0 (a lower bound)
};

ExactConfiguration prove_existence(const ConfigurationInput& input, const MinimalPolynomial& d);

}  // namespace tripack::exact
