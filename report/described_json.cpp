#include <nlohmann/json.hpp>
#include <ostream>

#include "report/described.hpp"

namespace tripack::report {

// JSON: one object; numbers as numbers, the rest as strings.
void write_described_json(std::ostream& out, const Described& result) {
  nlohmann::ordered_json j;
  j["result"] = result.title;
  for (const auto& f : result.fields)
    j[f.name] = f.number ? nlohmann::ordered_json::parse(f.value) : nlohmann::ordered_json(f.value);
  out << j.dump(2) << "\n";
}

}  // namespace tripack::report
