#include "engine/rt/light_sampling.h"

#include <algorithm>
#include <cmath>

#include "engine/scene/camera_math.h"

namespace diptych {
namespace {

constexpr float kPi = 3.14159265358979f;

}  // namespace

std::uint32_t pcgHash(std::uint32_t v) {
  const std::uint32_t state = v * 747796405u + 2891336453u;
  const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

void orthonormalBasis(const vec3& n, vec3& t, vec3& b) {
  const float sign = std::copysign(1.f, n.z);
  const float a = -1.f / (sign + n.z);
  const float c = n.x * n.y * a;
  t = vec3(1.f + sign * n.x * n.x * a, sign * c, -sign * n.x);
  b = vec3(c, sign + n.y * n.y * a, -n.y);
}

bool isAreaLight(const Light& l) {
  return l.type == LightType::QuadArea || l.type == LightType::DiscArea ||
         l.type == LightType::SphereArea;
}

int stratifiedSampleCount(int requested) {
  const int k = std::max(1, int(std::lround(std::sqrt(double(std::max(requested, 1))))));
  return k * k;
}

vec2 stratifiedSample(int index, int count, std::uint32_t seed) {
  const int k = std::max(1, int(std::lround(std::sqrt(double(count)))));
  const std::uint32_t h1 = pcgHash(seed ^ pcgHash(std::uint32_t(index)));
  const std::uint32_t h2 = pcgHash(h1);
  return vec2((float(index % k) + unitFloat(h1)) / float(k),
              (float(index / k % k) + unitFloat(h2)) / float(k));
}

vec3 areaLightPoint(const Light& l, vec2 s, const vec3& receiver) {
  switch (l.type) {
    case LightType::QuadArea:
      return l.position + (s.x - 0.5f) * l.edgeU + (s.y - 0.5f) * l.edgeV;
    case LightType::DiscArea: {
      const vec2 d = concentricDisk(s);  // strata-preserving square -> unit disc
      vec3 t, b;
      orthonormalBasis(glm::normalize(l.direction), t, b);
      return l.position + l.radius * (d.x * t + d.y * b);
    }
    case LightType::SphereArea: {
      const vec3 toReceiver = receiver - l.position;
      const float len = glm::length(toReceiver);
      const vec3 axis = len > 0.f ? toReceiver / len : vec3(0.f, 1.f, 0.f);
      vec3 t, b;
      orthonormalBasis(axis, t, b);
      const float cosTheta = s.x;
      const float sinTheta = std::sqrt(std::max(0.f, 1.f - cosTheta * cosTheta));
      const float phi = 2.f * kPi * s.y;
      return l.position +
             l.radius * (cosTheta * axis + sinTheta * (std::cos(phi) * t + std::sin(phi) * b));
    }
    default:
      return l.position;
  }
}

vec3 directionAbout(const vec3& axis, float cosT, float phi) {
  const float sinT = std::sqrt(std::max(0.f, 1.f - cosT * cosT));
  vec3 t, b;
  orthonormalBasis(axis, t, b);
  return glm::normalize(cosT * axis + sinT * (std::cos(phi) * t + std::sin(phi) * b));
}

vec3 sampleCosine(const vec3& n, vec2 u) {
  const vec2 d = concentricDisk(u);
  const float z = std::sqrt(std::max(0.f, 1.f - glm::dot(d, d)));
  vec3 t, b;
  orthonormalBasis(n, t, b);
  return glm::normalize(d.x * t + d.y * b + z * n);
}

}  // namespace diptych
