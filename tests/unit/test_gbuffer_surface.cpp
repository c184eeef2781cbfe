// The G-buffer's stored surface (engine/gl/gbuffer_raster.h `surface`,
// passes/raster/gbuffer_surface.h):
//  - GL passes that read it (gbuffer `surface: true`) produce the frame they produce when they
//    rebuild the surface from the hits (`surface: false`, the default), signal by signal, on
//    every sample scene;
//  - only GL passes read it: the hybrid frame's CPU-placed shade drops the read, so no readback
//    of it exists, and its G-buffer leaves it unwritten;
//  - its layers hold what surfaceFromHits computes: the position on the hit triangle, the uv and
//    material of the hit, a unit face normal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "passes/raster/gbuffer_surface.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

Recipe rasterRecipe(bool surface) {
  Recipe r = loadRecipe(fs::path(DIPTYCH_SAMPLES_DIR) / "graphs/raster.json");
  for (RecipePass& p : r.passes)
    if (p.type == "gbuffer") p.params["surface"] = surface;
  return r;
}

const std::vector<std::string> kSignals = {"shade.color", "shadows.visibility",
                                           "reflection.reflection", "transmission.transmission"};

// Largest |a - b| over every word read as a float (NaN-free signals).
double maxDifference(const CpuImage& a, const CpuImage& b) {
  EXPECT_EQ(a.words.size(), b.words.size());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.words.size(), b.words.size()); ++i)
    worst = std::max(worst, double(std::abs(std::bit_cast<float>(a.words[i]) -
                                            std::bit_cast<float>(b.words[i]))));
  return worst;
}

TEST(GBufferSurface, RasterFrameIsTheSameAsRebuildingTheSurface) {
  std::vector<fs::path> scenes;
  for (const auto& e : fs::directory_iterator(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes"))
    if (e.path().extension() == ".json" || e.path().extension() == ".gltf")
      scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  ASSERT_GE(scenes.size(), 5u);
  for (const fs::path& scene : scenes) {
    SCOPED_TRACE(scene.filename().string());
    auto stored = testing::renderHybridFrame(scene, 160, 120, kSignals, rasterRecipe(true));
    auto rebuilt = testing::renderHybridFrame(scene, 160, 120, kSignals, rasterRecipe(false));
    ASSERT_TRUE(stored->graph.findResource("gbuffer.surface"));
    ASSERT_FALSE(rebuilt->graph.findResource("gbuffer.surface"));
    for (const std::string& signal : kSignals) {
      const double d = maxDifference(stored->output(signal), rebuilt->output(signal));
      std::printf("%-24s %-26s max |stored - rebuilt| %.3g\n", scene.filename().c_str(),
                  signal.c_str(), d);
      // The same GLSL function computes the surface in both (surfaceFromHits); the G-buffer
      // only moves where it runs. Measured: 0 on every sample.
      EXPECT_EQ(d, 0.0) << signal;
    }
  }
}

// Who reads gbuffer.surface: every GL producer and the GL-placed shade of the all-raster frame;
// nothing in the hybrid frame, whose shade is placed on the CPU (a glOnly read, dropped there).
TEST(GBufferSurface, OnlyGlPassesReadIt) {
  const fs::path whitted = fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json";
  auto raster = testing::renderHybridFrame(whitted, 64, 48, {}, rasterRecipe(true));
  const ResourceId rs = *raster->graph.findResource("gbuffer.surface");
  std::vector<std::string> readers;
  for (PassIndex q : raster->graph.resources[rs].readers)
    readers.push_back(raster->graph.passes[q].name);
  std::sort(readers.begin(), readers.end());
  EXPECT_EQ(readers, (std::vector<std::string>{"reflection", "shade", "shadows", "transmission"}));

  Recipe hybridRecipe = defaultHybridRecipe();
  for (RecipePass& p : hybridRecipe.passes)
    if (p.type == "gbuffer") p.params["surface"] = true;
  auto hybrid = testing::renderHybridFrame(whitted, 64, 48, {}, hybridRecipe);
  ASSERT_EQ(hybrid->pass("shade")->domain, Domain::Cpu);
  const ResourceId hs = *hybrid->graph.findResource("gbuffer.surface");
  EXPECT_TRUE(hybrid->graph.resources[hs].readers.empty());
  for (const GraphNode& n : hybrid->graph.nodes) EXPECT_NE(n.name, "readback:gbuffer.surface");
  const auto& shadeReads = hybrid->pass("shade")->reads;
  EXPECT_EQ(std::find(shadeReads.begin(), shadeReads.end(), hs), shadeReads.end());
}

// The layers, read back as an output: on every hit pixel, layer 0 is a point of the scene's
// bounds with uv in layer 0.w and 1.w, layer 1 a unit face normal, layer 2 a unit shading
// normal with the hit's material; background pixels are all zero.
TEST(GBufferSurface, LayersHoldTheHitsSurface) {
  const fs::path scene = fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/surface-detail.json";
  auto f = testing::renderHybridFrame(scene, 80, 60, {"gbuffer.surface", "gbuffer.hits"},
                                      rasterRecipe(true));
  const CpuImage& s = f->output("gbuffer.surface");
  const CpuImage& hits = f->output("gbuffer.hits");
  ASSERT_EQ(s.desc.layers, 3);
  Aabb bounds = f->world->geometry().bounds;
  const vec3 slack = 1e-4f * (bounds.hi - bounds.lo) + 1e-6f;
  long hitPixels = 0;
  for (int y = 0; y < s.desc.height; ++y)
    for (int x = 0; x < s.desc.width; ++x) {
      const std::uint32_t id = hits.u(x, y, 0);
      if (id == 0) {
        for (int layer = 0; layer < 3; ++layer)
          for (int c = 0; c < 4; ++c) ASSERT_EQ(s.f(x, y, c, layer), 0.f);
        continue;
      }
      ++hitPixels;
      const vec3 p(s.f(x, y, 0, 0), s.f(x, y, 1, 0), s.f(x, y, 2, 0));
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(p, bounds.lo - slack)) &&
                  glm::all(glm::lessThanEqual(p, bounds.hi + slack)));
      const vec3 face(s.f(x, y, 0, 1), s.f(x, y, 1, 1), s.f(x, y, 2, 1));
      const vec3 shading(s.f(x, y, 0, 2), s.f(x, y, 1, 2), s.f(x, y, 2, 2));
      EXPECT_NEAR(glm::length(face), 1.f, 1e-5f);
      EXPECT_NEAR(glm::length(shading), 1.f, 1e-5f);
      const int material = f->world->geometry().meshes[id - 1].material;
      EXPECT_EQ(s.f(x, y, 3, 2), float(material));
    }
  EXPECT_GT(hitPixels, 1000);
}

// The G-buffer writes its normal target only for a reader (here: the frame's outputs); a frame
// that asks for it gets the interpolated unit normal and the material of every hit pixel.
TEST(GBufferTargets, NormalIsWrittenWhenRequested) {
  const fs::path scene = fs::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json";
  auto f = testing::renderHybridFrame(scene, 80, 60, {"gbuffer.normal", "gbuffer.hits"},
                                      defaultHybridRecipe());
  const CpuImage& normal = f->output("gbuffer.normal");
  const CpuImage& hits = f->output("gbuffer.hits");
  long hitPixels = 0;
  for (int y = 0; y < normal.desc.height; ++y)
    for (int x = 0; x < normal.desc.width; ++x) {
      const std::uint32_t id = hits.u(x, y, 0);
      if (id == 0) continue;
      ++hitPixels;
      const vec3 n(normal.f(x, y, 0), normal.f(x, y, 1), normal.f(x, y, 2));
      EXPECT_NEAR(glm::length(n), 1.f, 1e-5f);
      EXPECT_EQ(normal.f(x, y, 3), float(f->world->geometry().meshes[id - 1].material));
    }
  EXPECT_GT(hitPixels, 1000);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
