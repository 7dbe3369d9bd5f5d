#include <nlohmann/json.hpp>
#include <ostream>

#include "report/described.hpp"

namespace tripack::report {

// JSON: the tree as one object.
void write_json_tree(std::ostream& out, const Tree& description) {
  out << description.dump(2) << "\n";
}

}  // namespace tripack::report
