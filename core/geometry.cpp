#include "core/geometry.hpp"

namespace tripack {

std::string_view side_name(Side s) {
  static constexpr std::string_view kNames[] = {"bottom", "left", "right"};
  return kNames[static_cast<int>(s)];
}

}  // namespace tripack
