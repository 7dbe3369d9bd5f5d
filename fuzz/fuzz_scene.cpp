// libFuzzer target: the scene YAML (parse_scene, which validates, then validate_scene again on
// the result). Relative file paths resolve in an empty directory, so `initial: FILE` only reaches
// the error path unless the input names an absolute path.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "sim/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace tripack;
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = parse_scene(text, "/nonexistent-tripack-fuzz-dir");
    validate_scene(scene);
  } catch (const std::exception&) {
  }
  return 0;
}
