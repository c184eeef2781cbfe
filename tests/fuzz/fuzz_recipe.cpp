// libFuzzer harness: the frame-graph recipe loader (loadRecipe: file checks, JSON parse with the
// depth limit, structure). Parameter values are checked later by the passes' schemas when a
// graph is compiled, which needs the renderer; that part is not fuzzed (docs/robustness.md).
#include "engine/graph/recipe.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = diptych::fuzz::writeScratch("recipe.json", data, size);
  diptych::fuzz::expectCleanOutcome([&] { diptych::loadRecipe(path); });
  return 0;
}
