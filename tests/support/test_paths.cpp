#include "tests/support/test_paths.h"

#include <unistd.h>

#include <mutex>
#include <set>

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
  // Emptied at its first use in this process: /tmp keeps earlier runs' folders, and a reused
  // pid would otherwise find their files (a stale FIFO once failed mkfifo with EEXIST in CI).
  // Later calls in the same process keep what this run wrote.
  static std::mutex mutex;
  static std::set<std::string> emptied;
  const std::lock_guard lock(mutex);
  if (emptied.insert(name).second) std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}
}  // namespace diptych::testing
