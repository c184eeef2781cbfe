// MetalRoughSpheresNoTextures places one 10k-triangle sphere 102 times (its meshes share position
// and index accessors): RtScene builds it once and instances it, and the instanced scene sees
// what the flattened one sees from the scene's camera (issue 14).
#include <gtest/gtest.h>

#include "engine/rt/rt_scene.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

TEST(MetalRoughInstancing, OnePrototypeForEveryRepeatedSphereAndTheSameHitsAsFlattened) {
  const Scene scene = loadScene(DIPTYCH_SHARED_SCENES +
                                "/metal-rough-spheres-no-textures/MetalRoughSpheresNoTextures.glb");
  const WorldGeometry world = flattenScene(scene);
  ASSERT_GT(world.triangleCount(), 1000000u);
  RtDevice device;
  RtSceneOptions flatOptions;
  flatOptions.instancing = false;
  const RtScene flat(device, world, scene, flatOptions);
  const RtScene inst(device, world, scene);
  EXPECT_EQ(inst.prototypes(), 1);
  EXPECT_GE(inst.instancedGeometries(), 90);  // 98: every sphere placement of the file

  constexpr int kW = 160, kH = 120;
  const PinholeFrame camera(scene.camera, kW, kH);
  int hits = 0, same = 0, disagree = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const Ray ray = camera.ray(float(x) + 0.5f, float(y) + 0.5f);
      const auto a = flat.intersect(ray, 0.f, 1e30f);
      const auto b = inst.intersect(ray, 0.f, 1e30f);
      if (a.has_value() != b.has_value()) {
        ++disagree;
        continue;
      }
      if (!a) continue;
      ++hits;
      EXPECT_NEAR(b->t, a->t, 1e-5f * a->t);
      same += a->instance == b->instance && a->primitive == b->primitive ? 1 : 0;
    }
  }
  EXPECT_GT(hits, 2000);               // the spheres cover about 15% of the frame
  EXPECT_LE(disagree, 3);              // silhouette rays a rounding may tip either way
  EXPECT_GE(same, hits - hits / 200);  // the rest: rays through a shared edge
}

}  // namespace DIPTYCH_UNITY_ID
