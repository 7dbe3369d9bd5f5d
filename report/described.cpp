#include "report/described.hpp"

#include <ostream>
#include <stdexcept>

namespace tripack::report {

// The writers, each in its file (report/described_FORMAT.cpp).
void write_described_text(std::ostream& out, const Described& result);
void write_described_json(std::ostream& out, const Described& result);
void write_described_csv(std::ostream& out, const Described& result);

const std::vector<DescribedWriter>& described_writers() {
  static const std::vector<DescribedWriter> writers{
      {"text", write_described_text},
      {"json", write_described_json},
      {"csv", write_described_csv},
  };
  return writers;
}

void write_described(std::ostream& out, const Described& result, const std::string& format) {
  for (const auto& w : described_writers())
    if (w.format == format) return w.write(out, result);
  throw std::invalid_argument("no writer for the output format '" + format + "'");
}

}  // namespace tripack::report
