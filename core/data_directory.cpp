#include "core/data_directory.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <stdexcept>

namespace tripack {

namespace {

namespace fs = std::filesystem;

bool holds_data(const fs::path& dir) {
  std::error_code ec;
  return fs::exists(dir / "classes.yaml", ec);
}

// The file this code was loaded from: the program, or the Python module (python/) that links
// the library into another program (/usr/bin/python3), whose own directory says nothing.
fs::path loaded_object() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&data_directory), &info) && info.dli_fname &&
      *info.dli_fname) {
    std::error_code ec;
    const auto path = fs::canonical(info.dli_fname, ec);
    if (!ec) return path;
  }
  return {};
}

}  // namespace

std::filesystem::path data_directory() {
  if (const char* env = std::getenv("TRIPACK_DATA"); env && *env) return env;
  std::error_code ec;
  const auto exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec)
    for (const auto& dir : {exe.parent_path().parent_path() / "share" / "tripack",
                            exe.parent_path() / "share" / "tripack"})
      if (holds_data(dir)) return dir;
  // The module: build/python/tripack/_tripack.so beside build/share/tripack, or installed under
  // PREFIX/lib/python3/dist-packages/tripack beside PREFIX/share/tripack.
  if (const auto object = loaded_object(); !object.empty())
    for (auto dir = object.parent_path(); dir.has_relative_path(); dir = dir.parent_path())
      if (holds_data(dir / "share" / "tripack")) return dir / "share" / "tripack";
  throw std::runtime_error(
      "cannot find tripack's data (share/tripack/classes.yaml beside the program): set "
      "TRIPACK_DATA to that directory");
}

}  // namespace tripack
