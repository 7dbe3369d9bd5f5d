#include <ostream>

#include "report/described.hpp"

namespace tripack::report {

// Text: the title, then one "name: value" line per field.
void write_described_text(std::ostream& out, const Described& result) {
  out << result.title << "\n";
  for (const auto& f : result.fields) out << "  " << f.name << ": " << f.value << "\n";
}

}  // namespace tripack::report
