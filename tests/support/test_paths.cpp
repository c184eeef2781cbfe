#include "tests/support/test_paths.h"

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
