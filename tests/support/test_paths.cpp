#include "tests/support/test_paths.h"

#include <unistd.h>

namespace diptych::testing {
std::string samplesDir() {
  return DIPTYCH_SAMPLES_DIR_VALUE;
}
std::string sharedScenesDir() {
  return DIPTYCH_SHARED_SCENES_VALUE;
}
std::string testsDir() {
  return DIPTYCH_TESTS_DIR_VALUE;
}
std::string sourceShaderDir() {
  return DIPTYCH_SOURCE_SHADER_DIR_VALUE;
}
}  // namespace diptych::testing

namespace diptych::testing {
std::filesystem::path scratchDir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace diptych::testing
