#include <ostream>

#include "report/description.hpp"

namespace tripack::report {

// JSON: the fields as one object on one line. Invalid UTF-8 (a label or a file name) is replaced,
// never thrown: a formatting problem must not discard computed results.
void write_json(std::ostream& out, const Description& description) {
  out << description.fields.dump(-1, ' ', false, Tree::error_handler_t::replace) << "\n";
}

}  // namespace tripack::report
