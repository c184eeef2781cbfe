// Per-view culling of shadow casters (passes/raster/shadow_map_render.cpp): the frustum test is
// conservative (a box is skipped only when one clip plane rejects all its corners), and on the
// Whitted sample each point-light cube face draws only the meshes it can see. That the maps
// are unchanged is checked against exact shadow rays by test_shadow_map.cpp.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/shadow_map_frusta.h"
#include "passes/raster/shadow_map_gl.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
using shadowmap::boxOutsideFrustum;

Aabb box(vec3 lo, vec3 hi) {
  return Aabb{lo, hi};
}

// The -y cube face of a light at the origin (near 0.1, far 100), as fitCube builds it.
mat4 downFace() {
  const Aabb bounds = box(vec3(-10.f, -20.f, -10.f), vec3(10.f, -1.f, 10.f));
  Light light;
  light.type = LightType::Point;
  light.position = vec3(0.f);
  const auto frusta = shadowmap::fitLightFrusta({light}, bounds, {});
  return frusta[0].viewProj[3];  // faces +x, -x, +y, -y, +z, -z
}

TEST(ShadowMapCulling, FrustumTestIsConservative) {
  const mat4 down = downFace();
  EXPECT_FALSE(boxOutsideFrustum(box(vec3(-1.f, -5.f, -1.f), vec3(1.f, -3.f, 1.f)), down));
  // Above the light: behind the -y face.
  EXPECT_TRUE(boxOutsideFrustum(box(vec3(-1.f, 3.f, -1.f), vec3(1.f, 5.f, 1.f)), down));
  // Below, but beyond the 45-degree side plane |x| <= |y|.
  EXPECT_TRUE(boxOutsideFrustum(box(vec3(6.f, -5.f, -1.f), vec3(8.f, -4.f, 1.f)), down));
  // Straddling the side plane, and reaching from above to below the light: kept.
  EXPECT_FALSE(boxOutsideFrustum(box(vec3(3.f, -5.f, -1.f), vec3(8.f, -4.f, 1.f)), down));
  EXPECT_FALSE(boxOutsideFrustum(box(vec3(-1.f, -5.f, -1.f), vec3(1.f, 5.f, 1.f)), down));
  // A box around the light itself touches every face.
  EXPECT_FALSE(boxOutsideFrustum(box(vec3(-1.f), vec3(1.f)), down));
  EXPECT_TRUE(boxOutsideFrustum(Aabb{}, down));  // empty
}

TEST(ShadowMapCulling, WhittedCubeFacesDrawOnlyTheCastersTheySee) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "sm",
                    .type = "shadow_map",
                    .params = {{"resolution", 64}},
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"}};
  const CompiledGraph graph = compileGraph(recipe, builtinPasses(), scene,
                                           FrameSettings{64, 48, scene.camera}, {"sm.visibility"});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor ex(graph, world);
  ex.runFrame();
  double draws = -1;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (graph.nodes[n].name == "sm") draws = ex.timings()[n].counters.at("shadow_map_caster_draws");
  // Floor and two spheres under one point light (cube map, 6 faces): 18 draws without culling.
  // The light at (4, 8, 6) looks down on all three; nothing lies above it, so the +y face draws
  // nothing, and each sphere subtends a few degrees, so it falls in one or two faces.
  ASSERT_EQ(world.geometry().meshes.size(), 3u);
  EXPECT_GE(draws, 3);
  EXPECT_LE(draws, 9);
}
}  // namespace DIPTYCH_UNITY_ID
