// Q(d, sqrt 3) as the tower Q(d)[s]/(s^2 - 3) (docs/exact.md, statement (I) step 1): an element
// a(d) + sqrt3 b(d) with a, b in Q[d]/(P). Coordinates are found in this basis, whose
// coefficients stay small, and certificates of format 3 are written in it: in the power basis
// of t = d + j sqrt 3 the same numbers need thousands of digits.
#pragma once

#include <optional>
#include <vector>

#include "exact/algebraic.hpp"
#include "exact/configuration.hpp"
#include "exact/flint_tools.hpp"

namespace tripack::exact {

struct TowerElement {
  flint::FmpqPoly a, b;
};

class Tower {
 public:
  Tower(const fmpz_poly_t p, int j);
  int m() const { return m_; }
  int j() const { return j_; }
  // out = x * (d + j s); out may be x.
  void times_theta(TowerElement& out, const TowerElement& x) const;
  // Entry r of the coordinate vector (a_0 .. a_{m-1}, b_0 .. b_{m-1}).
  void coordinate(fmpq_t out, const TowerElement& x, int r) const;
  // e(t) in the tower, t = d + j s (Horner; exact).
  void from_power_basis(TowerElement& out, const fmpq_poly_t e) const;

 private:
  flint::FmpqPoly p_;
  int m_ = 0, j_ = 1;
};

// A tower element as plain strings: a(x) + s b(x), x = d, s = sqrt 3.
struct TowerForm {
  RationalPolynomial a, b;
};

// The j of K's generator t = d + j sqrt 3 (j = 1..5) when the configuration's field is Q(d,
// sqrt 3) of degree 2 deg P given that way (t - d_in_K = j sqrt3_in_K exactly); none otherwise
// (K = Q(d), or a field grown beyond Q(d, sqrt 3)).
std::optional<int> tower_generator(const IntegerPolynomial& p, const ExactConfiguration& c);

// Elements of K (polynomials in t) in the tower basis of K's generator t = d + j sqrt 3.
std::vector<TowerForm> tower_forms(const IntegerPolynomial& p, int j,
                                   const std::vector<const RationalPolynomial*>& elements);

// The elements divided by one positive rational, so that every coefficient is an integer and
// they have no common factor (a stress, defined up to a positive factor).
void make_primitive(std::vector<TowerForm>& elements);

// PARI/GP text of a(x) + s b(x), each part written as its rational content times a primitive
// integer polynomial ("3/7*(2*x^2 - 1) + 5*s*(x + 4)"): in a stress the content is the large
// part of every coefficient (t59a: 4,000-digit contents, primitive parts of a few digits), so
// it is written once per part, not once per coefficient.
std::string tower_pari(const TowerForm& element);

}  // namespace tripack::exact
