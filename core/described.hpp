// A result that names its fields once, the way HOOMD's logger marks quantities: a title and
// (name, value) fields. Any output format renders any described result (report/described.hpp), so
// a new output format is one writer, not one function per result type.
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
