// Wall-clock timing, the one definition every layer uses.
#pragma once

#include <chrono>

namespace tripack {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Runs f, stores its wall time in `seconds`, returns its result.
template <class F>
auto timed(double& seconds, F&& f) {
  const auto start = Clock::now();
  auto result = f();
  seconds = seconds_since(start);
  return result;
}

}  // namespace tripack
