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

// A bound of an option's range as errors and the help show it: a whole number without a
// fraction ("2", "100000", for an integer option and a real alike), any other real in the
// shortest form that reads back as the same double ("0.001", "1e-300").
std::string option_bound(double value);
// "MIN to MAX" in those forms, as the range errors end: "Value 1 not in range 2 to 100000".
std::string option_range(double min, double max);

}  // namespace tripack
