#pragma once
// Source-tree paths for tests and benchmarks. The absolute paths are compiled into
// tests/support/test_paths.cpp alone, so that every other object is independent of where the
// checkout lives and ccache reuses it from any clone.
#include <filesystem>
#include <string>

namespace diptych::testing {
std::string samplesDir();       // samples/
std::string sharedScenesDir();  // ../shared/scenes (DIPTYCH_SHARED_SCENES cache variable)
std::string testsDir();         // tests/
std::string sourceShaderDir();  // shaders/
// A scratch folder for files a test writes: temp/NAME-PID. CTest runs each test case in its own
// process, in parallel, so a fixed folder would let two cases overwrite each other's files.
// The folder starts empty at its first use in a process (not later ones: a case may call it
// twice for the same files).
std::filesystem::path scratchDir(const std::string& name);
}  // namespace diptych::testing

#define DIPTYCH_SAMPLES_DIR ::diptych::testing::samplesDir()
#define DIPTYCH_SHARED_SCENES ::diptych::testing::sharedScenesDir()
#define DIPTYCH_TESTS_DIR ::diptych::testing::testsDir()
#define DIPTYCH_SOURCE_SHADER_DIR ::diptych::testing::sourceShaderDir()
