// Errors a user reads on one line (tests/unit/test_plot.cpp, tests/unit/test_diagram.cpp).
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>

namespace tripack {

// f throws a std::runtime_error whose message is one line and holds each of `parts`.
inline void expect_one_line_error(const std::function<void()>& f,
                                  std::initializer_list<std::string> parts) {
  try {
    f();
    std::string expected;
    for (const std::string& part : parts) expected += (expected.empty() ? "'" : ", '") + part + "'";
    ADD_FAILURE() << "no error; expected one containing " << expected;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    for (const std::string& part : parts) EXPECT_NE(what.find(part), std::string::npos) << what;
  }
}

}  // namespace tripack
