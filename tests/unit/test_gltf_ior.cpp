// KHR_materials_ior on a glTF file (samples/scenes/blender-point-light.gltf, its Ground material
// edited here): the extension's schema has a minimum of 1. Below it a positive IOR is used as
// given and the load says so once, naming the place; 0 is the extension's special case (an
// infinite IOR); below 0 is an error (validation).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

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

// The ratified extension allows 0 as a special case: the specular-glossiness compatibility mode,
// whose effective IOR is +infinity and whose Fresnel term is 1 at every angle. It loads without a
// warning, the dielectric F0 is 1 on both sides' shared formulas, a transmissive material lets
// nothing through, and a refraction at eta = 1/0 or 0 stays finite.
TEST(GltfIor, ZeroIsTheInfiniteIorOfTheSpecularGlossinessMode) {
  const Scene zero = loadScene(withGroundIor(0.0, "zero"));
  EXPECT_TRUE(iorWarnings(zero).empty());
  const Material* ground = nullptr;
  for (const Material& m : zero.materials)
    if (m.name == "Ground") ground = &m;
  ASSERT_NE(ground, nullptr);
  EXPECT_EQ(ground->ior, 0.f);
  shading::ShadingMaterial m = shading::toShadingMaterial(*ground);
  m.metallic = 0.f;
  m.specularWeight = 1.f;
  m.specularTint = vec3(1.f);
  m.baseColor = vec3(0.8f);
  m.transmission = 1.f;
  EXPECT_EQ(shading::pbrDielectricF0(m), vec3(1.f));
  EXPECT_EQ(gltfPbrToLecture(vec3(0.8f), 0.f, 0.f, 0.f, 0.f).ks, 1.f);  // F0's luminance
  const vec3 n(0.f, 0.f, 1.f);
  for (const vec3 v : {vec3(0.f, 0.f, 1.f), glm::normalize(vec3(1.f, 0.f, 0.05f))}) {
    const shading::SecondaryWeights w = shading::pbrSecondaryWeights(m, n, v);
    EXPECT_EQ(w.transmission, vec3(0.f)) << "Fresnel 1: nothing passes at n.v " << v.z;
  }
  for (const float eta : {1.f / ground->ior, ground->ior}) {  // entering, leaving
    const shading::Refraction t =
        shading::refractLecture(glm::normalize(vec3(0.3f, 0.f, 1.f)), n, eta);
    EXPECT_TRUE(std::isfinite(t.t.x) && std::isfinite(t.t.y) && std::isfinite(t.t.z)) << eta;
  }
  m.ior = 1.5f;  // the control: an ordinary dielectric lets light through
  EXPECT_GT(shading::pbrSecondaryWeights(m, n, n).transmission.x, 0.5f);
}

TEST(GltfIor, NegativeIsAnErrorNamingTheMaterial) {
  try {
    loadScene(withGroundIor(-1.0, "negative"));
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("ior"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("negative.gltf: materials["), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("].extensions.KHR_materials_ior.ior"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("positive, or 0"), std::string::npos) << e.what();
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
