#include "engine/scene/camera_math.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace diptych {

mat4 viewMatrix(const Camera& c) {
  return glm::lookAt(c.position, c.target, c.up);
}

mat4 reversedZProjection(const Camera& c, float aspect) {
  const float f = 1.f / std::tan(0.5f * c.verticalFov);
  mat4 p(0.f);  // column-major: p[column][row]
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.f;     // w_clip = -z_view
  p[3][2] = c.znear;  // z_clip = near, so depth = near / -z_view
  return p;
}

PinholeFrame::PinholeFrame(const Camera& c, int width, int height)
    : position_(c.position),
      forward_(glm::normalize(c.target - c.position)),
      right_(glm::normalize(glm::cross(forward_, c.up))),
      up_(glm::cross(right_, forward_)),
      aspect_(float(width) / float(height)),
      tanHalf_(std::tan(0.5f * c.verticalFov)),
      width_(float(width)),
      height_(float(height)) {}

Ray PinholeFrame::ray(float x, float y) const {
  const float ndcX = 2.f * x / width_ - 1.f;
  const float ndcY = 1.f - 2.f * y / height_;
  const vec3 d = forward_ + (ndcX * aspect_ * tanHalf_) * right_ + (ndcY * tanHalf_) * up_;
  return {position_, glm::normalize(d)};
}

void PinholeFrame::rowDirections(int y, std::span<vec3> out) const {
  const float ndcY = 1.f - 2.f * (float(y) + 0.5f) / height_;
  const vec3 rowTerm = (ndcY * tanHalf_) * up_;
  // Structure of arrays in chunks on the stack, so that each statement is one vector loop:
  // ray()'s d = (forward + s right) + t up, then d * (1 / sqrt((dx dx + dy dy) + dz dz)), as
  // glm::normalize computes it (dot of vec3 as (x x + y y) + z z; inversesqrt as 1 / sqrt).
  constexpr std::size_t kChunk = 64;
  float dx[kChunk], dy[kChunk], dz[kChunk];
  for (std::size_t first = 0; first < out.size(); first += kChunk) {
    const std::size_t n = std::min(kChunk, out.size() - first);
    for (std::size_t i = 0; i < n; ++i) {
      // An int to float conversion (a 64-bit unsigned one does not vectorise).
      const float ndcX = 2.f * (float(int(first + i)) + 0.5f) / width_ - 1.f;
      const float s = ndcX * aspect_ * tanHalf_;
      dx[i] = (forward_.x + s * right_.x) + rowTerm.x;
      dy[i] = (forward_.y + s * right_.y) + rowTerm.y;
      dz[i] = (forward_.z + s * right_.z) + rowTerm.z;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const float inv = 1.f / std::sqrt((dx[i] * dx[i] + dy[i] * dy[i]) + dz[i] * dz[i]);
      dx[i] *= inv;
      dy[i] *= inv;
      dz[i] *= inv;
    }
    for (std::size_t i = 0; i < n; ++i) out[first + i] = vec3(dx[i], dy[i], dz[i]);
  }
}

Ray primaryRay(const Camera& c, int width, int height, float x, float y) {
  return PinholeFrame(c, width, height).ray(x, y);
}

vec2 concentricDisk(vec2 s) {
  constexpr float kQuarterPi = std::numbers::pi_v<float> / 4.f;
  const vec2 q = 2.f * s - vec2(1.f);  // [-1,1]^2
  if (q.x == 0.f && q.y == 0.f) return vec2(0.f);
  // Squares of "radius" max(|q.x|, |q.y|) map to circles; the angle is linear along each edge.
  float r, phi;
  if (std::fabs(q.x) > std::fabs(q.y)) {
    r = q.x;
    phi = kQuarterPi * (q.y / q.x);
  } else {
    r = q.y;
    phi = 2.f * kQuarterPi - kQuarterPi * (q.x / q.y);
  }
  return r * vec2(std::cos(phi), std::sin(phi));
}

ThinLensFrame::ThinLensFrame(const Camera& c, int width, int height)
    : pinhole_(c, width, height),
      position_(c.position),
      aperture_(c.aperture),
      focusDistance_(c.focusDistance) {}

Ray ThinLensFrame::ray(float x, float y, vec2 lens) const {
  const Ray pinhole = pinhole_.ray(x, y);
  if (!(aperture_ > 0.f)) return pinhole;
  // The focal plane is perpendicular to the view axis (a plane, not a sphere, as for a real
  // lens), so the in-focus point lies at focusDistance / cos(angle to the axis) along the ray.
  const vec3 focus =
      pinhole.origin +
      (focusDistance_ / glm::dot(pinhole.direction, pinhole_.forward())) * pinhole.direction;
  const vec2 d = aperture_ * concentricDisk(lens);
  const vec3 origin = position_ + d.x * pinhole_.right() + d.y * pinhole_.up();
  return {origin, glm::normalize(focus - origin)};
}

Ray thinLensRay(const Camera& c, int width, int height, float x, float y, vec2 lens) {
  return ThinLensFrame(c, width, height).ray(x, y, lens);
}

Camera frameBounds(const Aabb& b) {
  Camera c;
  const vec3 centre = b.empty() ? vec3(0.f) : b.center();
  // A point-like scene still gets a radius, relative to where it is (no absolute floor).
  const float radius = 0.5f * b.diagonal() > 0.f ? 0.5f * b.diagonal()
                                                 : std::max(1e-3f * glm::length(centre), 1e-30f);
  const float distance = radius / std::sin(0.5f * c.verticalFov) * 1.1f;
  c.target = centre;
  c.position = centre + vec3(0.f, 0.25f * radius, distance);
  c.znear = std::max(distance - radius, distance * 1e-3f) * 0.5f;
  c.zfar = distance + 2.f * radius;
  c.focusDistance = distance;
  return c;
}

void fitNearFar(Camera& c, const Aabb& b) {
  if (b.empty()) return;
  const vec3 p = c.position;
  const vec3 nearest = glm::clamp(p, b.lo, b.hi);
  const vec3 farthest = glm::max(glm::abs(p - b.lo), glm::abs(p - b.hi));
  const float zfar = 1.01f * glm::length(farthest);
  if (!(zfar > 0.f) || !std::isfinite(zfar)) return;
  c.zfar = zfar;
  c.znear = std::max(0.5f * glm::length(nearest - p), 1e-4f * zfar);
}

}  // namespace diptych
