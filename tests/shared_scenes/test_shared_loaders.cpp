// Every glTF file under the shared scenes folder, loaded through loadScene: it either loads
// (meshes > 0, finite bounds) or fails with the named error this table expects.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include "engine/core/error.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

const fs::path kShared = DIPTYCH_SHARED_SCENES;

// Expected outcome per file (path relative to the shared folder). Files not listed must load
// cleanly. `errorParts`: substrings the InputError text must contain; `warningPart`: a
// substring at least one Scene::warnings entry must contain.
struct Expected {
  std::vector<std::string> errorParts;
  std::string warningPart;
};

const std::map<std::string, Expected>& expectations() {
  static const std::map<std::string, Expected> table = {
      {"edge-cases-assimp/BoxWithInfinites.glb",
       {{"BoxWithInfinites.glb", "meshes[0].primitives[0].attributes.POSITION", "non-finite"}, ""}},
      // Zero normals are recovered (recomputed from the faces), not rejected.
      {"edge-cases-assimp/BoxBadNormals.glb", {{}, "zero-length normals replaced"}},
      {"edge-cases-assimp/IndexOutOfRange/IndexOutOfRange.gltf",
       {{"meshes[0].primitives[0].indices", "out of range"}, ""}},
      {"edge-cases-assimp/IndexOutOfRange/AllIndicesOutOfRange.gltf",
       {{"meshes[0].primitives[0].indices", "out of range"}, ""}},
      {"edge-cases-assimp/RecursiveNodes.gltf",
       {{"RecursiveNodes.gltf", "node cycle", "nodes[0]", "nodes[1]"}, ""}},
      {"edge-cases-tinygltf/BoundsChecking/integer-out-of-bounds.gltf", {{"tinygltf"}, ""}},
      {"edge-cases-tinygltf/BoundsChecking/invalid-buffer-index.gltf", {{"tinygltf"}, ""}},
      {"edge-cases-tinygltf/BoundsChecking/invalid-buffer-view-index.gltf", {{"tinygltf"}, ""}},
      {"edge-cases-tinygltf/BoundsChecking/invalid-primitive-indices.gltf", {{"tinygltf"}, ""}},
      {"mesh-primitive-modes/MeshPrimitiveModes.gltf", {{}, "skipped POINTS primitive"}},
  };
  return table;
}

std::vector<fs::path> sharedGltfFiles() {
  std::vector<fs::path> files;
  if (!fs::exists(kShared)) return files;
  for (const auto& entry : fs::recursive_directory_iterator(kShared)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".gltf" || ext == ".glb") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool anyContains(const std::vector<std::string>& lines, const std::string& part) {
  for (const std::string& line : lines)
    if (line.find(part) != std::string::npos) return true;
  return false;
}

TEST(SharedScenes, EveryGltfLoadsOrFailsWithTheExpectedNamedError) {
  const auto files = sharedGltfFiles();
  if (files.empty()) GTEST_SKIP() << "no shared scenes at " << kShared;
  std::size_t matched = 0;
  for (const fs::path& file : files) {
    const std::string key = fs::relative(file, kShared).generic_string();
    SCOPED_TRACE(key);
    auto it = expectations().find(key);
    const bool mustFail = it != expectations().end() && !it->second.errorParts.empty();
    if (it != expectations().end()) ++matched;
    try {
      const Scene scene = loadScene(file);
      EXPECT_FALSE(mustFail) << "loaded, but an error was expected";
      EXPECT_GT(scene.meshes.size(), 0u);
      EXPECT_GT(scene.instances.size(), 0u);
      const Aabb box = scene.bounds();
      EXPECT_FALSE(box.empty());
      EXPECT_TRUE(allFinite(box.lo) && allFinite(box.hi));
      if (it != expectations().end() && !it->second.warningPart.empty()) {
        EXPECT_TRUE(anyContains(scene.warnings, it->second.warningPart));
      }
    } catch (const InputError& e) {
      EXPECT_TRUE(mustFail) << "unexpected error: " << e.what();
      if (!mustFail) continue;
      const std::string text = e.what();
      EXPECT_NE(text.find(file.filename().string()), std::string::npos) << text;
      for (const std::string& part : it->second.errorParts)
        EXPECT_NE(text.find(part), std::string::npos) << "missing '" << part << "' in: " << text;
    }
  }
  EXPECT_EQ(matched, expectations().size()) << "a file in the expectation table was not found";
}

TEST(SharedScenes, NegativeScaleTestHasMirroredInstances) {
  const fs::path file = kShared / "negative-scale-test/NegativeScaleTest.glb";
  if (!fs::exists(file)) GTEST_SKIP();
  const Scene scene = loadScene(file);
  int mirrored = 0;
  for (const Instance& inst : scene.instances)
    if (glm::determinant(inst.transform) < 0.f) ++mirrored;
  EXPECT_GT(mirrored, 0);
}

TEST(SharedScenes, MeshPrimitiveModesKeepsTrianglesStripsAndFans) {
  const fs::path file = kShared / "mesh-primitive-modes/MeshPrimitiveModes.gltf";
  if (!fs::exists(file)) GTEST_SKIP();
  const Scene scene = loadScene(file);
  EXPECT_EQ(scene.meshes.size(), 3u);  // TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN
  for (const char* mode : {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"})
    EXPECT_TRUE(anyContains(scene.warnings, std::string("skipped ") + mode)) << mode;
  for (const Mesh& mesh : scene.meshes) EXPECT_GT(mesh.triangleCount(), 0u) << mesh.name;
}

TEST(SharedScenes, LightsPunctualLampHasFivePointLightsInCandela) {
  const fs::path file = kShared / "lights-punctual-lamp/LightsPunctualLamp.gltf";
  if (!fs::exists(file)) GTEST_SKIP();
  const Scene scene = loadScene(file);
  ASSERT_EQ(scene.lights.size(), 5u);
  float maxIntensity = 0.f;
  for (const Light& l : scene.lights) {
    EXPECT_EQ(l.type, LightType::Point);
    maxIntensity = std::max(maxIntensity, l.intensity);
  }
  // 180 cd in the file, in shading units cd / (683 pi) (docs/materials.md, "Light units").
  EXPECT_NEAR(maxIntensity, 180.f / (683.f * 3.14159265f), 1e-6f);
  EXPECT_FALSE(scene.textures.empty());
}

TEST(SharedScenes, TransmissionAndEmissiveStrengthMapOntoLectureCoefficients) {
  const fs::path transmission =
      kShared / "transmission-roughness-test/TransmissionRoughnessTest.glb";
  const fs::path cornell = kShared / "cornell-box/CornellBox.glb";
  if (!fs::exists(transmission) || !fs::exists(cornell)) GTEST_SKIP();
  const Scene glass = loadScene(transmission);
  bool anyTransmissive = false;
  for (const Material& m : glass.materials) {
    EXPECT_TRUE(m.fromGltfPbr);
    if (m.kt > 0.f) anyTransmissive = true;
  }
  EXPECT_TRUE(anyTransmissive);
  const Scene box = loadScene(cornell);
  float brightest = 0.f;
  for (const Material& m : box.materials) brightest = std::max(brightest, m.emission.x);
  EXPECT_GT(brightest, 1.f);  // emissive_strength = 100 scales the [0,1] emissive factor
}

TEST(SharedScenes, MetalRoughSpheresLoadsAMillionTriangles) {
  const fs::path file = kShared / "metal-rough-spheres-no-textures/MetalRoughSpheresNoTextures.glb";
  if (!fs::exists(file)) GTEST_SKIP();
  const Scene scene = loadScene(file);
  std::size_t triangles = 0;
  for (const Instance& inst : scene.instances) triangles += scene.meshes[inst.mesh].triangleCount();
  EXPECT_GT(triangles, 1000000u);
}
}  // namespace DIPTYCH_UNITY_ID
