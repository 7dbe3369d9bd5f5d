// Number fields through PARI's C library (libpari), private to exact/: what an integer relation
// in a fixed basis cannot reach. A coordinate whose coefficients in the basis of K are too large
// for the digits (t126a's x_51: 108 digits in t's powers, while its minimal polynomial over Q has
// 33) is found exactly as a root of that minimal polynomial in K (nfroots), and one outside K
// makes K larger (nffactor, rnfequation). PARI only finds candidates: every element is verified
// afterwards by tripack's own exact arithmetic (FLINT) and the independent checker.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "exact/algebraic.hpp"

namespace tripack::exact::pari {

// A PARI error (its message), or a request PARI cannot take.
struct Error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The roots in K = Q[t]/(field(t)) (field irreducible, any leading coefficient) of the
// polynomial q with integer coefficients, each as a polynomial in t of degree < deg field.
std::vector<RationalPolynomial> roots_in_field(const IntegerPolynomial& field,
                                               const IntegerPolynomial& q);

// The irreducible factors over K of q (PARI's nffactor), each monic and given by its
// coefficients in K (polynomials in t), constant term first.
std::vector<std::vector<RationalPolynomial>> factors_over_field(const IntegerPolynomial& field,
                                                                const IntegerPolynomial& q);

// K' = K[w]/(f(w)) for an irreducible factor f over K (coefficients in K, constant first, monic):
// its polynomial over Q (PARI's rnfequation: a primitive element theta = w + shift t, shift an
// integer), and t, w as polynomials in theta.
struct Extension {
  IntegerPolynomial field;  // K'(theta), monic
  RationalPolynomial t, w;  // the old generator and the new element in K'
  std::string shift;        // theta = w + shift t
};
Extension extend_field(const IntegerPolynomial& field, const std::vector<RationalPolynomial>& f);

}  // namespace tripack::exact::pari
