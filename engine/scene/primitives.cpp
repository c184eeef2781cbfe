#include "engine/scene/primitives.h"

#include <algorithm>
#include <cmath>

#include "engine/scene/sdf.h"

namespace diptych {
namespace {

constexpr float kPi = glm::pi<float>();

std::uint32_t addVertex(Mesh& m, vec3 p, vec3 n, vec2 uv) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  m.uvs.push_back(uv);
  return std::uint32_t(m.positions.size() - 1);
}

void addTriangle(Mesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  m.indices.insert(m.indices.end(), {a, b, c});
}

// Direction in the xz plane at angle phi, turning counter-clockwise seen from +y, so that the
// ring orders below give outward-facing counter-clockwise triangles.
vec3 around(float phi) {
  return vec3(std::cos(phi), 0.f, -std::sin(phi));
}

// Fan of `slices` triangles closing a circle at height y, facing +y (up) or -y.
void addCap(Mesh& m, float radius, float y, int slices, bool up) {
  const vec3 normal(0.f, up ? 1.f : -1.f, 0.f);
  const std::uint32_t centre = addVertex(m, vec3(0.f, y, 0.f), normal, vec2(0.5f));
  const std::uint32_t first = std::uint32_t(m.positions.size());
  for (int i = 0; i <= slices; ++i) {
    const vec3 d = around(2.f * kPi * float(i) / float(slices));
    addVertex(m, vec3(0.f, y, 0.f) + radius * d, normal,
              vec2(0.5f + 0.5f * d.x, 0.5f + 0.5f * d.z));
  }
  for (int i = 0; i < slices; ++i) {
    if (up)
      addTriangle(m, centre, first + i, first + i + 1);
    else
      addTriangle(m, centre, first + i + 1, first + i);
  }
}

}  // namespace

Mesh makePlane(vec2 size, ivec2 segments) {
  segments = glm::max(segments, ivec2(1));
  Mesh m;
  m.name = "plane";
  for (int j = 0; j <= segments.y; ++j) {
    for (int i = 0; i <= segments.x; ++i) {
      const vec2 uv(float(i) / segments.x, float(j) / segments.y);
      addVertex(m, vec3((uv.x - 0.5f) * size.x, 0.f, (uv.y - 0.5f) * size.y), vec3(0, 1, 0), uv);
    }
  }
  const std::uint32_t row = segments.x + 1;
  for (int j = 0; j < segments.y; ++j) {
    for (int i = 0; i < segments.x; ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      // x right, z towards the viewer: (a, c, d) is counter-clockwise seen from +y.
      addTriangle(m, a, c, d);
      addTriangle(m, a, d, b);
    }
  }
  return m;
}

Mesh makeQuad(const std::array<vec3, 4>& p) {
  // Newell's method: n = sum over edges of cross(p_i, p_i+1), twice the vector area.
  vec3 n(0.f);
  for (int i = 0; i < 4; ++i) n += glm::cross(p[i], p[(i + 1) % 4]);
  const float len = glm::length(n);
  n = len > 0.f ? n / len : vec3(0.f, 1.f, 0.f);
  Mesh m;
  m.name = "quad";
  const vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int i = 0; i < 4; ++i) addVertex(m, p[i], n, uv[i]);
  addTriangle(m, 0, 1, 2);
  addTriangle(m, 0, 2, 3);
  return m;
}

Mesh makeBox(vec3 size) {
  Mesh m;
  m.name = "box";
  const vec3 h = 0.5f * size;
  // Each face: its normal and two in-plane axes u, v with cross(u, v) = normal.
  const vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const vec3& n : normals) {
    const vec3 u = std::abs(n.y) > 0.f ? vec3(1, 0, 0) * n.y : glm::cross(vec3(0, 1, 0), n);
    const vec3 v = glm::cross(n, u);
    const std::uint32_t base = std::uint32_t(m.positions.size());
    const vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (const vec2& c : corners) addVertex(m, h * (n + c.x * u + c.y * v), n, 0.5f * (c + 1.f));
    addTriangle(m, base, base + 1, base + 2);
    addTriangle(m, base, base + 2, base + 3);
  }
  return m;
}

Mesh makeUvSphere(float radius, int slices, int stacks) {
  slices = std::max(slices, 3);
  stacks = std::max(stacks, 2);
  Mesh m;
  m.name = "sphere";
  for (int j = 0; j <= stacks; ++j) {
    const float v = float(j) / stacks, theta = kPi * v;
    for (int i = 0; i <= slices; ++i) {
      const float u = float(i) / slices;
      const vec3 n = std::sin(theta) * around(2.f * kPi * u) + vec3(0.f, std::cos(theta), 0.f);
      addVertex(m, radius * n, n, vec2(u, v));
    }
  }
  const std::uint32_t row = slices + 1;
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      // a-b along increasing phi (counter-clockwise from above), c-d one stack lower.
      if (j != 0) addTriangle(m, a, c, b);
      if (j != stacks - 1) addTriangle(m, b, c, d);
    }
  }
  return m;
}

Mesh makeDisc(float radius, int slices) {
  Mesh m;
  addCap(m, radius, 0.f, std::max(slices, 3), true);
  m.name = "disc";
  return m;
}

Mesh makeCylinder(float radius, float height, int slices, bool capped) {
  slices = std::max(slices, 3);
  Mesh m;
  m.name = "cylinder";
  const float y0 = -0.5f * height, y1 = 0.5f * height;
  for (int i = 0; i <= slices; ++i) {
    const float u = float(i) / slices;
    const vec3 d = around(2.f * kPi * u);
    addVertex(m, radius * d + vec3(0, y0, 0), d, vec2(u, 0.f));
    addVertex(m, radius * d + vec3(0, y1, 0), d, vec2(u, 1.f));
  }
  for (int i = 0; i < slices; ++i) {
    const std::uint32_t bottom = 2 * i, top = bottom + 1, nextBottom = bottom + 2,
                        nextTop = bottom + 3;
    addTriangle(m, bottom, nextBottom, nextTop);
    addTriangle(m, bottom, nextTop, top);
  }
  if (capped) {
    addCap(m, radius, y1, slices, true);
    addCap(m, radius, y0, slices, false);
  }
  return m;
}

Mesh makeCone(float radius, float height, int slices, bool capped) {
  slices = std::max(slices, 3);
  Mesh m;
  m.name = "cone";
  const float y0 = -0.5f * height, y1 = 0.5f * height;
  auto sideNormal = [&](float phi) {
    const vec3 d = around(phi);
    return glm::normalize(vec3(height * d.x, radius, height * d.z));
  };
  for (int i = 0; i < slices; ++i) {
    const float phi0 = 2.f * kPi * i / slices, phi1 = 2.f * kPi * (i + 1) / slices;
    const float u0 = float(i) / slices, u1 = float(i + 1) / slices;
    const std::uint32_t a =
        addVertex(m, radius * around(phi0) + vec3(0, y0, 0), sideNormal(phi0), vec2(u0, 0.f));
    const std::uint32_t b =
        addVertex(m, radius * around(phi1) + vec3(0, y0, 0), sideNormal(phi1), vec2(u1, 0.f));
    const std::uint32_t apex =
        addVertex(m, vec3(0, y1, 0), sideNormal(0.5f * (phi0 + phi1)), vec2(0.5f * (u0 + u1), 1.f));
    addTriangle(m, a, b, apex);
  }
  if (capped) addCap(m, radius, y0, slices, false);
  return m;
}

Scene tessellateAnalytic(const Scene& scene, int segments) {
  Scene out = scene;
  for (Mesh& m : out.meshes) {
    if (m.sdf) {
      const SdfObject& o = *m.sdf;
      const double evaluations = std::pow(double(segments) + 1.0, 3.0) * double(o.sdf.nodes.size());
      if (evaluations > kMaxSdfEvaluations) {
        out.warnings.push_back("SDF object '" + m.name + "' kept exact: polygonising it at " +
                               std::to_string(segments) + " cells exceeds the evaluation budget");
        continue;
      }
      Mesh t = polygonizeSdf(o.sdf, o.lo, o.hi, segments);
      t.name = m.name;
      t.material = m.material;
      m = std::move(t);  // no sdf: traced as the triangles
      continue;
    }
    if (!m.analytic) continue;
    const AnalyticShape s = *m.analytic;
    Mesh t;
    switch (s.type) {
      case ShapeType::Sphere:
        t = makeUvSphere(s.radius, segments, segments / 2);
        break;
      case ShapeType::Disc:
        t = makeDisc(s.radius, segments);
        break;
      case ShapeType::Cylinder:
        t = makeCylinder(s.radius, s.height, segments, s.capped);
        break;
      case ShapeType::Cone:
        t = makeCone(s.radius, s.height, segments, s.capped);
        break;
    }
    t.name = m.name;
    t.material = m.material;
    m = std::move(t);
  }
  return out;
}

}  // namespace diptych
