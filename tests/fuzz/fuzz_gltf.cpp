// libFuzzer harness: the glTF loader (tinygltf, our conversion, scene validation). Inputs that
// start with the binary magic "glTF" are loaded as .glb, others as .gltf.
#include <OpenImageIO/imageio.h>

#include <cstring>

#include "engine/scene/load.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  OIIO::attribute("threads", 1);  // embedded images: decode on the fuzzing thread
  OIIO::attribute("exr_threads", 0);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const auto path = diptych::fuzz::writeScratch(binary ? "scene.glb" : "scene.gltf", data, size);
  diptych::fuzz::expectCleanOutcome([&] { diptych::loadScene(path); });
  return 0;
}
