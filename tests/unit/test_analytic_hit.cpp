// The analytic hit record (engine/scene/analytic_hit.h): a sphere hit carries its octahedral
// unit normal (Cigolle et al. 2014), a cylinder's or cone's wall its diamond angle and height,
// from which the point, the normal and, where a material reads them, the texture (u, v) are
// rebuilt. Checked: both encodings round-trip every direction to float precision; walls give
// the hit's point, normal and uv; at extreme scales and offsets the rebuilt point lies on the
// sphere and on the ray to float rounding, the normal is unit and radial, and the uv is the
// spherical parameters of the exact hit; makeSurfacePoint computes uv exactly when the material
// reads it.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "engine/rt/surface_point.h"
#include "engine/scene/analytic_hit.h"
#include "engine/scene/load.h"
#include "engine/scene/primitives.h"
#include "engine/shading/texture_sampling.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

constexpr double kPi = 3.141592653589793;
constexpr float kInf = std::numeric_limits<float>::infinity();

double angleBetween(const dvec3& a, const dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

dvec3 randomUnit(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double z = 2.0 * u(rng) - 1.0, phi = 2.0 * kPi * u(rng);
  const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
  return {s * std::cos(phi), s * std::sin(phi), z};
}

TEST(AnalyticHit, OctahedralEncodingRoundTripsEveryDirection) {
  std::mt19937 rng(14);
  std::vector<dvec3> dirs;
  for (int i = 0; i < 200000; ++i) dirs.push_back(randomUnit(rng));
  // The axes, the octahedron's vertices and edges, and the fold (z = +-0, tiny z).
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      dvec3 v(0.0);
      v[axis] = s;
      dirs.push_back(v);
    }
  for (double x : {1.0, -1.0})
    for (double y : {1.0, -1.0})
      for (double z : {1.0, -1.0, 1e-30, -1e-30, 0.0, -0.0})
        dirs.push_back(glm::normalize(dvec3(x, y, z)));
  double worst = 0.0;
  for (const dvec3& n : dirs) {
    const dvec3 back = octahedralDecode(octahedralEncode(n));
    ASSERT_NEAR(glm::length(back), 1.0, 1e-15);
    worst = std::max(worst, angleBetween(n, back));
  }
  // Two floats at 2^-24 of the [-1, 1] square: well under the 3.7e-7 rad of the former
  // (u, v) record (u = phi / 2 pi rounded to float).
  EXPECT_LT(worst, 2e-7);
  for (int axis = 0; axis < 3; ++axis)
    for (double s : {1.0, -1.0}) {
      dvec3 v(0.0);
      v[axis] = s;
      EXPECT_EQ(octahedralDecode(octahedralEncode(v)), v) << axis << " " << s;
    }
}

TEST(AnalyticHit, DiamondEncodingRoundTripsEveryDirectionAboutTheAxis) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * kPi);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double phi = angle(rng);
    const dvec2 v(std::cos(phi), std::sin(phi));
    const dvec2 back = diamondDecode(diamondEncode(v.x, v.y));
    ASSERT_NEAR(glm::length(back), 1.0, 1e-15);
    worst = std::max(worst, std::abs(std::atan2(v.x * back.y - v.y * back.x, glm::dot(v, back))));
  }
  EXPECT_LT(worst, 3e-7);  // a float's step near the ends of [-2, 2], 2.4e-7
  for (const dvec2 axis : {dvec2(1, 0), dvec2(0, 1), dvec2(-1, 0), dvec2(0, -1)})
    EXPECT_EQ(diamondDecode(diamondEncode(axis.x, axis.y)), axis);
  EXPECT_EQ(diamondDecode(diamondEncode(0.0, 0.0)), dvec2(1, 0));  // the cone's apex: +x
}

// Cylinder and cone walls, in object space at three sizes: the record's point is the exact hit's
// to float precision, its normal the one shapeNormal gives at the hit's uv, and its uv shapeUv's.
TEST(AnalyticHit, WallRecordsOfCylindersAndConesGiveTheHitsPointNormalAndUv) {
  std::mt19937 rng(10);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int tested = 0;
  for (const ShapeType type : {ShapeType::Cylinder, ShapeType::Cone}) {
    for (const double size : {1e-3, 1.0, 1e4}) {
      const AnalyticShape s{type, float(size), float(2.0 * size), true};
      for (int i = 0; i < 2000; ++i) {
        // A point on the wall (uv away from the cone's apex), aimed at from outside.
        const vec2 target(float(unit(rng)), float(0.02 + 0.9 * unit(rng)));
        const dvec3 p = shapePoint(s, 0, target), n = shapeNormal(s, 0, target);
        const dvec3 o = p + 3.0 * size * glm::normalize(n + 0.5 * randomUnit(rng));
        const auto hit = intersectPart(s, 0, o, p - o, 0.0, 2.0);
        if (!hit) continue;
        ++tested;
        const dvec3 q = o + hit->t * (p - o);
        dvec3 point, normal;
        shapeHitPointAndNormal(s, 0, hit->record, point, normal);
        EXPECT_LT(glm::length(point - q), 1e-6 * size);
        const vec2 expected = shapeUv(s, 0, q), uv = shapeHitUv(s, 0, hit->record);
        EXPECT_EQ(uv.y, expected.y);
        const float du = std::abs(uv.x - expected.x);
        EXPECT_LT(std::min(du, 1.f - du), 1e-6f);
        EXPECT_LT(angleBetween(normal, shapeNormal(s, 0, expected)), 1e-6);
        EXPECT_NEAR(glm::length(normal), 1.0, 1e-15);
      }
    }
  }
  EXPECT_GT(tested, 6000);
}

// Rays from random outside points at random points of a sphere of world radius 1e-3 .. 1e4,
// centred at the origin or 1e3 radii away; the hit record as Embree's callback makes it.
TEST(AnalyticHit, SpherePointNormalAndUvFromTheRecordAtExtremeScalesAndOffsets) {
  std::mt19937 rng(9);
  int tested = 0;
  for (double radius : {1e-3, 1.0, 1e4}) {
    for (double offset : {0.0, 1e3 * radius}) {
      Scene scene;
      Mesh mesh = makeUvSphere(1.f, 3, 2);
      mesh.analytic = AnalyticShape{ShapeType::Sphere, 0.5f};
      scene.meshes.push_back(mesh);
      const dvec3 centre = offset * glm::normalize(dvec3(1.0, -2.0, 3.0));
      const glm::dmat4 m = glm::scale(glm::translate(glm::dmat4(1.0), centre), dvec3(2.0 * radius));
      scene.instances.push_back({"sphere", 0, mat4(m)});
      const WorldGeometry world = flattenScene(scene);
      const AnalyticInstance& a = *world.meshes[0].analytic;
      const dvec3 c = dvec3(a.toWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0));
      const double mag = std::max({a.magnitude.x, a.magnitude.y, a.magnitude.z});
      for (int i = 0; i < 2000; ++i) {
        const vec3 o = vec3(c + radius * (3.0 * randomUnit(rng)));
        const vec3 d = vec3(glm::normalize(c + 0.9 * radius * randomUnit(rng) - dvec3(o)));
        const auto hit = intersectAnalytic(a, o, d, 0.f, kInf);
        if (!hit) continue;  // float cannot always aim at it
        ++tested;
        const dvec3 q = dvec3(o) + hit->t * dvec3(d);  // the exact hit, in double
        vec3 p, n;
        analyticHitPointAndNormal(a, hit->part, hit->record, p, n);
        const double eps = std::ldexp(1.0, -24);
        // On the sphere and on the ray: the record's 1e-7 rad plus the point's float rounding.
        EXPECT_NEAR(glm::length(dvec3(p) - c), radius, 4 * eps * mag + 2e-7 * radius);
        EXPECT_LE(glm::length(dvec3(p) - q), 4 * eps * mag + 2e-7 * radius);
        EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
        EXPECT_LT(angleBetween(dvec3(n), q - c), 1e-6);
        // The texture uv: the spherical parameters of the exact hit (shapeUv), as the record
        // before held them; u compared around the seam, and away from the poles where it is
        // undefined.
        const vec2 uv = analyticHitUv(a, hit->part, hit->record);
        const dvec3 qo = dvec3(a.toObject * glm::dvec4(q, 1.0));
        const vec2 expected = shapeUv(a.shape, 0, qo);
        EXPECT_NEAR(uv.y, expected.y, 1e-6);
        if (std::sin(kPi * expected.y) > 1e-3) {
          const float du = std::abs(uv.x - expected.x);
          EXPECT_LT(std::min(du, 1.f - du), 1e-6f);
        }
        EXPECT_LT(glm::length(shapePoint(a.shape, 0, uv) - qo), 2e-6);
      }
    }
  }
  EXPECT_GT(tested, 10000);
}

// makeSurfacePoint reads the texture uv from the record only when the material reads uv; the
// point and normal are the same either way.
TEST(AnalyticHit, SurfacePointHasUvExactlyWhenTheMaterialReadsIt) {
  Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  const WorldGeometry world = flattenScene(scene);
  int sphere = -1, checker = -1;
  for (std::size_t i = 0; i < world.meshes.size(); ++i)
    if (world.meshes[i].analytic && sphere < 0) sphere = int(i);
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].checker) checker = int(i);
  ASSERT_GE(sphere, 0);
  ASSERT_GE(checker, 0);
  const AnalyticInstance& a = *world.meshes[std::size_t(sphere)].analytic;
  const vec3 c = vec3(dvec3(a.toWorld * glm::dvec4(0.0, 0.0, 0.0, 1.0)));
  const vec3 origin = c + vec3(0.3f, 0.4f, 5.f), dir = glm::normalize(c - origin);
  const auto hit = intersectAnalytic(a, origin, dir, 0.f, kInf);
  ASSERT_TRUE(hit);
  const SurfaceHit sh{sphere, std::uint32_t(hit->part), hit->record.x, hit->record.y, true};
  const Material& own = scene.material(world.meshes[std::size_t(sphere)].material);
  ASSERT_FALSE(materialReadsUv(own)) << "whitted.json's spheres are untextured";
  const SurfacePoint plain = makeSurfacePoint(scene, world, sh, dir);
  EXPECT_EQ(plain.uv, vec2(0.f));
  // The same sphere with the checkerboard material: uv from the record, C from the checker.
  const int instance = world.meshes[std::size_t(sphere)].instance;
  scene.meshes[std::size_t(scene.instances[std::size_t(instance)].mesh)].material = checker;
  const WorldGeometry checkered = flattenScene(scene);
  const SurfacePoint p = makeSurfacePoint(scene, checkered, sh, dir);
  EXPECT_EQ(p.material, checker);
  EXPECT_EQ(p.uv, analyticHitUv(a, hit->part, hit->record));
  EXPECT_EQ(p.resolved.color, checkerColor(*scene.materials[std::size_t(checker)].checker, p.uv));
  EXPECT_EQ(p.position, plain.position);
  EXPECT_EQ(p.faceNormal, plain.faceNormal);
}

// materialReadsUv is a hand-kept list of the Material fields that resolveMaterial, normalMapped
// and the bump map read at uv: each such field set alone makes it true, a plain material none.
// Where cheap (colour and emission textures), resolveMaterial differs at two uvs.
TEST(AnalyticHit, MaterialReadsUvForEachUvReadingFieldAlone) {
  EXPECT_FALSE(materialReadsUv(Material{}));
  Material plain;
  plain.color = vec3(0.3f);
  plain.emission = vec3(1.f);
  plain.ks = 0.5f;
  plain.kt = 0.2f;
  plain.alphaMode = AlphaMode::Mask;
  EXPECT_FALSE(materialReadsUv(plain)) << "constants read no uv";
  std::vector<std::pair<const char*, Material>> readers;
  auto with = [&](const char* name, auto set) {
    Material m;
    set(m);
    readers.emplace_back(name, m);
  };
  with("checker", [](Material& m) { m.checker = Checker{}; });
  with("colorTexture", [](Material& m) { m.colorTexture = 0; });
  with("emissionTexture", [](Material& m) { m.emissionTexture = 0; });
  with("metallicRoughnessTexture", [](Material& m) { m.metallicRoughnessTexture = 0; });
  with("occlusionTexture", [](Material& m) { m.occlusionTexture = 0; });
  with("normalTexture", [](Material& m) { m.normalTexture = 0; });
  with("bump", [](Material& m) { m.bump = BumpMap{}; });
  for (const auto& [name, m] : readers) EXPECT_TRUE(materialReadsUv(m)) << name;

  // A 2 x 1 texture, black on the left, white on the right, nearest filtering.
  Scene scene;
  Texture t;
  t.image = Image(2, 1, 4, 1.f);
  for (int c = 0; c < 3; ++c) t.image.at(0, 0, c) = 0.f;
  t.minFilter = t.magFilter = FilterMode::Nearest;
  scene.textures.push_back(t);
  const vec2 left(0.25f, 0.5f), right(0.75f, 0.5f);
  for (const auto& [name, m] : readers) {
    if (std::string(name) == "colorTexture") {
      EXPECT_NE(resolveMaterial(scene, m, left).color, resolveMaterial(scene, m, right).color);
    } else if (std::string(name) == "emissionTexture") {
      Material e = m;
      e.emission = vec3(1.f);
      EXPECT_NE(resolveMaterial(scene, e, left).emission,
                resolveMaterial(scene, e, right).emission);
    }
  }
}
}  // namespace DIPTYCH_UNITY_ID
