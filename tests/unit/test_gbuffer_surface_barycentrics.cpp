// The G-buffer's surface target is built from the hits texels' (u, v) (resolveSurface), so a
// render that asks for it never draws a visibility buffer: GBufferTargets::barycentrics = false
// is ignored there, as it is with the normal target (engine/gl/gbuffer_raster.h), and the hits
// and every surface layer are those of the exact render, bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>

#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 160, kH = 120;

TEST(GBufferSurfaceBarycentrics, ASurfaceRenderComputesTheBarycentrics) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  RenderWorld world(scene, &gl::testing::osmesaContext());
  auto& raster = world.glCached<gl::GBufferRasterizer>();
  gl::GBufferTextures exact = gl::GBufferTextures::allocate(kW, kH, true);
  gl::GBufferTextures asked = gl::GBufferTextures::allocate(kW, kH, true);
  raster.render(world.glScene(), scene.camera, {&exact.hits, nullptr, &exact.surface, &exact.depth},
                &world.glShading());
  raster.render(world.glScene(), scene.camera,
                {&asked.hits, nullptr, &asked.surface, &asked.depth, false}, &world.glShading());

  const std::vector<std::uint32_t> hits = gl::readTexture(asked.hits);
  EXPECT_EQ(hits, gl::readTexture(exact.hits));
  int covered = 0, nan = 0;
  for (std::size_t i = 0; i < hits.size(); i += 4)
    if (hits[i] != 0) {
      ++covered;
      nan += std::isnan(std::bit_cast<float>(hits[i + 2])) ||
             std::isnan(std::bit_cast<float>(hits[i + 3]));
    }
  EXPECT_GT(covered, kW * kH / 2);
  EXPECT_EQ(nan, 0);
  for (int layer = 0; layer < 3; ++layer)
    EXPECT_EQ(gl::readTexture(asked.surface, layer), gl::readTexture(exact.surface, layer))
        << "layer " << layer;
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
