// Precision has one owner: a real number knows how many significant digits it is known to.
// Values come either from long double arithmetic (kLongDoubleDigits) or from an MPFR polish
// (its decimal text, any number of digits); every writer asks the value for the digits it wants
// and gets at most what is known.
#pragma once

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace tripack {

// Significant digits a long double result of the pipeline is trusted to (x87 64-bit mantissa:
// 19.3 digits, less the polish's last-bit noise).
inline constexpr int kLongDoubleDigits = 18;
// Digits that write a long double so it reads back bit for bit.
inline constexpr int kLongDoubleRoundTripDigits = 21;

// How many significant digits a decimal text holds (leading zeros, sign and point not counted;
// an exponent ends it).
int significant_digits(const std::string& text);

// Decimal string of a long double with `digits` significant digits.
std::string format_significant(long double value, int digits);

// A real number and the digits it is known to.
class PreciseReal {
 public:
  PreciseReal() = default;
  // From long double arithmetic: known to kLongDoubleDigits.
  explicit PreciseReal(long double value) : value_(value) {}
  // From a multiprecision computation: `text` holds `digits` significant digits.
  PreciseReal(long double value, std::string text, int digits)
      : value_(value), text_(std::move(text)), digits_(digits) {}

  long double value() const { return value_; }
  int digits() const { return text_.empty() ? kLongDoubleDigits : digits_; }
  bool multiprecision() const { return !text_.empty(); }
  // `wanted` significant digits, or all that are known when fewer.
  std::string str(int wanted) const {
    if (!text_.empty() && wanted >= kLongDoubleDigits && digits_ >= wanted)
      return wanted == digits_ ? text_ : round_text(wanted);
    if (!text_.empty() && wanted > kLongDoubleDigits) return text_;
    return format_significant(value_, std::min(wanted, kLongDoubleDigits));
  }
  std::string str() const { return str(digits()); }

 private:
  std::string round_text(int wanted) const;
  long double value_ = 0;
  std::string text_;
  int digits_ = 0;
};

// Coordinates beyond long double (an MPFR polish): decimal strings per point, x then y.
using PrecisePoints = std::vector<std::array<std::string, 2>>;

}  // namespace tripack
