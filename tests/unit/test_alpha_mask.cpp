// Alpha-masked casters (AlphaMode::Mask) in both visibility producers and in primary
// visibility: a 2 x 2 quad at y = 1 whose colour texture is an 8 x 8 checkerboard of alpha 0 / 1
// hangs over a ground plane at y = 0, under a point light at (0, 4, 0). Real OSMesa + Embree.
//
// Expected shadow, computed analytically per plane pixel: the light ray from p meets the quad
// plane at q = L + 3/4 (p - L); p is in shadow exactly when q is on the quad and the checker
// cell at q is opaque. Pixels whose q lies within kEdge (in uv) of a cell edge are left out
// (the map's texels and the band of the shadow-map tests live there).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>

#include "engine/gl/debug.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/rt/rt_scene.h"
#include "engine/scene/camera_math.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/rt_test_geometry.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kCells = 8;
constexpr float kEdge = 0.01f;
constexpr int kWidth = 320, kHeight = 240;

bool opaqueCell(int cx, int cy) {
  return (cx + cy) % 2 == 0;
}

Scene checkerScene(AlphaMode mode) {
  Mesh plane = testgeo::groundPlane(3.f, 0.f);
  Mesh quad = testgeo::groundPlane(1.f, 1.f);
  quad.name = "mask";
  quad.material = 0;
  Scene s = testgeo::sceneOf({plane, quad});
  Texture t;
  t.name = "checker alpha";
  t.image = Image(kCells, kCells, 4, 1.f);
  for (int y = 0; y < kCells; ++y)
    for (int x = 0; x < kCells; ++x) t.image.at(x, y, 3) = opaqueCell(x, y) ? 1.f : 0.f;
  t.wrapS = t.wrapT = WrapMode::ClampToEdge;
  t.minFilter = t.magFilter = FilterMode::Nearest;
  s.textures.push_back(t);
  Material m;
  m.name = "mask";
  m.alphaMode = mode;
  m.alphaCutoff = 0.5f;
  m.colorTexture = 0;
  s.materials.push_back(m);
  Light l;
  l.type = LightType::Point;
  l.position = vec3(0.f, 4.f, 0.f);
  l.intensity = 20.f;
  s.lights.push_back(l);
  s.camera.position = vec3(0.f, 4.5f, 4.5f);
  s.camera.target = vec3(0.f, 0.f, 0.f);
  s.hasCamera = true;
  return s;
}

struct Frame {
  std::vector<float> map, rays;        // shadow_map and rt_shadows visibility, per pixel
  std::vector<std::uint32_t> gbuffer;  // 4 words per pixel
  std::uint32_t instance(int x, int y) const { return gbuffer[4 * (std::size_t(y) * kWidth + x)]; }
  std::uint32_t word(int x, int y, int c) const {
    return gbuffer[4 * (std::size_t(y) * kWidth + x) + std::size_t(c)];
  }
};

// gbuffer + rt_shadows + shadow_map on one frame; `check` gets the world for Embree queries.
template <class Check>
Frame renderFrame(const Scene& scene, Check&& check) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "rt",
       .type = "rt_shadows",
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[1]"},
      {.name = "sm",
       .type = "shadow_map",
       .params = {{"resolution", 1024}, {"bias", "slope"}},
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[2]"},
  };
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, FrameSettings{kWidth, kHeight, scene.camera},
                   {"sm.visibility", "rt.visibility", "gbuffer.hits"});
  const int errors = gl::glDebugErrorCount();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor ex(graph, world);
  ex.runFrame();
  EXPECT_EQ(gl::glDebugErrorCount(), errors);
  Frame f;
  const CpuImage& sm = ex.output("sm.visibility");
  const CpuImage& rt = ex.output("rt.visibility");
  const CpuImage& gb = ex.output("gbuffer.hits");
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      f.map.push_back(sm.f(x, y, 0));
      f.rays.push_back(rt.f(x, y, 0));
      for (int c = 0; c < 4; ++c) f.gbuffer.push_back(gb.words[gb.index(x, y, c)]);
    }
  check(world, f);
  return f;
}

TEST(AlphaMask, CheckerboardShadowInBothProducersAndHolesInPrimaryVisibility) {
  const Scene scene = checkerScene(AlphaMode::Mask);
  long considered = 0, rtAgree = 0, smAgree = 0, shadowed = 0, planeUnderQuad = 0;
  long pixels = 0, idAgree = 0;
  renderFrame(scene, [&](RenderWorld& world, const Frame& f) {
    EXPECT_EQ(world.rtScene().alphaMaskedGeometries(), 1);
    EXPECT_TRUE(world.glShading().anyAlphaTested());
    const WorldGeometry& geo = world.geometry();
    const vec3 light = scene.lights[0].position;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        // Primary visibility: the G-buffer names the instance Embree's filtered closest hit
        // names for the same pixel-centre ray (what rt_whitted's primary rays see).
        const Ray ray = primaryRay(scene.camera, kWidth, kHeight, x + 0.5f, y + 0.5f);
        const auto hit = world.rtScene().intersect(ray, 0.f, 1e30f);
        const std::uint32_t rtId = hit ? std::uint32_t(hit->instance + 1) : 0u;
        ++pixels;
        if (rtId == f.instance(x, y)) ++idAgree;

        if (f.instance(x, y) != 1u) continue;  // plane pixels only
        const float u = std::bit_cast<float>(f.word(x, y, 2));
        const float v = std::bit_cast<float>(f.word(x, y, 3));
        const vec3 p = interpolatePosition(geo.meshes[0], f.word(x, y, 1), u, v);
        const vec3 q = light + 0.75f * (p - light);
        if (std::abs(q.x) >= 1.f + kEdge || std::abs(q.z) >= 1.f + kEdge) {
          // Outside the quad's shadow footprint: lit in both.
          if (std::abs(q.x) > 1.f + kEdge || std::abs(q.z) > 1.f + kEdge) {
            ++considered;
            rtAgree += f.rays[std::size_t(y) * kWidth + x] >= 0.5f;
            smAgree += f.map[std::size_t(y) * kWidth + x] >= 0.5f;
          }
          continue;
        }
        const vec2 uv(0.5f * (q.x + 1.f) * kCells, 0.5f * (q.z + 1.f) * kCells);
        const vec2 frac = uv - glm::floor(uv);
        if (std::min({frac.x, frac.y, 1.f - frac.x, 1.f - frac.y}) < kEdge * kCells) continue;
        if (std::abs(q.x) > 1.f - kEdge || std::abs(q.z) > 1.f - kEdge) continue;
        const bool lit = !opaqueCell(int(uv.x), int(uv.y));
        ++considered;
        ++planeUnderQuad;
        shadowed += lit ? 0 : 1;
        rtAgree += (f.rays[std::size_t(y) * kWidth + x] >= 0.5f) == lit;
        smAgree += (f.map[std::size_t(y) * kWidth + x] >= 0.5f) == lit;
      }
    }
  });
  std::printf(
      "alpha mask: %ld plane pixels classified (%ld under the quad, %ld expected in "
      "shadow); rt_shadows agrees on %.2f%%, shadow_map on %.2f%%; G-buffer vs "
      "Embree primary ids %.3f%%\n",
      considered, planeUnderQuad, shadowed, 100.0 * rtAgree / considered,
      100.0 * smAgree / considered, 100.0 * idAgree / pixels);
  ASSERT_GT(planeUnderQuad, 2000);
  // Both lit and shadowed cells are seen: a checkerboard, not a solid or missing shadow.
  EXPECT_GT(shadowed, planeUnderQuad / 4);
  EXPECT_LT(shadowed, 3 * planeUnderQuad / 4);
  EXPECT_GE(double(rtAgree) / double(considered), 0.99);
  EXPECT_GE(double(smAgree) / double(considered), 0.95);
  EXPECT_GE(double(idAgree) / double(pixels), 0.995);
}

TEST(AlphaMask, GBufferSeesThePlaneThroughTheHoles) {
  std::array<long, 2> plane{}, quad{};
  for (int k = 0; k < 2; ++k) {
    const Scene scene = checkerScene(k == 0 ? AlphaMode::Opaque : AlphaMode::Mask);
    const Frame f = renderFrame(scene, [](RenderWorld&, const Frame&) {});
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        plane[std::size_t(k)] += f.instance(x, y) == 1u;
        quad[std::size_t(k)] += f.instance(x, y) == 2u;
      }
  }
  // Half of the quad's cells are holes: about half of its pixels become plane pixels.
  EXPECT_GT(quad[0], 3000);
  EXPECT_NEAR(double(quad[1]) / double(quad[0]), 0.5, 0.1);
  EXPECT_EQ(plane[1] - plane[0], quad[0] - quad[1]);
}

TEST(AlphaMask, ConstantCoverageBelowCutoffIsCutOutEverywhere) {
  Scene scene = checkerScene(AlphaMode::Mask);
  scene.materials[0].colorTexture = -1;
  scene.materials[0].alpha = 0.2f;
  renderFrame(scene, [](RenderWorld& world, const Frame& f) {
    EXPECT_EQ(world.glShading().alphaDraw(0), gl::AlphaDraw::Hidden);
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x) {
        ASSERT_NE(f.instance(x, y), 2u);
        if (f.instance(x, y) != 1u) continue;
        ASSERT_EQ(f.rays[std::size_t(y) * kWidth + x], 1.f);
        ASSERT_EQ(f.map[std::size_t(y) * kWidth + x], 1.f);
      }
  });
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
