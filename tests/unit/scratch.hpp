// Scratch files of a test process: a directory per test binary and process, so parallel ctest
// runs never share a file.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace tripack::testing_scratch {

// A fresh database path (the file and its -wal, -shm removed) under a directory named for `area`.
inline std::string fresh_db(const std::string& area, const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("tripack_" + area + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const auto path = (dir / name).string();
  for (const char* suffix : {"", "-wal", "-shm"}) std::filesystem::remove(path + suffix);
  return path;
}

}  // namespace tripack::testing_scratch
