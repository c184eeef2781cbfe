// Alpha masks (glTF alphaMode MASK) on analytic shapes: an exact sphere whose colour texture's
// alpha is 8 stripes in u, opaque and clear in turn. A ray through a clear stripe on the near
// side goes on to the far side, and through clear stripes on both it misses; closest hit and
// occlusion agree. Expected answers come from the same sphere unmasked, hit from both sides.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/rt/rt_scene.h"
#include "engine/scene/analytic_hit.h"
#include "engine/scene/primitives.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kStripes = 8;

bool opaqueAt(float u) {
  return int(std::floor(u * kStripes)) % 2 == 0;
}
// Within this much (in u) of a stripe edge a float's rounding may pick either stripe.
bool nearEdge(float u) {
  const float s = u * kStripes;
  return std::fabs(s - std::round(s)) < 1e-3f * kStripes;
}

// The texture u of a hit on the sphere (its record holds the octahedral normal: analytic_hit.h).
float textureU(const WorldGeometry& world, const Hit& h) {
  return analyticHitUv(*world.meshes[0].analytic, int(h.primitive), vec2(h.u, h.v)).x;
}

Scene stripedSphere(AlphaMode mode) {
  Scene s;
  Mesh mesh = makeUvSphere(1.f, 32, 16);
  mesh.analytic = AnalyticShape{ShapeType::Sphere, 1.f};
  mesh.material = 0;
  s.meshes.push_back(mesh);
  // Scaled and moved, so the mask is tested through the instance transform.
  s.instances.push_back(
      {"ball", 0, glm::scale(glm::translate(mat4(1.f), vec3(0.5f, -1.f, 2.f)), vec3(1.5f))});
  Texture t;
  t.image = Image(kStripes, 1, 4, 1.f);
  for (int x = 0; x < kStripes; ++x) t.image.at(x, 0, 3) = x % 2 == 0 ? 1.f : 0.f;
  t.wrapS = t.wrapT = WrapMode::ClampToEdge;
  t.minFilter = t.magFilter = FilterMode::Nearest;
  s.textures.push_back(t);
  Material m;
  m.alphaMode = mode;
  m.alphaCutoff = 0.5f;
  m.colorTexture = 0;
  s.materials.push_back(m);
  return s;
}

TEST(AnalyticAlphaMask, ClearStripesLetRaysThroughToTheFarSideOrPast) {
  const Scene masked = stripedSphere(AlphaMode::Mask), opaque = stripedSphere(AlphaMode::Opaque);
  const WorldGeometry wm = flattenScene(masked), wo = flattenScene(opaque);
  RtDevice device;
  const RtScene rm(device, wm, masked), ro(device, wo, opaque);
  ASSERT_EQ(rm.analyticGeometries(), 1);
  EXPECT_EQ(rm.alphaMaskedGeometries(), 1);
  EXPECT_EQ(ro.alphaMaskedGeometries(), 0);

  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(-1.f, 1.f);
  const vec3 centre(0.5f, -1.f, 2.f);
  int front = 0, back = 0, through = 0;
  for (int i = 0; i < 2000; ++i) {
    const vec3 o = centre + 6.f * glm::normalize(vec3(unit(rng), unit(rng), unit(rng)));
    const vec3 target = centre + 1.2f * vec3(unit(rng), unit(rng), unit(rng));
    const vec3 d = glm::normalize(target - o);
    const auto near = ro.intersect({o, d}, 0.f, 1e30f);
    if (!near) continue;
    const vec3 far0 = o + 20.f * d;
    const auto far = ro.intersect({far0, -d}, 0.f, 1e30f);  // the far side, seen from beyond
    ASSERT_TRUE(far);
    const float nearU = textureU(wo, *near), farU = textureU(wo, *far);
    if (nearEdge(nearU) || nearEdge(farU)) continue;
    const auto hit = rm.intersect({o, d}, 0.f, 1e30f);
    const bool occluded = rm.occluded(o, d, 0.f, 1e30f);
    if (opaqueAt(nearU)) {
      ASSERT_TRUE(hit);
      EXPECT_EQ(hit->t, near->t);
      ++front;
    } else if (opaqueAt(farU)) {
      ASSERT_TRUE(hit);
      EXPECT_NEAR(hit->t, 20.f - far->t, 1e-4f);
      EXPECT_NEAR(hit->u, far->u, 1e-4f);  // the same record, within the two rays' rounding
      EXPECT_NEAR(hit->v, far->v, 1e-4f);
      ++back;
    } else {
      EXPECT_FALSE(hit);
      ++through;
    }
    EXPECT_EQ(occluded, hit.has_value());
  }
  // Every case occurs often enough to mean something.
  EXPECT_GT(front, 100);
  EXPECT_GT(back, 50);
  EXPECT_GT(through, 50);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
