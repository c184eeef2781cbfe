// traceShadowRays generates its rays straight into per-thread stream tiles (engine/rt/
// shadow_rays.cpp); it must give exactly what the single-ray lightVisibility gives for the same
// receivers and seeds, whatever the tiling (one ray per receiver, or many area samples that
// straddle tile boundaries); traceShadowTile, rt_shadows' per-row streams, must give exactly
// what traceShadowRays gives. Under them all, OcclusionStream answers each ray as a single
// rtcOccluded1 would.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/rt/occlusion_stream.h"
#include "engine/rt/shadow_rays.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

struct ShadowCase {
  Scene scene;
  std::vector<Light> lights;
  std::vector<ShadowReceiver> receivers;
  std::vector<std::uint32_t> seeds;
};

ShadowCase shadowCase() {
  ShadowCase k;
  k.scene = testgeo::sceneOf(
      {testgeo::uvSphere(vec3(0.f, 2.f, 0.f), 1.f, 48, 24), testgeo::groundPlane(10.f)});
  Light point;
  point.position = vec3(0.3f, 6.f, 0.2f);
  Light quad;
  quad.type = LightType::QuadArea;
  quad.position = vec3(0.f, 6.f, 0.f);
  quad.direction = vec3(0.f, -1.f, 0.f);
  quad.edgeU = vec3(2.f, 0.f, 0.f);
  quad.edgeV = vec3(0.f, 0.f, 2.f);
  Light off = point;
  off.castsShadows = false;
  k.lights = {point, quad, off};
  for (int i = 0; i < 997; ++i) {
    const float x = -3.f + 6.f * float(i % 37) / 36.f, z = -3.f + 6.f * float(i / 37) / 26.f;
    k.receivers.push_back({vec3(x, 0.f, z), vec3(0.f, i % 11 == 0 ? -1.f : 1.f, 0.f), vec3(10.f)});
    k.seeds.push_back(std::uint32_t(i * 7919 + 3));
  }
  return k;
}

// traceShadowTile (rt_shadows' row streams: receiver-major, every light in one stream) gives
// traceShadowRays' values bit for bit, for tiles of any length (a row's covered pixels).
TEST(ShadowStreams, TileEqualsBatchForAnyRunOfReceivers) {
  const ShadowCase k = shadowCase();
  const WorldGeometry world = flattenScene(k.scene);
  RtDevice device;
  const RtScene rt(device, world);
  const std::size_t n = k.receivers.size(), lights = k.lights.size();
  for (const int samples : {1, 16, 100}) {
    const std::vector<float> batch = traceShadowRays(rt, k.lights, k.receivers, samples, k.seeds);
    int shadowed = 0;
    // Runs of 1, 13 and 640 receivers (a row), the last shorter: every tile boundary moves.
    for (const std::size_t run : {std::size_t(1), std::size_t(13), std::size_t(640)}) {
      for (std::size_t begin = 0; begin < n; begin += run) {
        const std::size_t count = std::min(run, n - begin);
        std::vector<float> tile(count * lights, -1.f);
        traceShadowTile(rt, k.lights, {k.receivers.data() + begin, count}, samples,
                        {k.seeds.data() + begin, count}, tile);
        for (std::size_t p = 0; p < count; ++p) {
          for (std::size_t l = 0; l < lights; ++l) {
            ASSERT_EQ(tile[p * lights + l], batch[l * n + begin + p])
                << "light " << l << " receiver " << begin + p << " samples " << samples << " run "
                << run;
            shadowed += tile[p * lights + l] < 1.f ? 1 : 0;
          }
        }
      }
    }
    EXPECT_GT(shadowed, 150);  // occluded rays are compared, not only lit ones
  }
  std::vector<float> small(3);
  EXPECT_THROW(traceShadowTile(rt, k.lights, k.receivers, 1, k.seeds, small), Error);
}

TEST(ShadowStreams, BatchEqualsSingleRayVisibilityForPointAreaAndNonCastingLights) {
  // Receivers on the ground, some in the umbra, some in the penumbra, some lit; a few facing
  // down (their rays leave from the other side), seeds unlike their indices.
  const ShadowCase k = shadowCase();
  const WorldGeometry world = flattenScene(k.scene);
  RtDevice device;
  const RtScene rt(device, world);
  const std::vector<Light>& lights = k.lights;
  const std::vector<ShadowReceiver>& receivers = k.receivers;
  const std::vector<std::uint32_t>& seeds = k.seeds;
  for (const int samples : {1, 16, 100}) {  // 100: a receiver's rays straddle 256-ray tiles
    const std::vector<float> batch = traceShadowRays(rt, lights, receivers, samples, seeds);
    ASSERT_EQ(batch.size(), lights.size() * receivers.size());
    int shadowed = 0, partial = 0;
    for (std::size_t l = 0; l < lights.size(); ++l) {
      for (std::size_t p = 0; p < receivers.size(); ++p) {
        const float single = lightVisibility(rt, lights[l], receivers[p], samples, seeds[p]);
        ASSERT_EQ(batch[l * receivers.size() + p], single)
            << "light " << l << " receiver " << p << " samples " << samples;
        shadowed += single < 1.f ? 1 : 0;
        partial += single > 0.f && single < 1.f ? 1 : 0;
      }
    }
    EXPECT_GT(shadowed, 50);  // the comparison covers occluded rays, not only lit ones
    if (samples > 1) {
      EXPECT_GT(partial, 20);
    }
  }
}

// OcclusionStream, the loop under every stream above: each ray answered once, with its own
// owner, in the order added, as the single-ray query answers it; an inactive ray visible; full
// streams traced as they fill (more rays than one stream holds), the rest at flush().
TEST(ShadowStreams, OcclusionStreamAnswersEachRayAsASingleRayQuery) {
  const ShadowCase k = shadowCase();
  const WorldGeometry world = flattenScene(k.scene);
  RtDevice device;
  const RtScene rt(device, world);
  std::vector<OcclusionRay> rays;
  for (const ShadowReceiver& r : k.receivers)
    for (const Light& light : k.lights) rays.push_back(makeShadowRay(light, r));
  ASSERT_GT(rays.size(), 2 * kOcclusionStreamRays);
  std::vector<std::pair<std::size_t, bool>> answers;
  const auto record = [&](std::size_t owner, bool visible) {
    answers.emplace_back(owner, visible);
  };
  OcclusionStream<std::size_t, decltype(record)> stream(rt, true, record);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    stream.add(rays[i], i);
    // A full stream is traced when its last ray arrives, not before.
    ASSERT_EQ(answers.size(), (i + 1) / kOcclusionStreamRays * kOcclusionStreamRays);
  }
  stream.flush();
  ASSERT_EQ(answers.size(), rays.size());
  int occluded = 0, inactive = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const OcclusionRay& r = rays[i];
    const bool active = r.tnear <= r.tfar;
    const bool visible = !active || !rt.occluded(r.origin, r.direction, r.tnear, r.tfar);
    ASSERT_EQ(answers[i].first, i);
    ASSERT_EQ(answers[i].second, visible) << "ray " << i;
    occluded += visible ? 0 : 1;
    inactive += active ? 0 : 1;
  }
  EXPECT_GT(occluded, 50);                       // both answers are exercised
  EXPECT_EQ(inactive, int(k.receivers.size()));  // the light that casts no shadows
  stream.flush();                                // nothing pending: no answer twice
  EXPECT_EQ(answers.size(), rays.size());
}
}  // namespace DIPTYCH_UNITY_ID
