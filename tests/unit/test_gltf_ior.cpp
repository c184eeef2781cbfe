// KHR_materials_ior on a glTF file (samples/scenes/blender-point-light.gltf, its Ground material
// edited here): the extension's schema has a minimum of 1. Below it a positive IOR is used as
// given and the load says so once, naming the place; 0 and below are errors (validation).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace {

namespace fs = std::filesystem;

fs::path withGroundIor(double ior, const std::string& name) {
  const fs::path dir = testing::scratchDir("gltf_ior");
  nlohmann::json gltf;
  std::ifstream(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "blender-point-light.gltf") >> gltf;
  for (nlohmann::json& m : gltf["materials"])
    if (m["name"] == "Ground") m["extensions"]["KHR_materials_ior"] = {{"ior", ior}};
  gltf["extensionsUsed"].push_back("KHR_materials_ior");
  const fs::path file = dir / (name + ".gltf");  // buffers are data URIs: the copy stands alone
  std::ofstream(file) << gltf.dump();
  return file;
}

std::vector<std::string> iorWarnings(const Scene& s) {
  std::vector<std::string> out;
  for (const std::string& w : s.warnings)
    if (w.find("KHR_materials_ior") != std::string::npos) out.push_back(w);
  return out;
}

TEST(GltfIor, BelowOneIsUsedAsGivenAndSaidOnce) {
  const Scene below = loadScene(withGroundIor(0.75, "below"));
  const auto warnings = iorWarnings(below);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("below.gltf: materials["), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("].extensions.KHR_materials_ior.ior: 0.75 is below"),
            std::string::npos)
      << warnings[0];
  bool found = false;
  for (const Material& m : below.materials) {
    if (m.name != "Ground") continue;
    found = true;
    EXPECT_EQ(m.ior, 0.75f);
  }
  EXPECT_TRUE(found);

  EXPECT_TRUE(iorWarnings(loadScene(withGroundIor(1.33, "water"))).empty());
  EXPECT_TRUE(iorWarnings(loadScene(withGroundIor(1.0, "one"))).empty());
}

TEST(GltfIor, ZeroIsAnErrorNamingTheMaterial) {
  try {
    loadScene(withGroundIor(0.0, "zero"));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ior"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("positive"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace diptych
