#include "core/option_values.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace tripack {

namespace {

// The whole of `text` read by `read` (std::stoll, std::stold), or nothing.
template <class T, class Read>
std::optional<T> whole(const std::string& text, Read read) {
  std::size_t used = 0;
  try {
    const T v = read(text, &used);
    if (used > 0 && used == text.size()) return v;
  } catch (...) {
  }
  return std::nullopt;
}

}  // namespace

std::pair<long long, long long> parse_range(const std::string& text, const std::string& option) {
  auto number = [&](const std::string& t) {
    const auto v = whole<long long>(
        t, [](const std::string& s, std::size_t* used) { return std::stoll(s, used); });
    if (!v) throw std::invalid_argument(option + " expects a number or A..B, got '" + text + "'");
    return *v;
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
  const auto v = whole<long double>(
      text, [](const std::string& s, std::size_t* used) { return std::stold(s, used); });
  if (!v || !(*v > 0) || !std::isfinite(*v))
    throw std::invalid_argument(option + " must be a positive decimal number, not '" + text + "'");
  return *v;
}

std::string option_bound(double value) {
  // Whole numbers below 2^53 are exact doubles: printed as integers, never "2.000000" or "1e+07".
  if (std::isfinite(value) && value == std::trunc(value) && std::fabs(value) < 0x1p53)
    return fmt::format("{}", static_cast<long long>(value));
  return fmt::format("{}", value);
}

std::string option_range(double min, double max) {
  return option_bound(min) + " to " + option_bound(max);
}

}  // namespace tripack
