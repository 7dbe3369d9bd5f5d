#include "core/option_values.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace tripack {

std::pair<long long, long long> parse_range(const std::string& text, const std::string& option) {
  auto number = [&](const std::string& t) {
    std::size_t used = 0;
    long long v = 0;
    try {
      v = std::stoll(t, &used);
    } catch (...) {
      used = 0;
    }
    if (used == 0 || used != t.size())
      throw std::invalid_argument(option + " expects a number or A..B, got '" + text + "'");
    return v;
  };
  const auto dots = text.find("..");
  if (dots == std::string::npos) {
    const long long k = number(text);
    return {k, k};
  }
  const long long a = number(text.substr(0, dots)), b = number(text.substr(dots + 2));
  if (b < a) throw std::invalid_argument(option + " range " + text + " is empty");
  return {a, b};
}

std::vector<long long> parse_range_list(const std::string& text, const std::string& option) {
  std::vector<long long> values;
  std::stringstream items(text);
  for (std::string item; std::getline(items, item, ',');) {
    const auto [a, b] = parse_range(item, option);
    for (long long v = a; v <= b; ++v) values.push_back(v);
  }
  if (values.empty()) throw std::invalid_argument(option + " is empty");
  return values;
}

long double positive_decimal(const std::string& text, const std::string& option) {
  std::size_t used = 0;
  long double v = 0;
  try {
    v = std::stold(text, &used);
  } catch (...) {
    used = 0;
  }
  if (used != text.size() || used == 0 || !(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(option + " must be a positive decimal number, not '" + text + "'");
  return v;
}

}  // namespace tripack
