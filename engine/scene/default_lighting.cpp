#include "engine/scene/default_lighting.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/scene/load.h"

namespace diptych {
namespace {

// Sky radiances (linear RGB, the shading's units). A clear-sky look, not a physical sky model:
// blue at the zenith, pale at the horizon, a dim warm ground below it.
constexpr vec3 kZenith{0.18f, 0.32f, 0.70f};
constexpr vec3 kHorizon{0.75f, 0.80f, 0.88f};
constexpr vec3 kGround{0.12f, 0.11f, 0.10f};
// Sun: S_i of the lecture's sum for a directional light (docs/materials.md: a white Lambertian
// surface facing it reflects radiance S). 2.5 keeps an albedo-0.4 surface below 1 at EV 0.
constexpr vec3 kSunColor{1.0f, 0.95f, 0.88f};
constexpr float kSunIntensity = 2.5f;
// Fill: stands in for the sky's light on the shadowed side, which the lecture's local model has
// no term for (only the path tracer integrates the environment); casts no shadow.
constexpr vec3 kFillColor{0.75f, 0.82f, 1.0f};
constexpr float kFillIntensity = 0.5f;

vec3 skyRadiance(float cosElevation) {
  if (cosElevation >= 0.f) return glm::mix(kHorizon, kZenith, std::sqrt(cosElevation));
  return glm::mix(kHorizon * 0.5f, kGround, std::min(1.f, -cosElevation * 4.f));
}

struct CameraFrame {
  vec3 back, right, up;
};

CameraFrame frameOf(const Camera& camera) {
  vec3 back = camera.position - camera.target;
  back = glm::length(back) > 0.f ? glm::normalize(back) : vec3(0.f, 0.f, 1.f);
  vec3 right = glm::cross(camera.up, back);
  if (!(glm::length(right) > 0.f)) right = glm::cross(vec3(0.f, 1.f, 0.f), back);
  if (!(glm::length(right) > 0.f)) right = vec3(1.f, 0.f, 0.f);
  right = glm::normalize(right);
  return {back, right, glm::cross(back, right)};
}

Light directional(const std::string& name, const vec3& towardLight, vec3 color, float intensity,
                  bool shadows) {
  Light l;
  l.name = name;
  l.type = LightType::Directional;
  l.direction = -glm::normalize(towardLight);
  l.color = color;
  l.intensity = intensity;
  l.castsShadows = shadows;
  return l;
}

}  // namespace

namespace {
bool environmentIsBlack(const Environment& env) {
  return env.intensity <= 0.f || (env.type == EnvironmentType::Color && env.color == vec3(0.f));
}
}  // namespace

bool sceneIsUnlit(const Scene& scene) {
  return scene.lights.empty() && environmentIsBlack(scene.environment);
}

std::optional<std::string> darkEnvironmentHint(const Scene& scene) {
  if (!isGltfPath(scene.sourcePath) || scene.lights.empty() ||
      !environmentIsBlack(scene.environment))
    return std::nullopt;
  return std::filesystem::path(scene.sourcePath).filename().string() + ": lit by its own " +
         std::to_string(scene.lights.size()) + (scene.lights.size() == 1 ? " light" : " lights") +
         " and no environment, so the background and what mirrors and glass show of it are "
         "black (a viewer would add image-based light): --env FILE.hdr gives it one";
}

Environment proceduralSky(int width) {
  Environment env;
  env.type = EnvironmentType::Equirect;
  env.source = "procedural sky (default lighting)";
  const int height = std::max(1, width / 2);
  env.equirect = Image(width, height, 3);
  for (int y = 0; y < height; ++y) {
    // Row centre -> polar angle; v = acos(d.y) / pi with v = 0 on the top row (scene.h).
    const vec3 c = skyRadiance(std::cos((float(y) + 0.5f) / float(height) * 3.14159265f));
    for (int x = 0; x < width; ++x)
      for (int ch = 0; ch < 3; ++ch) env.equirect.at(x, y, ch) = c[ch];
  }
  return env;
}

Light defaultSun(const Camera& camera) {
  const CameraFrame f = frameOf(camera);
  // Up 1, toward the viewer 0.7, to the left 0.5: a key light over the left shoulder.
  return directional("default sun", f.up + 0.7f * f.back - 0.5f * f.right, kSunColor, kSunIntensity,
                     true);
}

std::optional<std::string> applyLighting(Scene& scene, const Camera& camera,
                                         const LightingOptions& options) {
  std::vector<std::string> added;
  if (!options.environmentFile.empty()) {
    Environment env;
    env.type = EnvironmentType::Equirect;
    try {
      env.equirect = readImage(options.environmentFile);
    } catch (const Error& e) {
      throw InputError("--env", "", e.what());
    }
    if (env.equirect.channels < 3)
      throw InputError("--env", "", options.environmentFile + ": expected an RGB image");
    env.source = options.environmentFile;
    scene.environment = std::move(env);
    added.push_back("environment " + options.environmentFile);
  }
  if (!options.lightJson.empty()) {
    Light light = parseLightJson(options.lightJson, "--light");
    // The user writes the file's coordinates; the loaded world may have been rebased.
    light.position = vec3(glm::dvec3(light.position) - scene.worldOrigin);
    scene.lights.push_back(light);
    added.push_back("the --light " + scene.lights.back().name);
  }
  if (sceneIsUnlit(scene)) {
    const CameraFrame f = frameOf(camera);
    scene.environment = proceduralSky();
    scene.lights.push_back(defaultSun(camera));
    scene.lights.push_back(directional("default fill", f.right - 0.3f * f.up + 0.5f * f.back,
                                       kFillColor, kFillIntensity, false));
    return "scene has no lights and no environment: default lighting added (procedural sky, "
           "sun and shadowless fill; docs/materials.md; --env/--light override)";
  }
  if (scene.lights.empty() && !options.environmentFile.empty()) {
    // An environment alone lights only reflections and the path tracer: add the sun so the
    // hybrid frame's direct lighting is not black either.
    scene.lights.push_back(defaultSun(camera));
    added.push_back("the default sun (the scene has no light)");
  }
  if (added.empty()) return std::nullopt;
  std::string line = "lighting from the command line: ";
  for (std::size_t i = 0; i < added.size(); ++i) line += (i ? ", " : "") + added[i];
  return line;
}

}  // namespace diptych
