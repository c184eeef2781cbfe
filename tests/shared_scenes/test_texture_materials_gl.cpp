// GL materials sample the textures the CPU samples (docs/textures.md): on Khronos' sampler and
// texture test models and DamagedHelmet, sceneMaterial (shaders/gl/scene_shading.glsl) at every
// texel of a rasterized G-buffer equals resolveMaterial / makeSurfacePoint (C++) at the same
// surface point: base colour and alpha (wrap modes and mag filters of each sampler), emission,
// the per-texel re-mapping to lecture coefficients (remapsPerTexel: also under `--shading
// lecture`), occlusion, the normal-mapped shading normal and the film's textures.
// Bound: |gpu - cpu| <= 1e-4 * max(1, |cpu|) per value (texels are the same floats; the
// difference is the uv's rounding through the two reconstructions, amplified by bilinear slopes).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"
#include "tests/unit/gl_test_context.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 96, kH = 72, kStride = 32, kValues = 31;

// Fraction of hit texels whose GL material differs from the CPU's beyond the bound.
// With `model`, every material is shaded by it (forceShadingModel, as `--shading`).
double mismatchFraction(const std::filesystem::path& file, int& hits,
                        std::optional<ShadingModel> model = std::nullopt) {
  gl::testing::osmesaContext();
  Scene scene = loadScene(file);
  if (model) forceShadingModel(scene, *model);
  RenderWorld world(scene, &gl::testing::osmesaContext());
  gl::GBufferTextures targets;
  gl::rasterizeGBuffer(world.glScene(), scene.camera, kW, kH, targets);
  const gl::Buffer out = gl::Buffer::create(std::size_t(kW) * kH * kStride * 4);
  const gl::Program program = gl::loadProgram(
      {std::filesystem::path(DIPTYCH_TESTS_DIR) / "unit/shaders/material_parity.comp"});
  world.glScene().bind();
  world.glShading().bind();
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  program.use();
  gl::glBindTextureUnit(0, targets.hits.id());
  gl::glDispatchCompute(GLuint((kW * kH + 63) / 64), 1, 1);
  gl::glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(std::size_t(kW) * kH * kStride);
  out.download(0, gpu.size() * 4, gpu.data());
  const std::vector<std::uint32_t> ids = gl::readTexture(targets.hits);
  int bad = 0;
  hits = 0;
  for (int i = 0; i < kW * kH; ++i) {
    const std::uint32_t* t = &ids[std::size_t(i) * 4];
    if (t[0] == 0) continue;
    ++hits;
    const SurfaceHit hit{int(t[0]) - 1, t[1], std::bit_cast<float>(t[2]),
                         std::bit_cast<float>(t[3])};
    const SurfacePoint sp = makeSurfacePoint(scene, world.geometry(), hit, vec3(0.f));
    const shading::ShadingMaterial& m = sp.resolved;
    // makeSurfacePoint flips the normal to the incoming side; a zero incoming is the front.
    const float cpu[kValues] = {m.color.x,
                                m.color.y,
                                m.color.z,
                                m.alpha,
                                m.emission.x,
                                m.emission.y,
                                m.emission.z,
                                m.ka,
                                m.kd,
                                m.ks,
                                m.exponent,
                                m.kps,
                                sp.shadingNormal.x,
                                sp.shadingNormal.y,
                                sp.shadingNormal.z,
                                m.specularColor.x,
                                m.specularColor.y,
                                m.specularColor.z,
                                m.mirrorColor.x,
                                m.mirrorColor.y,
                                m.mirrorColor.z,
                                m.transmitColor.x,
                                m.transmitColor.y,
                                m.transmitColor.z,
                                m.baseColor.x,
                                m.baseColor.y,
                                m.baseColor.z,
                                m.metallic,
                                m.roughness,
                                m.iridescence,
                                m.iridescenceThickness};
    const float* g = &gpu[std::size_t(i) * kStride];
    bool ok = true;
    for (int k = 0; k < kValues; ++k) {
      // e (10) is 2/alpha^2 - 2, up to 19998: its float rounding is larger in absolute terms.
      const float bound = 1e-4f * std::max(1.f, std::fabs(cpu[k])) * (k == 10 ? 100.f : 1.f);
      ok = ok && std::fabs(g[k] - cpu[k]) <= bound;
    }
    bad += ok ? 0 : 1;
  }
  return hits ? double(bad) / hits : 1.0;
}

// Texels may sit where the two uv reconstructions round to different texels of a nearest filter
// or either side of a texel edge; a few per thousand are allowed, nothing systematic.
constexpr double kAllowedMismatch = 0.005;

TEST(TextureMaterialsGl, EverySamplerModelMatchesTheCpu) {
  const std::filesystem::path dir =
      std::filesystem::path(DIPTYCH_SHARED_SCENES) / "texture-sampler-assetgen";
  int files = 0;
  for (int k = 0; k < 14; ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "Texture_Sampler_%02d.gltf", k);
    int hits = 0;
    const double f = mismatchFraction(dir / name, hits);
    std::cout << name << ": " << hits << " texels, mismatch " << f << "\n";
    EXPECT_GT(hits, kW * kH / 10) << name;
    EXPECT_LE(f, kAllowedMismatch) << name;
    // The lecture's model on the same files: their metals' colour textures are re-mapped per
    // texel (remapsPerTexel), which moves the specular and mirror colours on both sides.
    const double lecture = mismatchFraction(dir / name, hits, ShadingModel::Lecture);
    std::cout << name << " (lecture): mismatch " << lecture << "\n";
    EXPECT_LE(lecture, kAllowedMismatch) << name << " under the lecture's model";
    ++files;
  }
  EXPECT_EQ(files, 14);
}

TEST(TextureMaterialsGl, TextureSettingsDamagedHelmetAndNormalMapsMatchTheCpu) {
  const std::filesystem::path shared(DIPTYCH_SHARED_SCENES);
  for (const char* file :
       {"texture-settings-test/TextureSettingsTest.glb", "damaged-helmet/DamagedHelmet.glb",
        "normal-tangent-test/NormalTangentTest.glb",
        "iridescence-suzanne/IridescenceSuzanne.glb"}) {
    int hits = 0;
    const double f = mismatchFraction(shared / file, hits);
    std::cout << file << ": " << hits << " texels, mismatch " << f << "\n";
    // IridescenceSuzanne's three heads cover about 5% of the frame (334 texels).
    EXPECT_GT(hits, kW * kH / 25) << file;
    EXPECT_LE(f, kAllowedMismatch) << file;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
