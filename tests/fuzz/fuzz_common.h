#pragma once
// Shared by the libFuzzer harnesses (docs/robustness.md): each writes the input to a scratch
// file (the loaders take paths, and the file checks are part of what is tested) and calls the
// loader. An input error (diptych::Error) is the expected outcome for most inputs; anything
// else escaping (another exception, a crash, a sanitizer report, a leak) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"

namespace diptych::fuzz {

// A file in a per-process folder (parallel fuzzing jobs must not share it), in memory when
// /dev/shm exists.
inline std::filesystem::path scratchFile(const std::string& name) {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    auto d = base / ("diptych-fuzz-" + std::to_string(getpid()));
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir / name;
}

inline std::filesystem::path writeScratch(const std::string& name, const std::uint8_t* data,
                                          std::size_t size) {
  const std::filesystem::path p = scratchFile(name);
  std::ofstream(p, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return p;
}

// Runs `load`; only diptych's own errors (InputError and Error: one named line) are accepted.
template <typename F>
void expectCleanOutcome(F&& load) {
  try {
    load();
  } catch (const diptych::Error&) {
  }
}

}  // namespace diptych::fuzz
