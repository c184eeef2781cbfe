// The procedural sky (engine/scene/environment_sky.h) and its JSON block: the model's
// structure (sun disc, glow, horizon step, gradient) survives baking into the equirect that
// every consumer samples, and bad parameters fail naming the JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/scene/environment.h"
#include "engine/scene/environment_sky.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

float luminance(const vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

SkyParams testSky() {
  SkyParams p;
  p.sunDirection = vec3(1.f, 1.f, 0.f);  // 45 degrees up, toward +x
  return p;
}

fs::path writeScene(const std::string& name, const std::string& environment) {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_test_environment_sky");
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << R"({"environment": )" << environment
                   << R"(, "objects": [{"type": "plane"}]})";
  return p;
}

TEST(Sky, AnalyticModelHasSunGlowHorizonAndGradient) {
  const SkyParams p = testSky();
  const vec3 sun = glm::normalize(p.sunDirection);
  // Inside the disc: base + glow + disc radiance.
  EXPECT_GT(skyRadiance(p, sun).x, p.sunRadiance * p.sunColor.x);
  // Just outside the disc the disc term is gone; the glow falls off with the angle.
  const vec3 off = glm::normalize(sun + vec3(0.f, 0.f, 2.f * p.sunRadius));
  EXPECT_LT(skyRadiance(p, off).x, p.sunRadiance * p.sunColor.x);
  const vec3 far = glm::normalize(vec3(-1.f, 0.2f, 0.f));
  EXPECT_NEAR(skyRadiance(p, far).x,
              glm::mix(p.horizon, p.zenith, std::pow(far.y, 1.f / p.gradientExponent)).x, 1e-3f);
  // The zenith is the zenith colour plus the sun's glow 45 degrees away; the ground is flat.
  const float glowAt45 = p.glow * std::exp(-glm::radians(45.f) / p.glowWidth);
  EXPECT_NEAR(skyRadiance(p, vec3(0.f, 1.f, 0.f)).z, p.zenith.z + p.sunColor.z * glowAt45, 1e-5f);
  const vec3 down = glm::normalize(vec3(-1.f, -0.3f, 0.f));
  const float glowDown = p.glow * std::exp(-std::acos(glm::dot(down, sun)) / p.glowWidth);
  EXPECT_NEAR(skyRadiance(p, down).x, p.ground.x + p.sunColor.x * glowDown, 1e-5f);
}

TEST(Sky, BakedEquirectKeepsTheStructure) {
  const SkyParams p = testSky();
  const Environment env = bakeSky(p);
  ASSERT_EQ(env.type, EnvironmentType::Equirect);
  EXPECT_EQ(env.equirect.width, p.width);
  EXPECT_EQ(env.equirect.height, p.width / 2);
  const vec3 sun = glm::normalize(p.sunDirection);
  // Looked up through the same sampler as ray misses: the disc is there and bright.
  EXPECT_GT(luminance(sampleEnvironment(env, sun)), 0.9f * luminance(skyRadiance(p, sun)));
  // A step at the horizon (away from the sun): pale sky above, ground below.
  const vec3 above = sampleEnvironment(env, glm::normalize(vec3(-1.f, 0.02f, 0.f)));
  const vec3 under = sampleEnvironment(env, glm::normalize(vec3(-1.f, -0.02f, 0.f)));
  EXPECT_GT(luminance(above), 3.f * luminance(under));
  // Gradient: the zenith is bluer than the horizon.
  const vec3 zenith = sampleEnvironment(env, vec3(0.f, 1.f, 0.f));
  EXPECT_GT(zenith.z / zenith.x, above.z / above.x);
}

TEST(Sky, JsonBlockLoadsAndBadValuesNameTheirPath) {
  const Scene s = loadScene(writeScene(
      "sky.json", R"({"sky": {"sun_direction": [0, 1, 1], "sun_radius_deg": 3, "width": 64},
                      "intensity": 2})"));
  EXPECT_EQ(s.environment.type, EnvironmentType::Equirect);
  EXPECT_EQ(s.environment.equirect.width, 64);
  EXPECT_EQ(s.environment.intensity, 2.f);
  const auto error = [](const std::string& env) -> std::string {
    try {
      loadScene(writeScene("bad.json", env));
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(error(R"({"sky": {"sun_direction": [0, 0, 0]}})").find("environment.sky.sun_direction"),
            std::string::npos);
  EXPECT_NE(error(R"({"sky": {"width": 4}})").find("environment.sky.width"), std::string::npos);
  EXPECT_NE(error(R"({"sky": {"zenith": [-1, 0, 0]}})").find("environment.sky.zenith"),
            std::string::npos);
  EXPECT_NE(error(R"({"sky": {"sun_radiance": -1}})").find("sun_radiance"), std::string::npos);
  EXPECT_NE(error(R"({"sky": {"typo": 1}})").find("typo"), std::string::npos);
  EXPECT_NE(error(R"({"sky": {}, "equirect": "x.hdr"})").find("environment.sky"),
            std::string::npos);
}
}  // namespace DIPTYCH_UNITY_ID
