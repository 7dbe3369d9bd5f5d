#include "report/fields.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace tripack::report {

void write_file(const std::filesystem::path& path, const std::string& bytes) {
  errno = 0;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << bytes;
  out.close();
  if (!out) {
    const int why = errno;
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(),
                                         why ? std::strerror(why) : "write failed"));
  }
}

}  // namespace tripack::report
