#pragma once
// Small procedural meshes for ray-tracing tests and benchmarks (header-only; tests/unit and
// tests/bench both include it).
#include <cmath>
#include <numbers>

#include "engine/scene/scene.h"

namespace diptych::testgeo {

// UV sphere with vertices ON the sphere: its silhouette is an inscribed polygon, slightly
// inside the true sphere (by a factor cos(pi / segments) across the equator).
inline Mesh uvSphere(vec3 centre, float radius, int segments, int rings) {
  Mesh m;
  m.name = "uv sphere";
  const float pi = std::numbers::pi_v<float>;
  for (int j = 0; j <= rings; ++j) {
    const float theta = pi * float(j) / float(rings);  // from +y down to -y
    for (int i = 0; i <= segments; ++i) {
      const float phi = 2.f * pi * float(i) / float(segments);
      const vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                   -std::sin(theta) * std::sin(phi));
      m.positions.push_back(centre + radius * n);
      m.normals.push_back(n);
      m.uvs.push_back(vec2(float(i) / float(segments), float(j) / float(rings)));
    }
  }
  const auto index = [&](int i, int j) { return std::uint32_t(j * (segments + 1) + i); };
  for (int j = 0; j < rings; ++j) {
    for (int i = 0; i < segments; ++i) {
      // Counter-clockwise seen from outside.
      const std::uint32_t a = index(i, j), b = index(i, j + 1), c = index(i + 1, j + 1),
                          d = index(i + 1, j);
      if (j != 0) m.indices.insert(m.indices.end(), {a, b, d});
      if (j != rings - 1) m.indices.insert(m.indices.end(), {d, b, c});
    }
  }
  return m;
}

// Square in the plane y = height, |x|, |z| <= half, front face up (+y), uv = (x, z) mapped
// to [0, 1].
inline Mesh groundPlane(float half, float height = 0.f) {
  Mesh m;
  m.name = "ground";
  m.positions = {
      {-half, height, -half}, {-half, height, half}, {half, height, half}, {half, height, -half}};
  m.normals.assign(4, vec3(0.f, 1.f, 0.f));
  m.uvs = {{0.f, 0.f}, {0.f, 1.f}, {1.f, 1.f}, {1.f, 0.f}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// One instance per mesh, identity transforms.
inline Scene sceneOf(std::vector<Mesh> meshes) {
  Scene s;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    s.meshes.push_back(std::move(meshes[i]));
    s.instances.push_back(Instance{"instance " + std::to_string(i), int(i), mat4(1.f)});
  }
  return s;
}

}  // namespace diptych::testgeo
