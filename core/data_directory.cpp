#include "core/data_directory.hpp"

#include <cstdlib>
#include <stdexcept>

namespace tripack {

std::filesystem::path data_directory() {
  if (const char* env = std::getenv("TRIPACK_DATA"); env && *env) return env;
  std::error_code ec;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const auto& dir : {exe.parent_path().parent_path() / "share" / "tripack",
                            exe.parent_path() / "share" / "tripack"})
      if (std::filesystem::exists(dir / "classes.yaml")) return dir;
  throw std::runtime_error(
      "cannot find tripack's data (share/tripack/classes.yaml beside the program): set "
      "TRIPACK_DATA to that directory");
}

}  // namespace tripack
