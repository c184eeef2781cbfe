// resolvedColorAt (engine/rt/surface_point.h), the narrow lookup texture_supersample reads, against
// makeSurfacePoint's resolved texture signal (textureSignalColor: C, or the glTF base colour) and
// alpha at the same hits, bit for bit: textured glTF scenes (base colour, metallic-roughness and
// alpha textures, every glTF sampler), and the samples with checkers, analytic shapes and SDF
// objects.
#include <gtest/gtest.h>

#include <bit>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>

#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/shading.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 96, kH = 72;

bool sameBits(float a, float b) {
  return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}

struct Counts {
  int hits = 0, textured = 0, analytic = 0, mismatches = 0;
};

// Primary rays through every pixel centre of the scene's camera; at each hit both functions.
Counts compareAtHits(const std::filesystem::path& file) {
  const Scene scene = loadScene(file);
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  const RtScene rt(device, world, scene);
  const PinholeFrame pinhole(testing::cameraOf(scene), kW, kH);
  Counts c;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Ray ray = pinhole.ray(float(x) + 0.5f, float(y) + 0.5f);
      const auto hit = rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), false);
      if (!hit) continue;
      const SurfaceHit h{hit->instance, hit->primitive, hit->u, hit->v, hit->analytic};
      const SurfacePoint p = makeSurfacePoint(scene, world, h, ray.direction);
      const vec4 narrow = resolvedColorAt(scene, world, h);
      const vec4 full(shading::textureSignalColor(p.resolved), p.resolved.alpha);
      bool same = true;
      for (int ch = 0; ch < 4; ++ch) same = same && sameBits(narrow[ch], full[ch]);
      ++c.hits;
      const Material& m = scene.material(world.meshes[std::size_t(h.instance)].material);
      if (m.colorTexture >= 0 || m.metallicRoughnessTexture >= 0 || m.checker) ++c.textured;
      if (h.analytic) ++c.analytic;
      if (!same) ++c.mismatches;
    }
  std::printf("%s: %d hits, %d textured, %d analytic, %d differ\n", file.filename().c_str(), c.hits,
              c.textured, c.analytic, c.mismatches);
  return c;
}

TEST(ResolvedColorAt, EqualsMakeSurfacePointOnTexturedGltfHits) {
  const std::filesystem::path shared(DIPTYCH_SHARED_SCENES);
  std::vector<std::filesystem::path> files = {
      shared / "damaged-helmet/DamagedHelmet.glb",
      shared / "texture-settings-test/TextureSettingsTest.glb"};
  for (int k = 0; k < 14; ++k) {
    char name[64];
    std::snprintf(name, sizeof name, "texture-sampler-assetgen/Texture_Sampler_%02d.gltf", k);
    files.push_back(shared / name);
  }
  for (const auto& file : files) {
    if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
    const Counts c = compareAtHits(file);
    EXPECT_GT(c.textured, kW * kH / 20) << file;  // TextureSettingsTest: about 10 %
    EXPECT_EQ(c.mismatches, 0) << file;
  }
}

TEST(ResolvedColorAt, EqualsMakeSurfacePointOnCheckersAnalyticShapesAndSdfs) {
  const std::filesystem::path samples(DIPTYCH_SAMPLES_DIR);
  int analytic = 0;
  for (const char* file : {"scenes/textures.json", "scenes/techniques.json", "scenes/whitted.json",
                           "scenes/sdf.json"}) {
    const Counts c = compareAtHits(samples / file);
    EXPECT_GT(c.textured, 0) << file;
    EXPECT_EQ(c.mismatches, 0) << file;
    analytic += c.analytic;
  }
  EXPECT_GT(analytic, 0);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
