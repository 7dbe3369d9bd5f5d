// EXPECT_NEAR converts its arguments to double (ulp 1.1e-16 near 1), too coarse for long double
// coordinates and d compared to 1e-17 and below: EXPECT_TRUE(near_ld(a, b, tolerance)).
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "core/io.hpp"

namespace tripack {

inline ::testing::AssertionResult near_ld(long double a, long double b, long double tolerance) {
  const long double difference = std::fabs(a - b);
  if (difference <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << format_significant(a, 21) << " and " << format_significant(b, 21) << " differ by "
         << format_significant(difference, 3) << " > " << format_significant(tolerance, 3);
}

}  // namespace tripack
