// Instancing of repeated meshes in RtScene (engine/rt/rt_scene_instancing.h): each distinct mesh
// is built once and the copies are Embree instances; hits name the same instance, primitive and
// point as the flattened scene, up to the rounding of the instance transform.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/rt/rt_scene.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

// Five copies of one sphere (three plain, one a separate but identical Mesh, two mirrored) and a
// plane that occurs once.
Scene repeatedSpheres() {
  const Mesh sphere = testgeo::uvSphere(vec3(0.f), 1.f, 32, 16);
  Scene s = testgeo::sceneOf({sphere, sphere, testgeo::groundPlane(20.f)});
  auto place = [&](int mesh, const mat4& m) { s.instances.push_back(Instance{"copy", mesh, m}); };
  s.instances[0].transform = glm::translate(mat4(1.f), vec3(-3.f, 1.f, 0.f));
  s.instances[1].transform =
      glm::scale(glm::translate(mat4(1.f), vec3(0.f, 0.5f, -3.f)), vec3(0.5f));
  place(0, glm::rotate(glm::translate(mat4(1.f), vec3(3.f, 1.f, 0.f)), 0.7f, vec3(0, 1, 1)));
  place(0, glm::scale(glm::translate(mat4(1.f), vec3(-1.5f, 1.f, 3.f)), vec3(-1.f, 1.f, 1.f)));
  place(1, glm::scale(glm::translate(mat4(1.f), vec3(1.5f, 1.f, 3.f)), vec3(1.f, 1.f, -1.2f)));
  return s;
}

TEST(RtInstancing, RepeatedMeshesAreBuiltOnceAndHitTheSameInstancePrimitiveAndPoint) {
  const Scene scene = repeatedSpheres();
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  RtSceneOptions flatOptions;
  flatOptions.instancing = false;
  const RtScene flat(device, world, scene, flatOptions);
  const RtScene inst(device, world, scene);
  EXPECT_EQ(flat.prototypes(), 0);
  EXPECT_EQ(inst.prototypes(), 2);  // the plain copies, and the mirrored ones (flipped winding)
  EXPECT_EQ(inst.instancedGeometries(), 5);

  const vec3 eye(0.f, 7.f, 14.f);
  int both = 0, sameTriangle = 0, disagree = 0;
  std::vector<int> hitsPerInstance(world.meshes.size(), 0);
  for (int y = 0; y < 90; ++y) {
    for (int x = 0; x < 120; ++x) {
      const vec3 target(-6.f + 12.f * (float(x) + 0.5f) / 120.f,
                        2.5f - 4.f * (float(y) + 0.5f) / 90.f, 0.f);
      const Ray ray{eye, glm::normalize(target - eye)};
      const auto a = flat.intersect(ray, 0.f, 1e30f);
      const auto b = inst.intersect(ray, 0.f, 1e30f);
      if (a.has_value() != b.has_value()) {
        ++disagree;  // a ray grazing a silhouette may go either way by a rounding
        continue;
      }
      if (!a) continue;
      ++both;
      ++hitsPerInstance[std::size_t(b->instance)];
      EXPECT_NEAR(b->t, a->t, 1e-5f * a->t);
      if (a->instance != b->instance || a->primitive != b->primitive) continue;  // shared edge
      ++sameTriangle;
      const WorldMesh& mesh = world.meshes[std::size_t(b->instance)];
      // The point rebuilt from the world-space vertices is where the ray met the surface.
      const vec3 p = interpolatePosition(mesh, b->primitive, b->u, b->v);
      EXPECT_LT(glm::length(p - (ray.origin + b->t * ray.direction)), 1e-4f);
      // Ng comes back to world space pointing like the CCW face normal of the world triangle.
      EXPECT_GT(glm::dot(glm::normalize(b->Ng), geometricNormal(mesh, b->primitive)), 1.f - 1e-5f);
    }
  }
  EXPECT_GT(both, 5000);
  EXPECT_LE(disagree, 10);
  EXPECT_GE(sameTriangle, both - both / 100);
  for (std::size_t i = 0; i < hitsPerInstance.size(); ++i)
    EXPECT_GT(hitsPerInstance[i], 50) << "instance " << i << " is never hit";
}

TEST(RtInstancing, AlphaMaskedAndSingleMeshesAreNotInstanced) {
  Scene scene = repeatedSpheres();
  Material masked;
  masked.alphaMode = AlphaMode::Mask;
  scene.materials.push_back(masked);
  scene.meshes[1].material = 0;  // the identical copy, now alpha masked
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  const RtScene rt(device, world, scene);
  // Instances 1 and 5 (mesh 1, masked) stay flat: their filter needs their own material. The
  // plain copies 0 and 3 make one group; the mirrored 4, now alone, stays flat too.
  EXPECT_EQ(rt.prototypes(), 1);
  EXPECT_EQ(rt.instancedGeometries(), 2);
  const RtScene without(device, world);  // no Scene: nothing to group by
  EXPECT_EQ(without.prototypes(), 0);
}
}  // namespace DIPTYCH_UNITY_ID
