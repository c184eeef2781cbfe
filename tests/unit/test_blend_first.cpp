// The blend producers' per-pixel first surface (passes/raster/blend_transmission.h
// renderBlendFirst, shaders/blend_transmission_first.frag), which the forward passes read instead
// of rebuilding the first visible surface in every fragment (gl::ForwardOptions::
// transmissiveFirst):
//  - it holds, per pixel, that surface's distance from the eye where its material transmits
//    (the CPU surface point of the same hit, to float rounding) and a negative value elsewhere,
//    the same from the hits as from the G-buffer's stored surface;
//  - the forward passes gated by it draw, on every transmissive pixel, exactly what the
//    ungated passes draw there, which rebuild the surface per fragment (bit for bit).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/gl/forward_renderer.h"
#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "passes/raster/blend_transmission.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kWidth = 160, kHeight = 120;

struct BlendScene {
  Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  RenderWorld world{scene, &gl::testing::osmesaContext()};
  gl::GBufferTextures gbuffer = gl::GBufferTextures::allocate(kWidth, kHeight, true);
  gl::ForwardView view = gl::cameraView(scene.camera, float(kWidth) / float(kHeight));
  gl::Texture first = gl::Texture::create2D(gl::TextureFormat::RGBA32F, kWidth, kHeight);
  BlendScene() {
    world.glCached<gl::GBufferRasterizer>().render(world.glScene(), scene.camera, gbuffer,
                                                   &world.glShading());
    renderBlendFirst(world, gbuffer.hits, nullptr, view.eye, first,
                     glm::ivec4(0, 0, kWidth, kHeight));
  }
};

TEST(BlendFirst, HoldsTheTransmissiveFirstSurfaceDistance) {
  BlendScene s;
  const std::vector<float> first = gl::readTextureFloats(s.first);
  const std::vector<std::uint32_t> hits = gl::readTexture(s.gbuffer.hits);
  int transmissive = 0, opaque = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = (std::size_t(y) * kWidth + std::size_t(x)) * 4;
      const float distance = first[i + 3];
      if (hits[i] == 0) {
        EXPECT_LT(distance, 0.f) << x << "," << y;  // background: no surface to be behind
        continue;
      }
      const SurfaceHit hit{int(hits[i] - 1), hits[i + 1], std::bit_cast<float>(hits[i + 2]),
                           std::bit_cast<float>(hits[i + 3])};
      const SurfacePoint p =
          makeSurfacePoint(s.scene, s.world.geometry(), hit, vec3(0.f, 0.f, -1.f));
      if (!shading::materialHasTransmission(s.scene.material(p.material))) {
        EXPECT_LT(distance, 0.f) << x << "," << y;
        ++opaque;
        continue;
      }
      ++transmissive;
      const float expected = glm::length(p.position - s.view.eye);
      EXPECT_NEAR(distance, expected, 1e-5f * expected) << x << "," << y;
      EXPECT_EQ(first[i], 1.f);  // whitted's glass has no volume: the mask factor is 1
    }
  EXPECT_GT(transmissive, 500);
  EXPECT_GT(opaque, 5000);

  // The same values from the G-buffer's stored surface (gbuffer `surface: true`).
  const gl::Texture stored = gl::Texture::create2D(gl::TextureFormat::RGBA32F, kWidth, kHeight);
  renderBlendFirst(s.world, s.gbuffer.hits, &s.gbuffer.surface, s.view.eye, stored,
                   glm::ivec4(0, 0, kWidth, kHeight));
  EXPECT_EQ(gl::readTextureFloats(stored), first);
}

TEST(BlendFirst, GatedForwardPassesDrawWhatRebuildingOnesDrawOnTransmissivePixels) {
  BlendScene s;
  auto& renderer = s.world.glCached<gl::ForwardRenderer>();
  // The producer's two passes (blend_transmission.cpp): the opaque scene, then the transparent
  // objects blended; once gated by `first`, once rebuilding the first surface per fragment.
  const auto twoPasses = [&](const gl::Texture* gate) {
    const gl::Texture color = gl::Texture::create2D(gl::TextureFormat::RGBA32F, kWidth, kHeight);
    const gl::Texture depth = gl::Texture::create2D(gl::TextureFormat::D32F, kWidth, kHeight);
    gl::ForwardOptions opaque{.instances = gl::InstanceSet::Opaque,
                              .behindVisibility = &s.gbuffer.hits,
                              .transmissiveFirst = gate};
    renderer.render(s.world.forwardScene(), s.view, color, depth, opaque);
    const std::vector<float> opaqueOnly = gl::readTextureFloats(color);
    gl::ForwardOptions transparent = opaque;
    transparent.instances = gl::InstanceSet::Transparent;
    transparent.clear = false;
    transparent.depthWrite = false;
    transparent.blend = true;
    renderer.render(s.world.forwardScene(), s.view, color, depth, transparent);
    return std::pair{opaqueOnly, gl::readTextureFloats(color)};
  };
  const auto [gatedOpaque, gated] = twoPasses(&s.first);
  const auto [rebuiltOpaque, rebuilt] = twoPasses(nullptr);
  const std::vector<float> first = gl::readTextureFloats(s.first);
  const vec3 sky(gatedOpaque[0], gatedOpaque[1], gatedOpaque[2]);  // top left: background
  int transmissive = 0, behind = 0;
  for (std::size_t i = 0; i < first.size(); i += 4) {
    if (first[i + 3] < 0.f) continue;
    ++transmissive;
    for (std::size_t c = 0; c < 4; ++c) {
      ASSERT_EQ(gatedOpaque[i + c], rebuiltOpaque[i + c]) << "texel " << i / 4;
      ASSERT_EQ(gated[i + c], rebuilt[i + c]) << "texel " << i / 4;
    }
    // Some opaque surface (the floor, the mirror sphere) was drawn behind the glass here.
    if (vec3(gatedOpaque[i], gatedOpaque[i + 1], gatedOpaque[i + 2]) != sky) ++behind;
  }
  EXPECT_GT(transmissive, 500);
  EXPECT_GT(behind, 200);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
