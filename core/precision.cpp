#include "core/precision.hpp"

#include <fmt/format.h>

namespace tripack {

std::string format_significant(long double value, int digits) {
  return fmt::format("{:.{}Lg}", value, digits);
}

int significant_digits(const std::string& text) {
  int count = 0;
  bool leading = true;
  for (char c : text) {
    if (c == 'e' || c == 'E') break;
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++count;
  }
  return count;
}

// The text rounded half up to `wanted` significant digits (the text is a fixed-notation decimal
// from the MPFR polish: optional sign, digits, optional point; no exponent).
std::string PreciseReal::round_text(int wanted) const {
  std::string s = text_;
  const bool negative = !s.empty() && s[0] == '-';
  std::string body = negative ? s.substr(1) : s;
  const auto point = body.find('.');
  std::string digits = body;
  if (point != std::string::npos) digits.erase(point, 1);
  const auto first = digits.find_first_not_of('0');
  if (first == std::string::npos) return text_;
  const std::size_t cut = first + static_cast<std::size_t>(wanted);
  if (cut >= digits.size()) return text_;
  const bool up = digits[cut] >= '5';
  digits.resize(cut);
  std::size_t integer = point == std::string::npos ? body.size() : point;
  if (up) {
    std::size_t i = digits.size();
    while (i > 0 && digits[i - 1] == '9') digits[--i] = '0';
    bool longer = i <= first;  // 0.999.. -> 1.000..: one significant digit more than asked
    if (i == 0) {
      digits.insert(digits.begin(), '1');
      ++integer;
    } else {
      ++digits[i - 1];
    }
    if (longer && digits.size() > integer) digits.pop_back();
  }
  while (digits.size() < integer) digits += '0';  // rounded within the integer part
  std::string out = digits.substr(0, integer);
  if (out.empty()) out.push_back('0');  // (push_back/append: GCC 12 -Wrestrict false positive on +)
  if (digits.size() > integer) out.append(1, '.').append(digits, integer);
  if (negative) out.insert(out.begin(), '-');
  return out;
}

}  // namespace tripack
