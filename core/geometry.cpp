#include "core/geometry.hpp"

namespace tripack {

std::string_view side_name(Side s) {
  switch (s) {
    case Side::Bottom:
      return "bottom";
    case Side::Left:
      return "left";
    case Side::Right:
      return "right";
  }
  return "?";
}

}  // namespace tripack
