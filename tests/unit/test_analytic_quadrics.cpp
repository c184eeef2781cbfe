// Analytic quadrics (engine/scene/analytic_shape.h) and their Embree user geometry: hits at known
// t, rays from inside, tangent rays, rays along the axis, the tessellation's uv/normal
// parameterisation, transforms with non-uniform scale and mirrors, and degenerate shapes
// rejected at load.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "engine/core/error.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/analytic_hit.h"
#include "engine/scene/load.h"
#include "engine/scene/primitives.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::optional<ShapeHit> hitOf(const AnalyticShape& s, dvec3 o, dvec3 d) {
  return intersectShape(s, o, d, 0.0, kInf);
}

AnalyticShape shape(ShapeType type, float radius, float height = 1.f, bool capped = true) {
  return AnalyticShape{type, radius, height, capped};
}

TEST(AnalyticQuadrics, SphereKnownTInsideTangentAndMiss) {
  const AnalyticShape s = shape(ShapeType::Sphere, 2.f);
  auto hit = hitOf(s, {0, 0, -10}, {0, 0, 1});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 8.0);
  // Unnormalised direction: t in units of |d|.
  hit = hitOf(s, {0, 0, -10}, {0, 0, 4});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 2.0);
  // From inside: the far root.
  hit = hitOf(s, {0, 0.5, 0}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.5);
  // Just inside the tangent line: hits near the tangent point; just outside: misses; exactly
  // tangent: finite if it hits at all.
  hit = hitOf(s, {2.0 - 1e-9, 0, -10}, {0, 0, 1});
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 10.0, 1e-3);
  EXPECT_FALSE(hitOf(s, {2.0 + 1e-9, 0, -10}, {0, 0, 1}));
  if (auto t = hitOf(s, {2.0, 0, -10}, {0, 0, 1})) {
    EXPECT_NEAR(t->t, 10.0, 1e-6);
  }
  // Pointing away, and behind tmax.
  EXPECT_FALSE(hitOf(s, {0, 0, -10}, {0, 0, -1}));
  EXPECT_FALSE(intersectShape(s, {0, 0, -10}, {0, 0, 1}, 0.0, 7.9));
  // Far from the origin the stable form keeps the near root accurate (a naive
  // (-b - sqrt(b^2 - ac)) / a loses it to cancellation).
  hit = hitOf(s, {0, 0, -1e7}, {0, 0, 1});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1e7 - 2.0);
}

TEST(AnalyticQuadrics, SphereGrazingRaysAtEveryScaleHitInsideAndMissOutside) {
  // sphereHit rejects clear misses by the naive discriminant before its careful one: a ray
  // passing a millionth of the radius inside the rim must still hit, from near and far, at every
  // scale and with unnormalised directions, and one that far outside must miss.
  for (const float r : {1e-3f, 1.f, 1e3f}) {
    const AnalyticShape s = shape(ShapeType::Sphere, r);
    for (const double distance : {3.0, 1e4}) {
      for (const double length : {1.0, 1e-2, 1e3}) {
        const dvec3 d(0.0, 0.0, length);
        const double z = -distance * double(r);
        const auto inside = hitOf(s, {double(r) * (1.0 - 1e-6), 0.0, z}, d);
        ASSERT_TRUE(inside) << "r " << r << " distance " << distance << " |d| " << length;
        EXPECT_NEAR(inside->t * length, -z, 1e-2 * double(r));
        EXPECT_FALSE(hitOf(s, {double(r) * (1.0 + 1e-6), 0.0, z}, d))
            << "r " << r << " distance " << distance << " |d| " << length;
        // Far off to the side: the early rejection; the same answer as ever.
        EXPECT_FALSE(hitOf(s, {3.0 * double(r), 0.0, z}, d));
      }
    }
  }
}

TEST(AnalyticQuadrics, DiscBothSidesAndEdge) {
  const AnalyticShape s = shape(ShapeType::Disc, 1.f);
  auto hit = hitOf(s, {0.5, 3, 0.2}, {0, -1, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 3.0);
  EXPECT_FLOAT_EQ(hit->record.x, 0.75f);
  EXPECT_FLOAT_EQ(hit->record.y, 0.6f);
  hit = hitOf(s, {0.5, -3, 0.2}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 3.0);
  EXPECT_FALSE(hitOf(s, {1.01, 3, 0}, {0, -1, 0}));
  EXPECT_FALSE(hitOf(s, {0, 0, -3}, {0, 0, 1}));  // in the plane: parallel
}

TEST(AnalyticQuadrics, CylinderSideCapsAxisAndInside) {
  const AnalyticShape capped = shape(ShapeType::Cylinder, 1.f, 2.f, true);
  const AnalyticShape open = shape(ShapeType::Cylinder, 1.f, 2.f, false);
  auto hit = hitOf(capped, {-5, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 4.0);
  EXPECT_EQ(hit->part, 0);
  // Along the axis: the bottom cap when capped, nothing when open.
  hit = hitOf(capped, {0, -5, 0}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 4.0);
  EXPECT_EQ(hit->part, 2);
  EXPECT_FALSE(hitOf(open, {0, -5, 0}, {0, 1, 0}));
  // From inside: the wall, and the top cap.
  hit = hitOf(capped, {0, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 1.0);
  hit = hitOf(capped, {0, 0, 0}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->part, 1);
  EXPECT_DOUBLE_EQ(hit->t, 1.0);
  // Inside an open tube, a ray leaving through the open end meets nothing; one aimed at the
  // inner wall meets it.
  EXPECT_FALSE(hitOf(open, {0, 0, 0}, {0, 1, 0}));
  hit = hitOf(open, {0, 3, 0}, {0.3, -1, 0});  // in through the top, x = 1 at y = -1/3
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->t, 10.0 / 3.0, 1e-12);
  // Beyond the height: the infinite cylinder's root is rejected.
  EXPECT_FALSE(hitOf(open, {-5, 1.5, 0}, {1, 0, 0}));
}

TEST(AnalyticQuadrics, ConeSideApexAxisAndBase) {
  const AnalyticShape s = shape(ShapeType::Cone, 1.f, 2.f, true);  // apex y = 1, base y = -1
  auto hit = hitOf(s, {-5, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 4.5);  // radius (r/h)(h/2 - y) = 0.5 at y = 0
  // Normal ~ (h cos phi, r, -h sin phi) at phi = pi: (-2, 1, 0) / sqrt 5.
  dvec3 p, n;
  shapeHitPointAndNormal(s, 0, hit->record, p,
                         n);  // hit->record: the wall's record (analytic_hit.h)
  EXPECT_NEAR(n.x, -2.0 / std::sqrt(5.0), 1e-7);
  EXPECT_NEAR(n.y, 1.0 / std::sqrt(5.0), 1e-7);
  // Down the axis onto the apex (a double root), up the axis onto the base.
  hit = hitOf(s, {0, 5, 0}, {0, -1, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 4.0);
  hit = hitOf(s, {0, -5, 0}, {0, 1, 0});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->part, 1);
  EXPECT_DOUBLE_EQ(hit->t, 4.0);
  // The upper nappe of the double cone is not part of the shape.
  EXPECT_FALSE(hitOf(s, {-5, 2, 0}, {1, 0, 0}));
  // From inside: the wall.
  hit = hitOf(s, {0, 0, 0}, {1, 0, 0});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 0.5);
}

// The exact surface has the tessellation's parameterisation: every vertex of the tessellated
// mesh lies at shapePoint(its uv), with shapeNormal(its uv) as its normal, and shapeUv inverts
// shapePoint; the tangent is d p / d u.
TEST(AnalyticQuadrics, UvNormalsAndTangentsMatchTheTessellation) {
  struct Case {
    AnalyticShape s;
    Mesh mesh;
  };
  const Case cases[] = {
      {shape(ShapeType::Sphere, 1.5f), makeUvSphere(1.5f, 24, 12)},
      {shape(ShapeType::Disc, 0.7f), makeDisc(0.7f, 16)},
      {shape(ShapeType::Cylinder, 0.5f, 2.f, true), makeCylinder(0.5f, 2.f, 16, true)},
      {shape(ShapeType::Cone, 1.f, 3.f, true), makeCone(1.f, 3.f, 16, true)},
  };
  for (const Case& c : cases) {
    int checked = 0;
    for (std::size_t i = 0; i < c.mesh.positions.size(); ++i) {
      const vec3 p = c.mesh.positions[i], n = c.mesh.normals[i];
      const vec2 uv = c.mesh.uvs[i];
      // The part: planar vertices (normal +-y on a cap or disc) vs the curved surface.
      int part = 0;
      if (c.s.type == ShapeType::Cylinder && std::abs(n.y) == 1.f) part = n.y > 0.f ? 1 : 2;
      if (c.s.type == ShapeType::Cone && n.y == -1.f) part = 1;
      // The cone's apex vertices carry the normal of their slice centre, not of u = their uv;
      // skip them (their position is still checked).
      const bool apex = c.s.type == ShapeType::Cone && part == 0 && uv.y == 1.f;
      const dvec3 q = shapePoint(c.s, part, uv);
      EXPECT_LT(glm::length(q - dvec3(p)), 1e-6) << int(c.s.type) << " vertex " << i;
      if (!apex) {
        EXPECT_GT(glm::dot(shapeNormal(c.s, part, uv), dvec3(n)), 1.0 - 1e-6)
            << int(c.s.type) << " vertex " << i;
      }
      ++checked;
    }
    // Round trip and tangent on a grid of interior parameters of every part (vertices sit on
    // the seam, the poles, the rims and the centres, where uv is singular or clamped).
    for (int part = 0; part < partCount(c.s); ++part) {
      for (float u : {0.13f, 0.37f, 0.61f, 0.89f}) {
        for (float v : {0.13f, 0.37f, 0.61f, 0.89f}) {
          const vec2 uv(u, v);
          const dvec3 q = shapePoint(c.s, part, uv);
          const vec2 back = shapeUv(c.s, part, q);
          EXPECT_NEAR(back.x, uv.x, 1e-6) << int(c.s.type) << " part " << part;
          EXPECT_NEAR(back.y, uv.y, 1e-6) << int(c.s.type) << " part " << part;
          const float du = 1e-3f;
          const dvec3 fd = glm::normalize(shapePoint(c.s, part, uv + vec2(du, 0.f)) -
                                          shapePoint(c.s, part, uv - vec2(du, 0.f)));
          EXPECT_GT(glm::dot(fd, shapeTangent(c.s, part, uv)), 1.0 - 1e-5);
          EXPECT_NEAR(glm::dot(shapeTangent(c.s, part, uv), shapeNormal(c.s, part, uv)), 0.0,
                      1e-12);
        }
      }
    }
    EXPECT_GT(checked, 10) << int(c.s.type);
  }
}

// A sphere scaled (2, 0.5, -1) -- non-uniform and mirrored -- and moved: Embree's user
// geometry finds the ellipsoid's exact t and its gradient normal (x/a^2, y/b^2, z/c^2), outward
// despite the negative determinant; the hit rebuilds to the point on the ray.
TEST(AnalyticQuadrics, EmbreeUserGeometryWithNonUniformMirroredTransform) {
  Scene scene;
  Mesh mesh = makeUvSphere(1.f, 16, 8);
  mesh.analytic = shape(ShapeType::Sphere, 1.f);
  scene.meshes.push_back(mesh);
  const mat4 transform =
      glm::scale(glm::translate(mat4(1.f), vec3(3.f, 1.f, -2.f)), vec3(2.f, 0.5f, -1.f));
  scene.instances.push_back({"ellipsoid", 0, transform});
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  RtScene rt(device, world, scene);
  EXPECT_EQ(rt.analyticGeometries(), 1);

  auto hit = rt.intersect({{-10.f, 1.f, -2.f}, {1.f, 0.f, 0.f}}, 0.f, 1e30f);
  ASSERT_TRUE(hit);
  EXPECT_TRUE(hit->analytic);
  EXPECT_FLOAT_EQ(hit->t, 11.f);  // x = 3 - 2
  hit = rt.intersect({{3.f, -10.f, -2.f}, {0.f, 1.f, 0.f}}, 0.f, 1e30f);
  ASSERT_TRUE(hit);
  EXPECT_FLOAT_EQ(hit->t, 10.5f);  // y = 1 - 0.5

  const glm::dvec3 o(-4.0, 3.0, 5.0);
  const glm::dvec3 target(3.5, 1.2, -2.3);  // inside the ellipsoid
  const vec3 d = vec3(glm::normalize(target - o));
  hit = rt.intersect({vec3(o), d}, 0.f, 1e30f);
  ASSERT_TRUE(hit);
  const SurfacePoint p =
      makeSurfacePoint(scene, world, {hit->instance, hit->primitive, hit->u, hit->v, true}, d);
  const glm::dvec3 onRay = o + double(hit->t) * glm::dvec3(d);
  EXPECT_LT(glm::length(glm::dvec3(p.position) - onRay), 1e-5);
  const glm::dvec3 local = onRay - glm::dvec3(3.0, 1.0, -2.0);
  const glm::dvec3 gradient = glm::normalize(local / glm::dvec3(4.0, 0.25, 1.0));
  EXPECT_GT(glm::dot(glm::dvec3(p.faceNormal), gradient), 1.0 - 1e-5);
  EXPECT_TRUE(p.frontFacing);
  EXPECT_GT(glm::dot(glm::normalize(hit->Ng), p.faceNormal), 1.f - 1e-5f);
  // Without the normal (the tracers' call): the same hit bit for bit, Ng left 0.
  const auto bare = rt.intersect({vec3(o), d}, 0.f, 1e30f, /*wantNormal=*/false);
  ASSERT_TRUE(bare);
  EXPECT_EQ(bare->instance, hit->instance);
  EXPECT_EQ(bare->primitive, hit->primitive);
  EXPECT_EQ(bare->u, hit->u);
  EXPECT_EQ(bare->v, hit->v);
  EXPECT_EQ(bare->t, hit->t);
  EXPECT_EQ(bare->Ng, vec3(0.f));
  // Occlusion through the same callbacks.
  EXPECT_TRUE(rt.occluded(vec3(o), d, 0.f, 1e30f));
  EXPECT_FALSE(rt.occluded(vec3(o), d, 0.f, 0.5f * hit->t));
  // Switched off, the same scene traces the tessellation.
  RtScene triangles(device, world, scene, {.analytic = false});
  EXPECT_EQ(triangles.analyticGeometries(), 0);
  const auto tri = triangles.intersect({vec3(o), d}, 0.f, 1e30f);
  ASSERT_TRUE(tri);
  EXPECT_FALSE(tri->analytic);
}

TEST(AnalyticQuadrics, DegenerateShapesAreRejectedAtLoadByName) {
  const auto dir = diptych::testing::scratchDir("diptych_test_analytic_quadrics");
  std::filesystem::create_directories(dir);
  auto error = [&](const std::string& object) {
    const auto file = dir / "degenerate.json";
    std::ofstream(file) << R"({"objects": [)" << object << "]}";
    try {
      loadScene(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string zeroRadius =
      error(R"({"type": "sphere", "radius": 0, "geometry": "analytic"})");
  EXPECT_NE(zeroRadius.find("objects[0].radius"), std::string::npos) << zeroRadius;
  const std::string zeroHeight =
      error(R"({"type": "cone", "radius": 1, "height": 0, "geometry": "analytic"})");
  EXPECT_NE(zeroHeight.find("objects[0].height"), std::string::npos) << zeroHeight;
  const std::string badKind = error(R"({"type": "disc", "geometry": "exact"})");
  EXPECT_NE(badKind.find("objects[0].geometry"), std::string::npos) << badKind;
  const std::string notQuadric = error(R"({"type": "box", "geometry": "analytic"})");
  EXPECT_NE(notQuadric.find("objects[0].geometry"), std::string::npos) << notQuadric;
  EXPECT_EQ(error(R"({"type": "cylinder", "capped": false, "geometry": "analytic"})"), "");
}
}  // namespace DIPTYCH_UNITY_ID
