#include "passes/raster/env_maps.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "engine/scene/environment.h"

namespace diptych::envmap {
namespace {

// Fills an RGBA image by evaluating `direction(s, t)` at every texel centre; (s, t) in [0,1],
// t = 0 on the top row.
template <class F>
Image resample(const Environment& env, int width, int height, F direction) {
  Image out(width, height, 4, 1.f);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const vec2 st((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height));
      const vec3 c = sampleEnvironment(env, direction(st));
      for (int k = 0; k < 3; ++k) out.at(x, y, k) = c[k];
    }
  });
  return out;
}

}  // namespace

vec3 cubeFaceDirection(int face, vec2 st) {
  // Table 8.19 gives, per face, (sc, tc, ma) with s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
  // Solving for the direction with |ma| = 1:
  const float sc = 2.f * st.x - 1.f, tc = 2.f * st.y - 1.f;
  vec3 d;
  switch (face) {
    case 0:
      d = vec3(1.f, -tc, -sc);
      break;  // +x: sc = -z, tc = -y
    case 1:
      d = vec3(-1.f, -tc, sc);
      break;  // -x: sc = +z, tc = -y
    case 2:
      d = vec3(sc, 1.f, tc);
      break;  // +y: sc = +x, tc = +z
    case 3:
      d = vec3(sc, -1.f, -tc);
      break;  // -y: sc = +x, tc = -z
    case 4:
      d = vec3(sc, -tc, 1.f);
      break;  // +z: sc = +x, tc = -y
    default:
      d = vec3(-sc, -tc, -1.f);
      break;  // -z: sc = -x, tc = -y
  }
  return glm::normalize(d);
}

std::array<Image, 6> cubeFacesFrom(const Environment& env, int size) {
  std::array<Image, 6> faces;
  for (int f = 0; f < 6; ++f)
    faces[f] = resample(env, size, size, [f](vec2 st) { return cubeFaceDirection(f, st); });
  return faces;
}

vec3 equirectDirection(vec2 uv) {
  // Inverse of u = 0.5 + atan2(d.z, d.x) / 2pi, v = acos(d.y) / pi.
  const float phi = (uv.x - 0.5f) * 2.f * glm::pi<float>(), theta = uv.y * glm::pi<float>();
  return vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
}

Image equirectFrom(const Environment& env, int height) {
  return resample(env, 2 * height, height, equirectDirection);
}

vec2 sphereMapCoord(vec3 r) {
  const float m = 2.f * std::sqrt(r.x * r.x + r.y * r.y + (r.z + 1.f) * (r.z + 1.f));
  if (!(m > 0.f)) return vec2(1.f, 0.5f);
  return vec2(r.x / m + 0.5f, r.y / m + 0.5f);
}

vec3 sphereMapDirection(vec2 st) {
  vec2 p = 2.f * st - 1.f;
  const float rr = glm::dot(p, p);
  if (rr > 1.f) p /= std::sqrt(rr);
  const float nz = std::sqrt(std::max(0.f, 1.f - glm::dot(p, p)));
  return vec3(2.f * nz * p.x, 2.f * nz * p.y, 2.f * nz * nz - 1.f);
}

Image sphereMapFrom(const Environment& env, int size, const mat3& eyeToWorld) {
  // Image row 0 is the top, where GL's t (up) is 1 once uploaded (transfer.h flips rows).
  return resample(env, size, size,
                  [&](vec2 st) { return eyeToWorld * sphereMapDirection(vec2(st.x, 1.f - st.y)); });
}

Image rgbaScaled(const Image& image, float scale) {
  Image out(image.width, image.height, 4, 1.f);
  const int channels = std::max(image.channels, 1);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int k = 0; k < 3; ++k)
        out.at(x, y, k) = image.at(x, y, std::min(k, std::min(channels, 3) - 1)) * scale;
  return out;
}

}  // namespace diptych::envmap
