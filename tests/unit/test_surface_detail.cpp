// Surface detail beyond triangle meshes and its comparison axis (engine/shading/surface_detail.h):
//  - the exact shapes' t_u, t_v (shapeDerivatives) are the derivatives of their parameterisation;
//  - bump mapping on an analytic sphere perturbs its exact normal with them, by the lecture's
//    formula;
//  - a normal map baked from a plane's height field gives the bump's normals;
//  - the displaced surface is P + k f_h N with the displaced surface's own normal, in closed form
//    on a plane and on a sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/analytic_tangents.h"
#include "engine/scene/load.h"
#include "engine/shading/surface_detail.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr double kPi = 3.14159265358979323846;

double angle(const vec3& a, const vec3& b) {  // atan2 in double: resolves angles below 1e-4
  const glm::dvec3 x(glm::normalize(a)), y(glm::normalize(b));
  return std::atan2(glm::length(glm::cross(x, y)), glm::dot(x, y));
}

Scene sceneFromJson(const std::string& name, const std::string& json) {
  const auto dir = ::diptych::testing::scratchDir("diptych_surface_detail");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << json;
  return loadScene(dir / name);
}

// A plane L x L (uv along x and z) and an analytic sphere, both with the sinusoid.
constexpr float kL = 2.f, kA = 0.04f, kK = 1.25f;
Scene bumpedScene() {
  return sceneFromJson("bumped.json", R"({"materials": {
    "p": {"bump": {"amplitude": 0.04, "frequency": [3, 2], "k": 1.25, "delta": 0.0005}},
    "s": {"bump": {"amplitude": 0.04, "frequency": [6, 3], "k": 1.25, "delta": 0.0005}}},
    "objects": [{"type": "plane", "size": [2, 2], "material": "p"},
                {"type": "sphere", "radius": 0.5, "geometry": "analytic", "material": "s",
                 "transform": {"translate": [0, 2, 0]}}]})");
}

// f_h of the plane's material and its closed-form normal on the plane (docs/materials.md).
vec3 planeExactNormal(vec2 uv) {
  const double a = 2 * kPi * 3 * uv.x, c = 2 * kPi * 2 * uv.y;
  const double fu = kA * 2 * kPi * 3 * std::cos(a) * std::cos(c);
  const double fv = -kA * 2 * kPi * 2 * std::sin(a) * std::sin(c);
  return vec3(glm::normalize(glm::dvec3(-kK * fu * kL, kL * kL, -kK * fv * kL)));
}

SurfacePoint hitStraightDown(const Scene& scene, RenderWorld& world, vec3 from) {
  const Ray ray{from, vec3(0.f, -1.f, 0.f)};
  const auto hit = world.rtScene().intersect(ray, 0.f, std::numeric_limits<float>::infinity());
  EXPECT_TRUE(hit.has_value());
  if (!hit) return {};
  return makeSurfacePoint(scene, world.geometry(),
                          {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
                          ray.direction);
}

TEST(SurfaceDetail, ShapeDerivativesAreTheParameterisationsDerivatives) {
  const AnalyticShape shapes[] = {{ShapeType::Sphere, 0.7f, 1.f, true},
                                  {ShapeType::Cylinder, 0.5f, 2.f, true},
                                  {ShapeType::Cone, 0.6f, 1.5f, true},
                                  {ShapeType::Disc, 0.8f, 1.f, true}};
  double worst = 0;
  for (const AnalyticShape& s : shapes)
    for (int part = 0; part < partCount(s); ++part)
      for (vec2 uv : {vec2(0.13f, 0.31f), vec2(0.62f, 0.77f), vec2(0.91f, 0.5f)}) {
        dvec3 du, dv;
        shapeDerivatives(s, part, uv, du, dv);
        const float h = 1.f / 1024.f;  // exact in float around these uv
        const dvec3 nu =
            (shapePoint(s, part, uv + vec2(h, 0.f)) - shapePoint(s, part, uv - vec2(h, 0.f))) /
            (2.0 * h);
        const dvec3 nv =
            (shapePoint(s, part, uv + vec2(0.f, h)) - shapePoint(s, part, uv - vec2(0.f, h))) /
            (2.0 * h);
        const double scale = std::max(glm::length(nu), glm::length(nv));
        worst = std::max({worst, glm::length(du - nu) / scale, glm::length(dv - nv) / scale});
        // And they span the tangent plane: t_u x t_v is along the normal (or against it).
        const dvec3 n = shapeNormal(s, part, uv), c = glm::cross(du, dv);
        EXPECT_NEAR(std::abs(glm::dot(c, n)) / glm::length(c), 1.0, 1e-9);
      }
  std::printf("[ measured ] worst relative difference to central differences %.3g\n", worst);
  EXPECT_LT(worst, 1e-4);  // central differences' own error: (2 pi f h)^2 / 6 ~ 6e-6
}

// The sphere (r = 0.5 at (0, 2, 0)) p = r (sin(theta) around(phi) + cos(theta) y), phi = 2 pi u,
// theta = pi v, around(phi) = (cos phi, 0, -sin phi): t_u, t_v in closed form here, d_u, d_v the
// sinusoid's exact derivatives times k, n' = normalize(t'_u x t'_v) on n's side. Away from the
// poles (sin theta > 0.2), where t_u vanishes and the sinusoid in u is not smooth on the sphere.
TEST(SurfaceDetail, BumpOnAnAnalyticSphereIsTheLecturesFormulaWithItsTangents) {
  const Scene scene = bumpedScene();
  RenderWorld world(scene);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> offset(-0.45f, 0.45f);
  double worst = 0, largest = 0;
  int tested = 0;
  for (int i = 0; i < 2000; ++i) {
    const float x = offset(rng), z = offset(rng);
    if (x * x + z * z > 0.45f * 0.45f) continue;  // inside the sphere's outline (r = 0.5)
    const SurfacePoint p = hitStraightDown(scene, world, vec3(x, 4.f, z));
    ASSERT_TRUE(p.hit.analytic);
    const double phi = 2 * kPi * p.uv.x, theta = kPi * p.uv.y, r = 0.5;
    if (std::sin(theta) < 0.2) continue;
    const glm::dvec3 around(std::cos(phi), 0, -std::sin(phi)), y(0, 1, 0);
    const glm::dvec3 tu =
        r * std::sin(theta) * 2 * kPi * glm::dvec3(-std::sin(phi), 0, -std::cos(phi));
    const glm::dvec3 tv = r * kPi * (std::cos(theta) * around - std::sin(theta) * y);
    const glm::dvec3 n = std::sin(theta) * around + std::cos(theta) * y;
    const double a = 2 * kPi * 6 * p.uv.x, c = 2 * kPi * 3 * p.uv.y;
    const double du = kK * kA * 2 * kPi * 6 * std::cos(a) * std::cos(c);
    const double dv = -kK * kA * 2 * kPi * 3 * std::sin(a) * std::sin(c);
    glm::dvec3 expected = glm::normalize(glm::cross(tu + du * n, tv + dv * n));
    if (glm::dot(expected, n) < 0) expected = -expected;
    worst = std::max(worst, angle(p.shadingNormal, vec3(expected)));
    largest = std::max(largest, angle(p.shadingNormal, p.faceNormal));
    ++tested;
  }
  std::printf(
      "[ measured ] analytic sphere, %d points: worst %.3g rad from the closed form, bump "
      "tilts up to %.3f rad\n",
      tested, worst, largest);
  EXPECT_GT(tested, 500);
  // The lecture's central difference against the exact derivative: (2 pi f Delta)^2 / 6 = 5.9e-5
  // relative at f = 6, Delta = 0.0005.
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(largest, 0.2);  // the exact normal is perturbed, not kept
}

TEST(SurfaceDetail, NormalMapBakedFromThePlanesHeightGivesTheBumpsNormals) {
  const Scene bumped = bumpedScene();
  const Scene mapped = withSurfaceDetail(bumped, SurfaceDetail::NormalMap);
  ASSERT_FALSE(mapped.materials[0].bump.has_value());
  ASSERT_GE(mapped.materials[0].normalTexture, 0);
  RenderWorld bumpWorld(bumped), mapWorld(mapped);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> at(-0.95f, 0.95f);
  double worst = 0, worstExact = 0;
  for (int i = 0; i < 2000; ++i) {
    const vec3 from(at(rng), 1.f, at(rng));
    const SurfacePoint b = hitStraightDown(bumped, bumpWorld, from);
    const SurfacePoint m = hitStraightDown(mapped, mapWorld, from);
    worst = std::max(worst, angle(b.shadingNormal, m.shadingNormal));
    worstExact = std::max(worstExact, angle(m.shadingNormal, planeExactNormal(m.uv)));
  }
  // Bilinear interpolation between texel centres (128 texels, 43 per period of f_u = 3) is the
  // error: about (pi / 43)^2 / 2 of the slope's swing.
  std::printf("[ measured ] baked normal map vs bump: worst %.3g rad (vs closed form %.3g)\n",
              worst, worstExact);
  EXPECT_LT(worst, 3e-3);
  EXPECT_LT(worstExact, 3e-3);
}

TEST(SurfaceDetail, DisplacedSurfacesAreMovedByTheHeightWithTheirOwnNormals) {
  const Scene bumped = bumpedScene();
  const Scene displaced = withSurfaceDetail(bumped, SurfaceDetail::Displaced);
  ASSERT_EQ(displaced.instances.size(), 2u);
  const auto f = [](vec2 uv, vec2 freq) {
    return kA * std::sin(2 * kPi * freq.x * uv.x) * std::cos(2 * kPi * freq.y * uv.y);
  };
  // Plane: y = k f_h(u, v) at every vertex, the normal the closed form (no curvature term).
  const Mesh& plane = displaced.meshes[std::size_t(displaced.instances[0].mesh)];
  EXPECT_FALSE(plane.analytic.has_value());
  EXPECT_GE(plane.triangleCount(), 2u * 48 * 48);  // >= 16 samples per period of f = 3
  double worstY = 0, worstN = 0;
  for (std::size_t i = 0; i < plane.positions.size(); ++i) {
    worstY = std::max(worstY, std::abs(plane.positions[i].y - kK * f(plane.uvs[i], vec2(3, 2))));
    worstN = std::max(worstN, angle(plane.normals[i], planeExactNormal(plane.uvs[i])));
  }
  // Sphere (tessellated first, so its vertices are on the sphere): |Q - c| = r + k f_h.
  const Mesh& sphere = displaced.meshes[std::size_t(displaced.instances[1].mesh)];
  double worstR = 0;
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    const double r = glm::length(sphere.positions[i] - vec3(0.f, 2.f, 0.f));
    worstR = std::max(worstR, std::abs(r - (0.5 + kK * f(sphere.uvs[i], vec2(6, 3)))));
  }
  std::printf(
      "[ measured ] displaced plane: %zu triangles, worst height error %.3g, normal %.3g "
      "rad; sphere: %zu triangles, worst radius error %.3g\n",
      plane.triangleCount(), worstY, worstN, sphere.triangleCount(), worstR);
  EXPECT_LT(worstY, 1e-6);
  EXPECT_LT(worstN, 1e-5);
  EXPECT_LT(worstR, 1e-5);
  EXPECT_FALSE(displaced.materials[0].bump.has_value());
  EXPECT_TRUE(bumped.materials[0].bump.has_value());  // the input is not changed
}

TEST(SurfaceDetail, FlatDropsTheBumpAndBumpKeepsTheScene) {
  const Scene bumped = bumpedScene();
  EXPECT_TRUE(hasBumpMaps(bumped));
  EXPECT_FALSE(hasBumpMaps(withSurfaceDetail(bumped, SurfaceDetail::Flat)));
  EXPECT_TRUE(hasBumpMaps(withSurfaceDetail(bumped, SurfaceDetail::Bump)));
  EXPECT_EQ(parseSurfaceDetail("normal_map"), SurfaceDetail::NormalMap);
  EXPECT_FALSE(parseSurfaceDetail("normal-map").has_value());
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
