// A small flat result that names its fields once, the way HOOMD's logger marks quantities: a title
// and (name, value) fields, for summaries (explore, exact-atlas); report/results/summary.hpp
// describes it to every output format.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace tripack {

struct Described {
  explicit Described(std::string what) : title(std::move(what)) {}
  struct Field {
    std::string name, value;
    bool number = false;  // JSON: a number, not a string
  };
  std::string title;  // what the result is ("explore", "exact atlas")
  std::vector<Field> fields;

  Described& text(std::string name, std::string value) {
    fields.push_back({std::move(name), std::move(value), false});
    return *this;
  }
  Described& number(std::string name, std::string value) {
    fields.push_back({std::move(name), std::move(value), true});
    return *this;
  }
};

}  // namespace tripack
