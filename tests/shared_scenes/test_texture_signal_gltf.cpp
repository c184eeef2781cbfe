// The texture_filtering slot on glTF materials (common/shading.glsl textureSignalColor): its
// signal is the base colour the glTF model reads. It used to be C, the lecture's diffuse colour,
// which is 0 for a metal: Texture_Sampler_00 (metallic 1, the glTF default, with a base colour
// texture) rendered a black quad in the built-in recipe on both sides; and shade ignored the
// signal on materials with a metallic-roughness texture, so on DamagedHelmet every texture-*
// variant was hybrid-exact's image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "engine/rt/surface_point.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/gltf_pbr.h"
#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 96, kH = 72;

std::filesystem::path shared(const char* file) {
  return std::filesystem::path(DIPTYCH_SHARED_SCENES) / file;
}

Recipe withoutAlbedo(Recipe r) {
  for (RecipePass& p : r.passes)
    if (p.type == "shade") p.inputs.erase("albedo");
  return r;
}

Recipe withFilter(Recipe r, const std::string& producer) {
  applySlotOverride(r, parseSlotOverride("texture_filtering=" + producer), builtinPasses());
  return r;
}

// The scene lit as `diptych render` lights it: these files have no light of their own (the
// default sky and sun, engine/scene/default_lighting.h).
// With `model`, every material is shaded by it (forceShadingModel, as `--shading`).
Scene lit(const std::filesystem::path& file, std::optional<ShadingModel> model = std::nullopt) {
  Scene scene = loadScene(file);
  applyLighting(scene, testing::cameraOf(scene), {});
  if (model) forceShadingModel(scene, *model);
  return scene;
}

CpuImage frame(const std::filesystem::path& file, const Recipe& r,
               std::optional<ShadingModel> model = std::nullopt) {
  const std::string output = "shade.color";
  return testing::renderHybridFrame(lit(file, model), kW, kH, {output}, r)->output(output);
}

// Mean |a - b| and the mean of b over the RGB of the frame.
struct Difference {
  double mean = 0.0, level = 0.0;
};
Difference difference(const CpuImage& a, const CpuImage& b) {
  Difference d;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      for (int c = 0; c < 3; ++c) {
        d.mean += std::fabs(double(a.f(x, y, c)) - b.f(x, y, c));
        d.level += b.f(x, y, c);
      }
  d.mean /= 3.0 * kW * kH;
  d.level /= 3.0 * kW * kH;
  return d;
}

// The built-in recipe's signal (one ray at the pixel centre, level 0) is shade's own lookup:
// the frame with it is the frame without the albedo input, on a textured metal and on a material
// with a metallic-roughness texture, under glTF's model and under the lecture's (whose
// coefficients shade maps from the signal's base colour there: withBaseColorSignal).
TEST(TextureSignalGltf, PixelCentreSignalGivesShadesOwnFrame) {
  for (const char* file :
       {"texture-sampler-assetgen/Texture_Sampler_00.gltf", "damaged-helmet/DamagedHelmet.glb"}) {
    if (!std::filesystem::exists(shared(file))) GTEST_SKIP() << "no " << shared(file);
    for (const ShadingModel model : {ShadingModel::Gltf, ShadingModel::Lecture}) {
      const Difference d =
          difference(frame(shared(file), defaultHybridRecipe(), model),
                     frame(shared(file), withoutAlbedo(defaultHybridRecipe()), model));
      std::printf("%s (%s): mean |built-in - own lookup| = %g (frame mean %g)\n", file,
                  model == ShadingModel::Gltf ? "gltf" : "lecture", d.mean, d.level);
      EXPECT_LT(d.mean, 1e-5 * d.level + 1e-7) << file;
    }
  }
}

// Under the lecture's model a raster filter's signal reaches the helmet's re-mapped coefficients
// (it was ignored there: every texture-* variant was hybrid-exact's image), and GL and CPU shade
// map it alike.
TEST(TextureSignalGltf, LectureShadingTakesARasterFiltersBaseColourOnBothSides) {
  const auto file = shared("damaged-helmet/DamagedHelmet.glb");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  const Recipe both =
      testing::withShadeInBothDomains(withFilter(defaultHybridRecipe(), "texture_trilinear"));
  const auto f =
      testing::renderHybridFrame(lit(file, ShadingModel::Lecture), kW, kH, both.outputs, both);
  const CpuImage own = frame(file, defaultHybridRecipe(), ShadingModel::Lecture);
  for (const char* side : {"shade_gl.color", "shade_cpu.color"}) {
    const Difference d = difference(f->output(side), own);
    std::printf("DamagedHelmet (lecture) %s: mean |trilinear - built-in| = %g (frame mean %g)\n",
                side, d.mean, d.level);
    EXPECT_GT(d.mean, 1e-3 * d.level) << side;
  }
  const Difference parity = difference(f->output("shade_gl.color"), f->output("shade_cpu.color"));
  EXPECT_LT(parity.mean, 1e-4 * parity.level) << "GL and CPU shade of the same signal";
}

// A raster filter's signal reaches the helmet's shading (trilinear reads the minified texture's
// mip levels, the centre ray level 0), where it used to be dropped for its metallic-roughness
// texture: the two frames were identical.
TEST(TextureSignalGltf, RasterFilterChangesTheHelmet) {
  const auto file = shared("damaged-helmet/DamagedHelmet.glb");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  const Difference d =
      difference(frame(file, withFilter(defaultHybridRecipe(), "texture_trilinear")),
                 frame(file, defaultHybridRecipe()));
  std::printf("DamagedHelmet: mean |trilinear - built-in| = %g (frame mean %g)\n", d.mean, d.level);
  EXPECT_GT(d.mean, 1e-3 * d.level);
}

// GL shade and CPU shade of one frame with a GL filter's signal (texture_trilinear): they agree,
// and the metal quad keeps its brightness against the frame without the signal (it was black on
// both sides).
TEST(TextureSignalGltf, TrilinearSignalShadesTheMetalOnBothSides) {
  const auto file = shared("texture-sampler-assetgen/Texture_Sampler_00.gltf");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  const Recipe both =
      testing::withShadeInBothDomains(withFilter(defaultHybridRecipe(), "texture_trilinear"));
  const auto f = testing::renderHybridFrame(lit(file), kW, kH, both.outputs, both);
  const CpuImage own = frame(file, withoutAlbedo(defaultHybridRecipe()));
  const CpuImage& hits = f->output("gbuffer.hits");
  for (const char* side : {"shade_gl.color", "shade_cpu.color"}) {
    const CpuImage& shaded = f->output(side);
    double quad = 0.0, ownQuad = 0.0;
    int pixels = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        if (hits.u(x, y, 0) == 0u) continue;  // background
        for (int c = 0; c < 3; ++c) {
          quad += shaded.f(x, y, c);
          ownQuad += own.f(x, y, c);
        }
        ++pixels;
      }
    std::printf("%s: quad mean %g against its own lookup's %g over %d pixels\n", side,
                quad / (3.0 * pixels), ownQuad / (3.0 * pixels), pixels);
    ASSERT_GT(pixels, kW * kH / 10);
    EXPECT_NEAR(quad / ownQuad, 1.0, 0.1) << side;
  }
  const Difference parity = difference(f->output("shade_gl.color"), f->output("shade_cpu.color"));
  EXPECT_LT(parity.mean, 1e-4 * parity.level) << "GL and CPU shade of the same signal";
}

// `--shading lecture` on a textured metal (remapsPerTexel): its base colour is its specular
// colour, so the lecture coefficients are mapped from the base colour at each texel on both
// sides. They used to be the loader's constants (C = 0 for a metal, the specular colour of
// baseColorFactor), so Texture_Sampler_00's quad rendered as if untextured: its frame was the
// frame without the colour texture (measured: equal to the last bit).
TEST(TextureSignalGltf, LectureShadingShowsAMetalsColourTextureOnBothSides) {
  const auto file = shared("texture-sampler-assetgen/Texture_Sampler_00.gltf");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  const auto lecture = [&](bool textured) {
    Scene scene = lit(file);
    forceShadingModel(scene, ShadingModel::Lecture);
    for (Material& m : scene.materials) {
      EXPECT_GT(m.metallicFactor, 0.f) << m.name;
      if (!textured) m.colorTexture = -1;
    }
    const Recipe both = testing::withShadeInBothDomains(defaultHybridRecipe());
    return testing::renderHybridFrame(std::move(scene), kW, kH, both.outputs, both);
  };
  const auto textured = lecture(true), flat = lecture(false);
  for (const char* side : {"shade_gl.color", "shade_cpu.color"}) {
    const Difference d = difference(textured->output(side), flat->output(side));
    std::printf("%s: mean |textured - untextured| = %g (frame mean %g)\n", side, d.mean, d.level);
    EXPECT_GT(d.mean, 0.05 * d.level) << side;
  }
  const Difference parity =
      difference(textured->output("shade_gl.color"), textured->output("shade_cpu.color"));
  EXPECT_LT(parity.mean, 1e-4 * parity.level) << "GL and CPU shade of the re-mapped metal";
}

// The same with a checker in place of the colour texture (a JSON glTF-model material's
// `checker`): the checker's colour is the base colour there (resolveMaterial's baseColor), so
// under the lecture's model the metal is re-mapped from it per texel on both sides (C = 0, a
// mirror and a specular colour of that colour), and with a texture_filtering producer on the GL
// side the signal carries it (texture_filter.comp). Before, remapsPerTexel left checkers out:
// the checker replaced C of the loader's constants, so the metal shaded as a diffuse checker
// with the white specular of its baseColorFactor.
TEST(TextureSignalGltf, LectureShadingShowsAMetalsCheckerOnBothSides) {
  const auto file = shared("texture-sampler-assetgen/Texture_Sampler_00.gltf");
  if (!std::filesystem::exists(file)) GTEST_SKIP() << "no " << file;
  const auto lecture = [&](bool twoColours, const Recipe& recipe) {
    Scene scene = lit(file);
    forceShadingModel(scene, ShadingModel::Lecture);
    // A copy of the model with its colour texture, far behind the model (hidden by it): the
    // texture_filtering slot needs a shown colour-textured material, else it is culled and no
    // producer runs. The camera stays the model's.
    scene.camera = testing::cameraOf(scene);
    scene.hasCamera = true;
    const vec3 away = 1e3f * glm::normalize(scene.camera.target - scene.camera.position);
    const std::size_t meshes = scene.meshes.size(), instances = scene.instances.size();
    for (std::size_t i = 0; i < meshes; ++i) {
      scene.materials.push_back(scene.material(scene.meshes[i].material));
      scene.meshes.push_back(scene.meshes[i]);
      scene.meshes.back().material = int(scene.materials.size()) - 1;
    }
    for (std::size_t i = 0; i < instances; ++i) {
      Instance copy = scene.instances[i];
      copy.mesh += int(meshes);
      copy.transform = glm::translate(mat4(1.f), away) * copy.transform;
      scene.instances.push_back(copy);
    }
    for (std::size_t i = 0; i < meshes; ++i) {
      Material& m = scene.materials[std::size_t(scene.meshes[i].material)];
      EXPECT_GT(m.metallicFactor, 0.f) << m.name;
      m.colorTexture = -1;
      m.checker = Checker{vec3(0.9f, 0.2f, 0.1f),
                          twoColours ? vec3(0.1f, 0.3f, 0.9f) : vec3(0.9f, 0.2f, 0.1f), 4.f};
      EXPECT_TRUE(remapsPerTexel(m)) << m.name;
      // At a texel of colour A: the metal of base colour A, as gltfPbrToLecture maps it.
      const shading::ShadingMaterial at = resolveMaterial(scene, m, vec2(0.01f, 0.01f));
      const LectureCoefficients metal = gltfPbrToLecture(
          m.checker->colorA, m.metallicFactor, m.roughnessFactor, m.transmissionFactor, m.ior);
      EXPECT_EQ(at.color, metal.color) << m.name;  // 0 for a full metal, not the checker
      EXPECT_EQ(at.mirrorColor, metal.mirrorColor) << m.name;
      EXPECT_EQ(at.kps, metal.kps) << m.name;
    }
    return testing::renderHybridFrame(std::move(scene), kW, kH, recipe.outputs, recipe);
  };
  const Recipe both = testing::withShadeInBothDomains(defaultHybridRecipe());
  const auto checkered = lecture(true, both), flat = lecture(false, both);
  for (const char* side : {"shade_gl.color", "shade_cpu.color"}) {
    const Difference d = difference(checkered->output(side), flat->output(side));
    std::printf("%s: mean |two colours - one colour| = %g (frame mean %g)\n", side, d.mean,
                d.level);
    EXPECT_GT(d.mean, 0.05 * d.level) << side;
  }
  const Difference parity =
      difference(checkered->output("shade_gl.color"), checkered->output("shade_cpu.color"));
  EXPECT_LT(parity.mean, 1e-4 * parity.level) << "GL and CPU shade of the re-mapped metal";
  // A GL texture_filtering producer's signal (point-sampled for a checker: texture_filter.comp)
  // is the checker's base colour too, which shade maps as its own lookup does.
  const Recipe filtered =
      testing::withShadeInBothDomains(withFilter(defaultHybridRecipe(), "texture_trilinear"));
  const auto viaSignal = lecture(true, filtered);
  ASSERT_TRUE(viaSignal->output("shade_gl.color").desc.width == kW);
  for (const char* side : {"shade_gl.color", "shade_cpu.color"}) {
    const Difference d = difference(viaSignal->output(side), checkered->output(side));
    std::printf("%s with texture_trilinear: mean difference %g (frame mean %g)\n", side, d.mean,
                d.level);
    EXPECT_LT(d.mean, 1e-4 * d.level) << side;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
