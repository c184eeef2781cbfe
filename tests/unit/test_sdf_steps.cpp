// The per-pixel sphere-tracing signal sdf_steps (passes/rt/sdf_steps.h) of the traced producers:
// non-zero where the pixel's ray hits the SDF object, zero where it misses the object's box, and
// its sums and maximum equal the RtScene's aggregate step statistics for the frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/rt/rt_scene.h"
#include "passes/rt/sdf_steps.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// An SDF sphere in front of an opaque wall; no lights and no mirrors, so each pixel traces its
// primary ray only and the steps of a pixel are those of that one ray.
const char* kScene = R"({
  "camera": {"position": [0, 0, 6], "target": [0, 0, 0], "fov": 40},
  "ambient": [0.2, 0.2, 0.2],
  "materials": {"grey": {"color": [0.7, 0.7, 0.7], "kd": 0.9, "ka": 0.3}},
  "objects": [
    {"type": "plane", "name": "wall", "size": [20, 20], "material": "grey",
     "transform": {"translate": [0, 0, -2], "rotate": [90, 0, 0]}},
    {"type": "sdf", "name": "ball", "material": "grey", "resolution": 24,
     "shape": {"type": "sphere", "radius": 0.8}, "transform": {"translate": [-0.6, 0.2, 0]}}
  ]
})";

Recipe whittedRecipe() {
  Recipe r;
  r.passes = {{.name = "reference", .type = "rt_whitted", .place = "test"}};
  r.outputs = {"reference.color"};
  return r;
}

TEST(SdfSteps, HeatMapMarksTheSdfObjectAndAgreesWithTheAggregateStatistics) {
  const auto dir = testing::scratchDir("diptych_sdf_steps");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "ball.json") << kScene;
  constexpr int kW = 64, kH = 48;
  const auto f = testing::renderHybridFrame(
      dir / "ball.json", kW, kH, {"reference.color", "reference.sdf_steps"}, whittedRecipe());
  const Image steps = f->output("reference.sdf_steps").toImage();
  ASSERT_EQ(steps.channels, 4);
  // The frame's figures from the image equal the scene's counters (this frame is all it traced).
  const RtScene& rt = f->world->rtScene();
  const RtScene::SdfStepStats stats = rt.sdfStepStats();
  const SdfStepSummary s = summariseSdfSteps(steps);
  ASSERT_GT(stats.rays, 0u);
  EXPECT_EQ(s.rays, double(stats.rays));
  EXPECT_EQ(s.steps, double(stats.steps));
  EXPECT_EQ(s.capped, double(stats.capped));
  EXPECT_EQ(s.maxSteps, double(stats.maxSteps));
  EXPECT_DOUBLE_EQ(s.meanSteps(), stats.meanSteps());

  // Per pixel: classified after the frame (these queries count too, so the figures come first).
  int ball = 0, outside = 0;
  int sdf = -1;
  for (std::size_t i = 0; i < f->world->geometry().meshes.size(); ++i)
    if (f->world->geometry().meshes[i].analytic && f->world->geometry().meshes[i].analytic->sdf)
      sdf = int(i);
  ASSERT_GE(sdf, 0);
  const Aabb box = f->world->geometry().meshes[std::size_t(sdf)].analytic->bounds;
  const PinholeFrame pinhole(f->graph.frame.camera, kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const Ray ray = pinhole.ray(x + 0.5f, y + 0.5f);
      const auto hit = rt.intersect(ray, 0.f, 1e30f);
      // The slab test against the object's world box (padded by a little for rounding).
      float t0 = 0.f, t1 = 1e30f;
      for (int a = 0; a < 3; ++a) {
        const float inv = 1.f / ray.direction[a];
        float ta = (box.lo[a] - 1e-3f - ray.origin[a]) * inv,
              tb = (box.hi[a] + 1e-3f - ray.origin[a]) * inv;
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
      }
      if (hit && hit->instance == sdf) {
        EXPECT_GT(steps.at(x, y, 0), 0.f) << x << "," << y;
        EXPECT_EQ(steps.at(x, y, 1), 1.f) << x << "," << y;
        ++ball;
      } else if (t0 > t1) {
        EXPECT_EQ(steps.at(x, y, 0), 0.f) << x << "," << y;
        ++outside;
      }
    }
  EXPECT_GT(ball, 100);
  EXPECT_GT(outside, 1000);
}

// Issue 10: "the exact producers (rt_shadows, rt_reflection, rt_transmission, rt_whitted,
// rt_distributed, rt_path) trace the analytic surface". A glass SDF ball before a mirror wall,
// lit from beside the camera: each producer's frame sends rays into the sphere tracer (shadow
// rays from the wall behind the ball, reflections off the wall back through it, refraction
// through the ball itself), and the traced ones write sdf_steps.
TEST(SdfSteps, EveryExactProducerSphereTracesTheSdfObject) {
  std::string scene = kScene;
  const auto replace = [&](const std::string& from, const std::string& to) {
    scene.replace(scene.find(from), from.size(), to);
  };
  replace(R"("materials": {)",
          R"("lights": [{"type": "point", "position": [0.5, 0.5, 6], "intensity": 30}],
             "materials": {"glass": {"color": [0, 0, 0], "kd": 0, "kt": 1, "ior": 1.5},
                           "mirror": {"color": [0.2, 0.2, 0.2], "kd": 0.5, "kps": 0.5},)");
  replace(R"("size": [20, 20], "material": "grey")", R"("size": [20, 20], "material": "mirror")");
  replace(R"("name": "ball", "material": "grey")", R"("name": "ball", "material": "glass")");
  const auto dir = testing::scratchDir("diptych_sdf_steps");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "lit.json") << scene;
  for (const char* type : {"rt_whitted", "rt_distributed", "rt_path"}) {
    Recipe r;
    r.passes = {{.name = "traced", .type = type, .params = {{"spp", 1}}, .place = "test"}};
    r.outputs = {"traced.color"};
    const auto f = testing::renderHybridFrame(dir / "lit.json", 32, 24, {}, r);
    EXPECT_GT(f->world->rtScene().sdfStepStats().rays, 0u) << type;
  }
  // The hybrid's exact slot producers, one frame each: asking for one output culls the other
  // slots (the G-buffer draws the polygonisation and sends no rays).
  for (const char* output :
       {"shadows.visibility", "reflection.sdf_steps", "transmission.sdf_steps"}) {
    const auto f = testing::renderHybridFrame(dir / "lit.json", 32, 24, {output});
    EXPECT_GT(f->world->rtScene().sdfStepStats().rays, 0u) << output;
    if (std::string(output).ends_with("sdf_steps")) {
      EXPECT_EQ(summariseSdfSteps(f->output(output).toImage()).rays,
                double(f->world->rtScene().sdfStepStats().rays))
          << output;
    }
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
