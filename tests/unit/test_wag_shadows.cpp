// wag_shadows (the lecture's Weiler-Atherton-Greenberg object-precision shadows,
// engine/scene/lit_polygons.h): the lit pieces of each triangle, checked polygon by polygon
// against closed forms, and the frame's visibility against rt_shadows' on the same G-buffer.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "engine/scene/lit_polygons.h"
#include "engine/scene/load.h"
#include "passes/slots.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

struct Mismatch {
  int covered = 0, exactShadow = 0, wagShadow = 0, mismatched = 0;
};

// Every light's visibility from wag_shadows and rt_shadows on one frame each.
Mismatch compareWithRtShadows(const std::filesystem::path& file, int w, int h) {
  Recipe recipe = defaultHybridRecipe();
  applySlotOverride(recipe, parseSlotOverride("visibility=wag_shadows"), builtinPasses());
  auto wag = diptych::testing::renderHybridFrame(file, w, h, {"shadows.visibility", "gbuffer.hits"},
                                                 recipe);
  auto exact = diptych::testing::renderHybridFrame(file, w, h, {"shadows.visibility"});
  const CpuImage& hits = wag->output("gbuffer.hits");
  const CpuImage& vw = wag->output("shadows.visibility");
  const CpuImage& ve = exact->output("shadows.visibility");
  Mismatch r;
  for (int l = 0; l < int(wag->scene.lights.size()); ++l)
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (hits.u(x, y, 0) == 0u) continue;
        const float a = vw.f(x, y, 0, l), e = ve.f(x, y, 0, l);
        EXPECT_TRUE(a == 0.f || a == 1.f) << x << "," << y;
        ++r.covered;
        r.exactShadow += e < 0.5f;
        r.wagShadow += a < 0.5f;
        const bool differ = (e < 0.5f) != (a < 0.5f);
        r.mismatched += differ;
      }
  return r;
}

// A WorldMesh of the given triangles (positions only: LitPolygons reads nothing else).
WorldMesh mesh(std::vector<vec3> positions, int instance) {
  WorldMesh m;
  m.instance = instance;
  m.positions = std::move(positions);
  for (std::uint32_t i = 0; i < m.positions.size(); ++i) m.indices.push_back(i);
  return m;
}

// The lit area of a triangle as a fraction of it: the pieces' areas in barycentrics (the
// barycentric triangle has area 1/2).
double litFraction(const LitPolygons& lit, int m, std::uint32_t t) {
  if (lit.coverage(m, t) != LitPolygons::Coverage::Partial)
    return lit.coverage(m, t) == LitPolygons::Coverage::Lit ? 1.0 : 0.0;
  double area = 0.0;
  for (const auto& p : lit.pieces(m, t)) {
    double s = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i)
      s += p[i].x * p[(i + 1) % p.size()].y - p[(i + 1) % p.size()].x * p[i].y;
    area += std::abs(0.5 * s);
  }
  return area / 0.5;
}

Light light(LightType type, vec3 position, vec3 direction) {
  Light l;
  l.type = type;
  l.position = position;
  l.direction = direction;
  return l;
}

// A floor triangle (legs 8 along x and z, area 32) under a square occluder of side 1 at height
// h: straight down from a directional light the shadow is the square (1/32 of the floor); from a
// point light at height H above the square's centre it is the square scaled by H / (H - h)
// (similar triangles), (H / (H - h))^2 / 32 of the floor. The occluder itself is lit; a light
// that casts no shadows, or an occluder that casts none, leaves the floor lit; a point inside
// the shadow reads 0 and one beside it 1.
TEST(WagShadows, ShadowOfASquareIsItsProjection) {
  WorldGeometry world;
  world.meshes.push_back(mesh({vec3(-4, 0, -4), vec3(-4, 0, 4), vec3(4, 0, -4)}, 0));
  world.meshes.push_back(mesh({vec3(-1.5f, 1, -1.5f), vec3(-1.5f, 1, -0.5f), vec3(-0.5f, 1, -1.5f),
                               vec3(-0.5f, 1, -1.5f), vec3(-1.5f, 1, -0.5f), vec3(-0.5f, 1, -0.5f)},
                              1));
  const std::vector<bool> casts = {true, true};
  const LitPolygons sun(world, casts, light(LightType::Directional, vec3(0), vec3(0, -1, 0)));
  EXPECT_NEAR(litFraction(sun, 0, 0), 1.0 - 1.0 / 32.0, 1e-9);
  EXPECT_EQ(sun.coverage(1, 0), LitPolygons::Coverage::Lit);
  EXPECT_EQ(sun.coverage(1, 1), LitPolygons::Coverage::Lit);
  // Barycentrics of floor point (x, z): u along +z (vertex 1), v along +x (vertex 2), from (-4,
  // -4).
  const auto at = [](float x, float z) { return vec2((z + 4.f) / 8.f, (x + 4.f) / 8.f); };
  EXPECT_EQ(sun.visibility(0, 0, at(-1.f, -1.f).x, at(-1.f, -1.f).y), 0.f);
  EXPECT_EQ(sun.visibility(0, 0, at(-1.f, 0.f).x, at(-1.f, 0.f).y), 1.f);
  EXPECT_EQ(sun.visibility(0, 0, at(-0.4f, -1.f).x, at(-0.4f, -1.f).y), 1.f);
  const float H = 3.f, h = 1.f;
  const LitPolygons point(world, casts, light(LightType::Point, vec3(-1, H, -1), vec3(0, -1, 0)));
  const double scale = H / (H - h);
  EXPECT_NEAR(litFraction(point, 0, 0), 1.0 - scale * scale / 32.0, 1e-9);
  EXPECT_EQ(point.visibility(0, 0, at(-1.7f, -1.f).x, at(-1.7f, -1.f).y), 0.f);  // 0.75 from centre
  EXPECT_EQ(point.visibility(0, 0, at(-1.8f, -1.f).x, at(-1.8f, -1.f).y), 1.f);
  Light off = light(LightType::Point, vec3(-1, H, -1), vec3(0, -1, 0));
  off.castsShadows = false;
  EXPECT_EQ(LitPolygons(world, casts, off).coverage(0, 0), LitPolygons::Coverage::Lit);
  EXPECT_EQ(LitPolygons(world, {true, false}, off).coverage(0, 0), LitPolygons::Coverage::Lit);
  EXPECT_EQ(
      LitPolygons(world, {true, false}, light(LightType::Directional, vec3(0), vec3(0, -1, 0)))
          .coverage(0, 0),
      LitPolygons::Coverage::Lit);
}

// The thresholds are local (review of session 25): a 5 mm square 5 cm above a floor triangle
// with 2e4-unit legs, lit from straight above, still shadows its own area, where thresholds
// relative to the floor's area or the scene's extent dropped it (the floor stayed lit).
TEST(WagShadows, ASmallOccluderOnAHugeFloorStillCastsItsShadow) {
  WorldGeometry world;
  world.meshes.push_back(
      mesh({vec3(-1e4f, 0, -1e4f), vec3(-1e4f, 0, 1e4f), vec3(1e4f, 0, -1e4f)}, 0));
  // The square spans x, z in [-1, -1 + a], inside the floor triangle (x + z <= 0).
  const float a = 0.005f, y = 0.05f, o = -1.f;
  world.meshes.push_back(mesh({vec3(o, y, o), vec3(o, y, o + a), vec3(o + a, y, o),
                               vec3(o + a, y, o), vec3(o, y, o + a), vec3(o + a, y, o + a)},
                              1));
  const LitPolygons sun(world, {true, true},
                        light(LightType::Directional, vec3(0), vec3(0, -1, 0)));
  ASSERT_EQ(sun.coverage(0, 0), LitPolygons::Coverage::Partial);
  // Floor barycentrics of (x, z): u = (z + 1e4) / 2e4 (vertex 1), v = (x + 1e4) / 2e4 (vertex 2).
  const auto at = [](double x, double z) {
    return vec2(float((z + 1e4) / 2e4), float((x + 1e4) / 2e4));
  };
  // The square's centre is shadowed; a point 1 cm beside it is lit. (Float barycentrics of a
  // 2e4 floor resolve ~1 mm.)
  const double c = o + 0.5 * a;
  EXPECT_EQ(sun.visibility(0, 0, at(c, c).x, at(c, c).y), 0.f);
  EXPECT_EQ(sun.visibility(0, 0, at(c + 0.01, c).x, at(c + 0.01, c).y), 1.f);
}

// Two triangles that pass through each other (an X seen from the side), lit from straight
// above: each is in front of the other on one side of their crossing line, so each shadows the
// other there and only there. A receiver's lit part is where its plane lies above the other's,
// not where a whole-polygon depth order would put it.
TEST(WagShadows, InterpenetratingPolygonsShadowEachOtherPastTheirCrossing) {
  WorldGeometry world;
  // A rises along +x (y = x / 4), B falls (y = -x / 4): they cross on x = 0.
  world.meshes.push_back(mesh({vec3(-2, -0.5f, -2), vec3(-2, -0.5f, 2), vec3(2, 0.5f, 0)}, 0));
  world.meshes.push_back(mesh({vec3(2, -0.5f, -2), vec3(-2, 0.5f, 0), vec3(2, -0.5f, 2)}, 1));
  const LitPolygons sun(world, {true, true},
                        light(LightType::Directional, vec3(0), vec3(0, -1, 0)));
  // A point on A at x (u, v): A = v0 + u (v1 - v0) + v (v2 - v0).
  const auto onA = [](float x, float z) {
    const float v = (x + 2.f) / 4.f;            // x = -2 + 4 v
    const float u = (z + 2.f - 2.f * v) / 4.f;  // z = -2 + 4 u + 2 v
    return vec2(u, v);
  };
  for (const float z : {-0.2f, 0.f, 0.2f}) {
    const vec2 behind = onA(-0.5f, z), front = onA(0.5f, z);
    EXPECT_EQ(sun.visibility(0, 0, behind.x, behind.y), 0.f) << z;  // below B where x < 0
    EXPECT_EQ(sun.visibility(0, 0, front.x, front.y), 1.f) << z;    // above B where x > 0
  }
  EXPECT_EQ(sun.coverage(0, 0), LitPolygons::Coverage::Partial);
  EXPECT_EQ(sun.coverage(1, 0), LitPolygons::Coverage::Partial);
}

TEST(WagShadows, MatchesRtShadowsOnTheSamples) {
  for (const char* name : {"whitted.json", "shadow-sphere.json"}) {
    const Mismatch m = compareWithRtShadows(
        std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / name, 160, 120);
    std::printf("%s: %d covered pixels, %d in exact shadow, %d in wag shadow, %d differ\n", name,
                m.covered, m.exactShadow, m.wagShadow, m.mismatched);
    EXPECT_GT(m.exactShadow, 100) << name;
    EXPECT_LE(m.mismatched, m.covered / 200) << name;
  }
}
}  // namespace DIPTYCH_UNITY_ID
