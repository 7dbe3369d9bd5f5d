// Exact d(n) (docs/exact.md): the minimal polynomial of a number known to many digits, found by an
// integer relation (LLL, FLINT) and accepted only when it uses far fewer digits than are
// available and comes out again from twice the digits; then proven irreducible (FLINT's exact
// factorisation over Z) and its root isolated in a rational interval (proven with exact signs and
// Arb ball arithmetic). FLINT and Arb live only in exact/*.cpp; this interface is plain strings.
#pragma once

#include <string>
#include <vector>

namespace tripack::exact {

// A polynomial with integer coefficients (decimal strings of any size), constant term first.
struct IntegerPolynomial {
  std::vector<std::string> coefficients;
  int degree() const { return static_cast<int>(coefficients.size()) - 1; }
  // PARI/GP syntax, highest power first: "3*x^2 - 1".
  std::string pari(const std::string& variable = "x") const;
  // Decimal digits of the largest coefficient.
  int height_digits() const;
};

// A polynomial with rational coefficients ("p/q" or "p"), constant term first; an element of a
// number field Q[t]/(K) when reduced modulo K.
struct RationalPolynomial {
  std::vector<std::string> coefficients;
  std::string pari(const std::string& variable = "t") const;
};

// Exactly one real root of a polynomial lies in [low, high] (rationals "p/q"): proven by the
// exact signs of the polynomial at both ends and a derivative that excludes 0 on the interval.
struct IsolatedRoot {
  std::string low, high;
};

struct MinimalPolynomial {
  bool found = false;
  IntegerPolynomial polynomial;  // primitive, leading coefficient > 0, irreducible over Q
  IsolatedRoot root;             // the value's root, width about 10^-(digits/2)
  int lattice_degree = 0;        // the degree of the relation search that found it
  int digits = 0;                // digits the relation was found with
  int confirmed_digits = 0;      // the same polynomial again from this many digits
  double relation_digits = 0;    // (degree + 1) * log10(height): what the relation "uses"
  std::string reason;            // why none was found
};

// `value`: a real number to 2D significant digits (fixed or scientific notation); the search uses
// its first D = digits and confirms with all 2D. Lattice degrees 1, 2, 3, 4, 6, 8, 12, 16, 24,
// 32, 48, 64, ... up to max_degree; a relation counts when (degree + 1) log10(height) is below
// half the digits used, its vanishing irreducible factor is found again from 2D digits, and that
// factor vanishes at the value to 2D digits. Throws std::invalid_argument for a bad value.
MinimalPolynomial minimal_polynomial(const std::string& value, int digits, int max_degree);

}  // namespace tripack::exact
