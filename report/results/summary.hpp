// A result whose fields are few and flat (core/described.hpp): the explorer's and the exact atlas's
// summaries. No text view of its own: every writer prints its fields by name.
#pragma once

#include "core/described.hpp"
#include "report/render.hpp"

namespace tripack::report {

template <>
struct View<Described> {
  static Description describe(const Described& result, const DescribeOptions&) {
    Description d;
    d.fields["result"] = result.title;
    for (const auto& f : result.fields)
      d.fields[f.name] = f.number ? Tree::parse(f.value) : Tree(f.value);
    return d;
  }
};

}  // namespace tripack::report
