// Where tripack's installed data is (classes.yaml, the atlas, the accuracy study's hard cases):
// never the source tree. $TRIPACK_DATA when set; else share/tripack of the installation
// (PREFIX/bin/tripack -> PREFIX/share/tripack) or of the build tree (the build copies it there).
#pragma once

#include <filesystem>

namespace tripack {

// Throws a one-line std::runtime_error when none holds classes.yaml.
std::filesystem::path data_directory();

}  // namespace tripack
