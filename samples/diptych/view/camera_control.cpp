#include "samples/diptych/view/camera_control.h"

#include <algorithm>
#include <cmath>

namespace diptych::view {
namespace {

// Rotates v about the unit axis by angle (Rodrigues).
vec3 rotate(const vec3& v, const vec3& axis, float angle) {
  return glm::vec3(glm::angleAxis(angle, glm::normalize(axis)) * v);
}

// Keeps the view direction at least ~1 degree away from +-up, where the orbit is undefined.
float clampPitch(const vec3& forward, const vec3& up, float pitch) {
  const float current = std::asin(std::clamp(glm::dot(glm::normalize(forward), up), -1.f, 1.f));
  const float limit = glm::radians(89.f);
  return std::clamp(current + pitch, -limit, limit) - current;
}

}  // namespace

void orbit(Camera& c, float yaw, float pitch) {
  const vec3 up = glm::normalize(c.up);
  vec3 offset = c.position - c.target;
  const vec3 right = glm::normalize(glm::cross(-offset, up));
  // Pitch moves the position; looking along -offset, raising the camera lowers the view.
  const float p = -clampPitch(-offset, up, -pitch);
  offset = rotate(offset, right, p);
  offset = rotate(offset, up, yaw);
  c.position = c.target + offset;
}

void pan(Camera& c, float dx, float dy) {
  const vec3 forward = c.target - c.position;
  const float distance = glm::length(forward);
  const vec3 right = glm::normalize(glm::cross(forward, c.up));
  const vec3 up = glm::normalize(glm::cross(right, forward));
  const vec3 shift = (right * dx + up * dy) * distance;
  c.position += shift;
  c.target += shift;
}

void dolly(Camera& c, float factor) {
  factor = std::clamp(factor, 1e-3f, 1e3f);
  c.position = c.target + (c.position - c.target) * factor;
  c.focusDistance = glm::length(c.target - c.position);
}

void fly(Camera& c, vec3 move, float yaw, float pitch) {
  vec3 forward = c.target - c.position;
  const float distance = glm::length(forward);
  const vec3 up = glm::normalize(c.up);
  const vec3 right = glm::normalize(glm::cross(forward, up));
  const vec3 shift = (right * move.x + up * move.y + glm::normalize(forward) * move.z) * distance;
  c.position += shift;
  forward = rotate(forward, right, clampPitch(forward, up, pitch));
  forward = rotate(forward, up, -yaw);
  c.target = c.position + forward;
}

float fovDegrees(float radians) {
  const float base = float(double(radians) * 180.0 / 3.14159265358979323846);
  for (int k = 0; k < 9; ++k) {  // offsets 0, +1, -1, +2, -2 ... ulps
    const int offset = (k + 1) / 2 * (k % 2 ? 1 : -1);
    float d = base;
    for (int i = 0; i < std::abs(offset); ++i)
      d = std::nextafter(d, offset > 0 ? INFINITY : -INFINITY);
    if (glm::radians(d) == radians) return d;
  }
  return base;
}

nlohmann::json cameraToJson(const Camera& c, const glm::dvec3& worldOrigin) {
  auto v = [](const vec3& a) { return nlohmann::json::array({a.x, a.y, a.z}); };
  auto file = [&](const vec3& a) { return v(vec3(glm::dvec3(a) + worldOrigin)); };
  return {{"position", file(c.position)},
          {"target", file(c.target)},
          {"up", v(c.up)},
          {"fov", fovDegrees(c.verticalFov)},
          {"aperture", c.aperture},
          {"focus_distance", c.focusDistance},
          {"near", c.znear},
          {"far", c.zfar}};
}

}  // namespace diptych::view
