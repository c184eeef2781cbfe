// Exposure and tone mapping (engine/core/tonemap.h) and default lighting
// (engine/scene/default_lighting.h); docs/materials.md.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/core/tonemap.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/environment.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Image constantImage(vec3 c, int w = 8, int h = 4) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) img.at(x, y, k) = c[k];
  return img;
}

TEST(ToneMap, AutoExposureMapsTheLogAverageToMiddleGrey) {
  // Constant luminance 0.72: log-average 0.72 (+ delta 1e-4), 0.18 / 0.72 = 2^-2.
  EXPECT_NEAR(autoExposure(constantImage(vec3(0.72f))), -2.f, 1e-3f);
  // Half the pixels at 0.02, half at 2.0: geometric mean of (delta + L), about 0.2.
  Image img = constantImage(vec3(0.02f));
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width / 2; ++x)
      for (int k = 0; k < 3; ++k) img.at(x, y, k) = 2.f;
  const double logAverage = std::exp(0.5 * (std::log(1e-4 + 0.02) + std::log(1e-4 + 2.0)));
  EXPECT_NEAR(autoExposure(img), std::log2(0.18 / logAverage), 1e-4);
  // Black and non-finite pixels: nothing to expose for, and no NaN.
  EXPECT_EQ(autoExposure(constantImage(vec3(0.f))), 0.f);
  EXPECT_EQ(autoExposure(constantImage(vec3(NAN))), 0.f);
}

TEST(ToneMap, OperatorsFollowTheirFormulas) {
  const ToneMap clamp{0.f, ToneOperator::Clamp};
  EXPECT_EQ(toneMapPixel(vec3(0.25f, 2.f, -1.f), clamp), vec3(0.25f, 1.f, 0.f));
  EXPECT_EQ(toneMapPixel(vec3(0.25f), ToneMap{2.f, ToneOperator::Clamp}), vec3(1.f));
  // Reinhard on luminance: grey L = 1 -> 0.5, L = 3 -> 0.75; the hue is kept.
  const ToneMap reinhard{0.f, ToneOperator::Reinhard};
  EXPECT_NEAR(toneMapPixel(vec3(1.f), reinhard).x, 0.5f, 1e-6f);
  EXPECT_NEAR(toneMapPixel(vec3(3.f), reinhard).y, 0.75f, 1e-6f);
  const vec3 tinted = toneMapPixel(vec3(0.4f, 0.2f, 0.1f), reinhard);
  EXPECT_NEAR(tinted.x / tinted.y, 2.f, 1e-5f);
  // ACES fit (Narkowicz 2015) with its 0.6 pre-scale: x = 0.6 -> 0.6 (2.51 0.6 + 0.03) /
  // (0.6 (2.43 0.6 + 0.59) + 0.14); very bright values approach 2.51 / 2.43 and clamp to 1.
  const ToneMap aces{0.f, ToneOperator::AcesFit};
  const float x = 0.6f;
  EXPECT_NEAR(toneMapPixel(vec3(1.f), aces).x,
              x * (2.51f * x + 0.03f) / (x * (2.43f * x + 0.59f) + 0.14f), 1e-6f);
  EXPECT_EQ(toneMapPixel(vec3(1e6f), aces), vec3(1.f));
  EXPECT_EQ(toneMapPixel(vec3(INFINITY, NAN, 0.5f), aces).x, 0.f);
  // Monotonic for each operator.
  for (ToneOperator op : {ToneOperator::Clamp, ToneOperator::Reinhard, ToneOperator::AcesFit}) {
    float last = -1.f;
    for (float v = 0.f; v < 20.f; v += 0.05f) {
      const float out = toneMapPixel(vec3(v), ToneMap{0.f, op}).x;
      EXPECT_GE(out, last);
      last = out;
    }
  }
  EXPECT_EQ(parseToneOperator("aces"), ToneOperator::AcesFit);
  EXPECT_FALSE(parseToneOperator("filmic"));
}

Scene unlitScene() {
  Scene s;
  s.meshes.push_back({});
  return s;
}

TEST(DefaultLighting, UnlitSceneGetsSkySunAndFillAndOneLine) {
  Scene scene = unlitScene();
  ASSERT_TRUE(sceneIsUnlit(scene));
  const Camera camera;  // at +z looking at the origin, +y up
  const auto line = applyLighting(scene, camera, {});
  ASSERT_TRUE(line);
  EXPECT_NE(line->find("default lighting"), std::string::npos);
  ASSERT_EQ(scene.lights.size(), 2u);
  const Light& sun = scene.lights[0];
  EXPECT_EQ(sun.type, LightType::Directional);
  EXPECT_TRUE(sun.castsShadows);
  // The sun comes from above and from the camera's side, so what the camera sees is lit.
  EXPECT_LT(sun.direction.y, -0.5f);
  EXPECT_LT(sun.direction.z, 0.f);
  EXPECT_FALSE(scene.lights[1].castsShadows);
  // Sky: bluer and brighter above than below the horizon.
  const vec3 up = sampleEnvironment(scene.environment, vec3(0.f, 1.f, 0.f));
  const vec3 down = sampleEnvironment(scene.environment, vec3(0.f, -1.f, 0.f));
  EXPECT_GT(up.z, up.x);
  EXPECT_GT(up.z, down.z);
  EXPECT_FALSE(sceneIsUnlit(scene));
}

TEST(DefaultLighting, SceneWithItsOwnLightOrEnvironmentIsNeverChanged) {
  Scene lit = unlitScene();
  lit.lights.push_back(Light{});
  EXPECT_FALSE(applyLighting(lit, Camera{}, {}));
  EXPECT_EQ(lit.lights.size(), 1u);
  EXPECT_EQ(lit.environment.type, EnvironmentType::Color);

  Scene withSky = unlitScene();
  withSky.environment.color = vec3(0.5f);
  EXPECT_FALSE(applyLighting(withSky, Camera{}, {}));
  EXPECT_TRUE(withSky.lights.empty());
}

// A glTF file with its own lights and no environment is left as it is, and says so once,
// naming --env; JSON scenes (their authors chose the environment), files with an environment
// and unlit files (default lighting) get no hint.
TEST(DefaultLighting, AGltfFileWithLightsAndNoEnvironmentIsToldAboutEnv) {
  // The scene as loaded from `path` (loadScene sets Scene::sourcePath).
  const auto from = [](Scene s, const char* path) {
    s.sourcePath = path;
    return s;
  };
  Scene lit = unlitScene();
  lit.lights.push_back(Light{});
  const auto hint = darkEnvironmentHint(from(lit, "models/Suzanne.GLB"));
  ASSERT_TRUE(hint);
  EXPECT_NE(hint->find("Suzanne.GLB: lit by its own 1 light and no environment"), std::string::npos)
      << *hint;
  EXPECT_NE(hint->find("--env"), std::string::npos) << *hint;
  EXPECT_TRUE(darkEnvironmentHint(from(lit, "lamp.gltf")));
  EXPECT_FALSE(darkEnvironmentHint(from(lit, "cornell.json")));
  Scene withSky = lit;
  withSky.environment.color = vec3(0.5f);
  EXPECT_FALSE(darkEnvironmentHint(from(withSky, "lamp.gltf")));
  EXPECT_FALSE(darkEnvironmentHint(from(unlitScene(), "helmet.glb")));
}

TEST(DefaultLighting, CommandLineLightReplacesTheDefault) {
  Scene scene = unlitScene();
  LightingOptions options;
  options.lightJson = R"({"type":"point","position":[0,5,0],"intensity":20,"name":"mine"})";
  const auto line = applyLighting(scene, Camera{}, options);
  ASSERT_TRUE(line);
  EXPECT_NE(line->find("mine"), std::string::npos);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].intensity, 20.f);
  EXPECT_EQ(scene.environment.type, EnvironmentType::Color);  // no sky added
}

TEST(DefaultLighting, BadCommandLineInputNamesTheOption) {
  Scene scene = unlitScene();
  LightingOptions bad;
  bad.lightJson = R"({"type":"laser"})";
  try {
    applyLighting(scene, Camera{}, bad);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--light"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("laser"), std::string::npos) << e.what();
  }
  LightingOptions missing;
  missing.environmentFile = "/nonexistent/sky.hdr";
  try {
    applyLighting(scene, Camera{}, missing);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--env"), std::string::npos) << e.what();
  }
}

TEST(DefaultLighting, EnvironmentFromTheCommandLineKeepsTheSun) {
  const std::filesystem::path hdr = testing::scratchDir("env-option") / "sky.exr";
  writeImage(hdr, constantImage(vec3(0.3f, 0.4f, 0.9f)));
  Scene scene = unlitScene();
  LightingOptions options;
  options.environmentFile = hdr.string();
  ASSERT_TRUE(applyLighting(scene, Camera{}, options));
  EXPECT_EQ(scene.environment.type, EnvironmentType::Equirect);
  EXPECT_EQ(scene.environment.source, hdr.string());
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].name, "default sun");
  EXPECT_NEAR(sampleEnvironment(scene.environment, vec3(1.f, 0.f, 0.f)).z, 0.9f, 1e-5f);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
