#include "passes/raster/shadow_map_frusta.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace diptych::shadowmap {

namespace {

constexpr float kMaxHalfFov = 1.48353f;  // 85 degrees: a perspective map cannot cover 180

// Turns a ZERO_TO_ONE projection into its reversed-Z form: depth' = 1 - depth, i.e. the clip z
// row becomes (w row - z row). Done on the matrix, so the rasterizer interpolates the reversed
// value and the precision gain of reversed-Z is kept.
mat4 reverseDepth(const mat4& m) {
  mat4 r = m;
  for (int c = 0; c < 4; ++c) r[c][2] = m[c][3] - m[c][2];
  return r;
}

std::array<vec3, 8> corners(const Aabb& b) {
  std::array<vec3, 8> out;
  for (int i = 0; i < 8; ++i)
    out[i] = vec3(i & 1 ? b.hi.x : b.lo.x, i & 2 ? b.hi.y : b.lo.y, i & 4 ? b.hi.z : b.lo.z);
  return out;
}

// Any up vector not parallel to `forward`.
vec3 upFor(const vec3& forward) {
  return std::abs(forward.y) < 0.9f ? vec3(0.f, 1.f, 0.f) : vec3(1.f, 0.f, 0.f);
}

// Directional light: orthographic box = the light-space AABB of the 8 corners of the scene
// bounds seen along the light direction, padded by 1% of its depth range and 0.1% + 2 texels of
// its width, so every surface of the scene lies inside with PCF taps to spare.
void fitDirectional(LightFrustum& f, const Aabb& bounds, const FrustumOptions& o) {
  const vec3 centre = 0.5f * (bounds.lo + bounds.hi);
  const float radius = std::max(0.5f * glm::length(bounds.hi - bounds.lo), 1e-6f);
  const vec3 eye = centre - f.direction * (2.f * radius);
  const mat4 view = glm::lookAtRH(eye, centre, upFor(f.direction));
  vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (const vec3& c : corners(bounds)) {
    const vec3 v = vec3(view * vec4(c, 1.f));
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  const vec2 extent = glm::max(vec2(hi.x - lo.x, hi.y - lo.y), vec2(1e-6f));
  const vec2 pad = extent * (1e-3f + 2.f / float(o.resolution));
  f.zNear = std::max(-hi.z - 0.01f * (hi.z - lo.z), 1e-6f * radius);
  f.zFar = -lo.z + 0.01f * (hi.z - lo.z) + 1e-6f * radius;
  const mat4 proj =
      glm::orthoRH_ZO(lo.x - pad.x, hi.x + pad.x, lo.y - pad.y, hi.y + pad.y, f.zNear, f.zFar);
  f.viewProj = {reverseDepth(proj) * view};
  f.texelScale = std::max(extent.x + 2.f * pad.x, extent.y + 2.f * pad.y) / float(o.resolution);
}

// Near and far planes along `axis` from `eye`: the box's extent along the axis (the minimum and
// maximum of a linear function over a box are at corners). When the box reaches behind the
// near side (the light is inside the scene bounds) near falls back to far / 10^4: reversed-Z
// D32F keeps ~2^-23 relative depth precision over that range.
std::pair<float, float> axisRange(const vec3& eye, const vec3& axis, const Aabb& bounds) {
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (const vec3& c : corners(bounds)) {
    const float d = glm::dot(c - eye, axis);
    lo = std::min(lo, d);
    hi = std::max(hi, d);
  }
  const float zFar = std::max(hi * 1.01f, 1e-6f);
  const float zNear = lo > 0.f ? std::max(0.99f * lo, 1e-4f * zFar) : 1e-4f * zFar;
  return {zNear, zFar};
}

void fitSpot(LightFrustum& f, const Light& light, const Aabb& bounds, const FrustumOptions& o) {
  // fov = 2 * outer cone, widened by 8 texels so PCF taps at the cone's rim stay in the map.
  const float outer = std::clamp(light.outerConeAngle, 1e-4f, kMaxHalfFov);
  const float half =
      std::min(std::atan(std::tan(outer) * (1.f + 8.f / float(o.resolution))), kMaxHalfFov);
  const auto [zNear, zFar] = axisRange(f.position, f.direction, bounds);
  f.zNear = zNear;
  f.zFar = zFar;
  const mat4 view = glm::lookAtRH(f.position, f.position + f.direction, upFor(f.direction));
  f.viewProj = {reversedPerspective(2.f * half, 1.f, zNear, zFar) * view};
  f.texelScale = 2.f * std::tan(half) / float(o.resolution);
}

// Point light (or an area light's centre): six 90-degree faces. Far = the farthest corner
// (Euclidean distance bounds every face's axis depth); near = the distance to the box / sqrt(3)
// (a point at distance d inside a face's frustum has axis depth >= d / sqrt(3)).
void fitCube(LightFrustum& f, const Aabb& bounds, const FrustumOptions& o) {
  float farthest = 0.f;
  for (const vec3& c : corners(bounds)) farthest = std::max(farthest, glm::length(c - f.position));
  const vec3 outside =
      glm::max(glm::max(bounds.lo - f.position, f.position - bounds.hi), vec3(0.f));
  const float boxDistance = glm::length(outside);
  f.zFar = std::max(farthest * 1.01f, 1e-6f);
  f.zNear = std::max(0.99f * boxDistance / std::sqrt(3.f), 1e-4f * f.zFar);
  const mat4 proj = reversedPerspective(glm::radians(90.f), 1.f, f.zNear, f.zFar);
  f.viewProj.clear();
  for (int face = 0; face < 6; ++face) {
    vec3 forward(0.f);
    forward[face / 2] = face % 2 == 0 ? 1.f : -1.f;
    f.viewProj.push_back(proj * glm::lookAtRH(f.position, f.position + forward, upFor(forward)));
  }
  f.texelScale = 2.f / float(o.resolution);
}

}  // namespace

mat4 reversedPerspective(float verticalFov, float aspect, float zNear, float zFar) {
  return reverseDepth(glm::perspectiveRH_ZO(verticalFov, aspect, zNear, zFar));
}

std::vector<LightFrustum> fitLightFrusta(const std::vector<Light>& lights, const Aabb& bounds,
                                         const FrustumOptions& o) {
  std::vector<LightFrustum> out;
  int layer = 0;
  const Aabb box = bounds.empty() ? Aabb{vec3(-1.f), vec3(1.f)} : bounds;
  for (const Light& light : lights) {
    LightFrustum f;
    f.position = light.position;
    const float len = glm::length(light.direction);
    f.direction = len > 0.f ? light.direction / len : vec3(0.f, -1.f, 0.f);
    if (light.castsShadows) {
      switch (light.type) {
        case LightType::Directional:
          f.kind = ViewKind::Ortho;
          f.lightSize = o.directionalAngle;
          fitDirectional(f, box, o);
          break;
        case LightType::Spot:
          f.kind = ViewKind::Perspective;
          f.lightSize = o.pointLightSize;
          fitSpot(f, light, box, o);
          break;
        case LightType::Point:
        case LightType::QuadArea:
        case LightType::DiscArea:
        case LightType::SphereArea:
          f.kind = ViewKind::Cube;
          // Area lights: a point at the centre for the map; their real size drives PCSS.
          f.lightSize = light.type == LightType::Point ? o.pointLightSize
                        : light.type == LightType::QuadArea
                            ? std::sqrt(glm::length(glm::cross(light.edgeU, light.edgeV)))
                            : 2.f * light.radius;
          fitCube(f, box, o);
          break;
      }
      f.firstLayer = layer;
      f.layers = int(f.viewProj.size());
      layer += f.layers;
    }
    out.push_back(std::move(f));
  }
  return out;
}

int totalLayers(const std::vector<LightFrustum>& frusta) {
  int n = 0;
  for (const LightFrustum& f : frusta) n += f.layers;
  return n;
}

}  // namespace diptych::shadowmap
