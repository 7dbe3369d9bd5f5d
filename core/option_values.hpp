// Values as the command line writes them, parsed in one place: integer ranges ("K", "A..B", or a
// comma-separated list of them: "254,255,260..262") and positive decimals. Errors name the option
// and are one line.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tripack {

// "K" or "A..B" (A <= B).
std::pair<long long, long long> parse_range(const std::string& text, const std::string& option);
// A comma-separated list of ranges, every value in order (duplicates kept). Throws when empty.
std::vector<long long> parse_range_list(const std::string& text, const std::string& option);
// A positive finite decimal number ("0.4" or "4e-1"), to long double.
long double positive_decimal(const std::string& text, const std::string& option);

}  // namespace tripack
