#include "engine/scene/environment_sky.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace diptych {

vec3 skyRadiance(const SkyParams& sky, const vec3& d) {
  vec3 base;
  if (d.y >= 0.f) {
    const float t = std::pow(d.y, 1.f / std::max(sky.gradientExponent, 1e-3f));
    base = glm::mix(sky.horizon, sky.zenith, t);
  } else {
    base = sky.ground;
  }
  const float len = glm::length(sky.sunDirection);
  if (!(len > 0.f)) return base;
  const float c = std::clamp(glm::dot(d, sky.sunDirection / len), -1.f, 1.f);
  const float angle = std::acos(c);
  vec3 sun = sky.sunColor * sky.glow * std::exp(-angle / std::max(sky.glowWidth, 1e-6f));
  if (angle <= sky.sunRadius) sun += sky.sunColor * sky.sunRadiance;
  return base + sun;
}

Environment bakeSky(const SkyParams& sky) {
  Environment env;
  env.type = EnvironmentType::Equirect;
  env.source = "procedural sky (scene JSON)";
  const int width = std::max(sky.width, 2), height = std::max(1, width / 2);
  env.equirect = Image(width, height, 3);
  const float pi = glm::pi<float>();
  // Rows in parallel: each texel is written once, so the bake is the same on any thread count.
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      vec3 sum(0.f);
      for (int s = 0; s < 4; ++s) {
        // Inverse of environment.cpp: u = 0.5 + atan2(d.z, d.x) / 2pi, v = acos(d.y) / pi.
        const float u = (float(x) + 0.25f + 0.5f * float(s & 1)) / float(width);
        const float v = (float(y) + 0.25f + 0.5f * float(s >> 1)) / float(height);
        const float phi = (u - 0.5f) * 2.f * pi, theta = v * pi;
        const vec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                     std::sin(theta) * std::sin(phi));
        sum += skyRadiance(sky, d);
      }
      for (int ch = 0; ch < 3; ++ch) env.equirect.at(x, y, ch) = 0.25f * sum[ch];
    }
  });
  return env;
}

}  // namespace diptych
