// libFuzzer harness: the JSON scene loader and scene validation (loadScene on a .json file).
#include "engine/scene/load.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = diptych::fuzz::writeScratch("scene.json", data, size);
  diptych::fuzz::expectCleanOutcome([&] { diptych::loadScene(path); });
  return 0;
}
