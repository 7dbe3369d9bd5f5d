// Wall-clock timing, the one definition every layer uses.
#pragma once

#include <chrono>
#include <ctime>

namespace tripack {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// CPU seconds this thread has used (CLOCK_THREAD_CPUTIME_ID): what a search step costs when
// the machine is shared, which wall time does not tell.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// CPU seconds of every thread of the process (CLOCK_PROCESS_CPUTIME_ID): what a multi-threaded
// stage cost, where thread_cpu_seconds would miss its workers.
inline double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
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
