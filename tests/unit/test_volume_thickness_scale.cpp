// KHR_materials_volume's thicknessFactor is in the mesh's own units (glTF 2.0 spec of the
// extension): the loader scales it into world units by cbrt |det| of each instance's transform
// (engine/scene/gltf/volume_scale.cpp), splitting a material placed at several scales.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Scene loadTriangles(const nlohmann::json& nodes) {
  const auto dir = testing::scratchDir("volume_scale");
  const float tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::ofstream(dir / "tri.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(tri), sizeof tri);
  const nlohmann::json volume = {
      {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 1.0}}}};
  const nlohmann::json gltf = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_materials_volume"}},
      {"buffers", {{{"uri", "tri.bin"}, {"byteLength", 36}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 36}}}},
      {"accessors",
       {{{"bufferView", 0},
         {"componentType", 5126},
         {"count", 3},
         {"type", "VEC3"},
         {"min", {0, 0, 0}},
         {"max", {1, 1, 0}}}}},
      {"materials", {{{"name", "glass"}, {"extensions", volume}}, {{"name", "thin"}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 0}}}}},
        {{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 1}}}}}}},
      {"nodes", nodes},
      {"scenes", {{{"nodes", nlohmann::json::array({0, 1, 2, 4})}}}},
      {"scene", 0}};
  std::ofstream(dir / "scene.gltf") << gltf.dump();
  return loadScene(dir / "scene.gltf");
}

float thicknessOf(const Scene& s, const Instance& i) {
  return s.materials[std::size_t(s.meshes[std::size_t(i.mesh)].material)].thickness;
}

TEST(VolumeThicknessScale, ThicknessFollowsTheNodeScaleAndSplitsAcrossScales) {
  const nlohmann::json nodes = {
      {{"mesh", 0}, {"scale", {2, 2, 2}}},                                  // 0.5 * 2
      {{"mesh", 0}, {"scale", {1, 2, 4}}, {"translation", {5, 0, 0}}},      // cbrt 8 = 2: same
      {{"scale", {3, 3, 3}}, {"children", {3}}},                            // parent scale 3
      {{"mesh", 0}, {"translation", {-2, 0, 0}}},                           // inherits 3: 1.5
      {{"mesh", 1}, {"scale", {10, 10, 10}}, {"translation", {0, 7, 0}}}};  // thin: stays 0
  const Scene s = loadTriangles(nodes);
  ASSERT_EQ(s.instances.size(), 4u);
  // Instances by their world translation (the loader's traversal order is its own).
  auto at = [&](vec3 t) -> const Instance& {
    for (const Instance& i : s.instances)
      if (glm::length(vec3(i.transform[3]) - t) < 1e-5f) return i;
    ADD_FAILURE() << "no instance at " << t.x << " " << t.y << " " << t.z;
    return s.instances[0];
  };
  const Instance &doubled = at(vec3(0.f)), &stretched = at(vec3(5.f, 0.f, 0.f));
  const Instance &child = at(vec3(-6.f, 0.f, 0.f)), &thin = at(vec3(0.f, 7.f, 0.f));
  EXPECT_NEAR(thicknessOf(s, doubled), 1.f, 1e-5f);
  EXPECT_NEAR(thicknessOf(s, stretched), 1.f, 1e-5f);
  EXPECT_EQ(doubled.mesh, stretched.mesh);
  // The instance under the scaled parent gets its own copy of the mesh and the material.
  EXPECT_NE(child.mesh, doubled.mesh);
  EXPECT_NEAR(thicknessOf(s, child), 1.5f, 1e-5f);
  EXPECT_EQ(s.materials.size(), 3u);
  EXPECT_EQ(thicknessOf(s, thin), 0.f);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
