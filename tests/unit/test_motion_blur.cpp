// Motion blur, distributed ray tracing's time dimension (Cook, Porter and Carpenter 1984): an
// object's "motion" in the scene file, Embree's motion-blurred instances at each ray's time, the
// surface points and shadow rays of a hit at that time, and the references that sample it
// (rt_distributed's stratified times, rt_path's per-path time). Analytic answers: an edge that
// sweeps D pixels over the shutter becomes a linear ramp D pixels wide.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/rt_device.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "engine/scene/scene_transform.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

std::filesystem::path writeScene(const std::string& name, const std::string& json) {
  const auto dir = ::diptych::testing::scratchDir("diptych_motion_blur");
  std::ofstream(dir / name) << json;
  return dir / name;
}

// One CPU-only frame of a single pass; its `color` output.
CpuImage renderPass(const Scene& scene, const std::string& type, nlohmann::json params, int w,
                    int h) {
  Recipe recipe;
  recipe.file = "test";
  recipe.passes = {{.name = "p", .type = type, .params = std::move(params), .place = "passes[0]"}};
  recipe.outputs = {"p.color"};
  const CompiledGraph g = compileGraph(recipe, builtinPasses(), scene, {w, h, scene.camera});
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  return ex.output("p.color");
}

// An emissive half-plane (x < 0, z = 0) seen head-on from z = 5 on a 65 x 49 image (the edge
// x = 0 on the centre line of column 32, as in test_references.cpp), moving by `motion` world
// units along +x over the shutter.
constexpr int kW = 65, kH = 49;
std::string edgeScene(float motion) {
  return R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 45},
    "materials": {"glow": {"color": [0, 0, 0], "kd": 0, "emission": [1, 1, 1]}},
    "objects": [{"type": "quad", "material": "glow", "motion": [)" +
         std::to_string(motion) + R"(, 0, 0],
                 "corners": [[-40, -40, 0], [0, -40, 0], [0, 40, 0], [-40, 40, 0]]}]})";
}
// Pixels per world unit in the plane z = 0: kH / (2 * 5 * tan(22.5 deg)).
const double kPixelsPerUnit = kH / (2.0 * 5.0 * std::tan(glm::radians(22.5)));

// A lit sphere (radius 1, centre (0, 1, 0): "analytic", "tessellated" or "sdf") moving by
// (4, 0, 0) over the shutter, over a static floor y = 0, under a directional light straight down.
std::string ballScene(const std::string& kind = "analytic") {
  const std::string ball =
      kind == "sdf" ? R"("type": "sdf", "shape": {"type": "sphere", "radius": 1},)"
                    : R"("type": "sphere", "radius": 1, "segments": [128, 64], "geometry": ")" +
                          kind + R"(",)";
  return R"({"camera": {"position": [0, 6, 9], "target": [0, 0.5, 0], "fov": 40},
    "materials": {"floor": {"color": [0.8, 0.8, 0.8], "kd": 1},
                  "ball": {"color": [0.9, 0.3, 0.2], "kd": 0.7, "ks": 0.3, "exponent": 20}},
    "lights": [{"type": "directional", "direction": [0, -1, 0], "intensity": 1}],
    "objects": [{"type": "plane", "size": [40, 40], "material": "floor"},
                {)" +
         ball + R"( "material": "ball",
                 "transform": {"translate": [0, 1, 0]}, "motion": [4, 0, 0]}]})";
}

// The scene format: "motion" lands on every instance the object makes and is checked like a
// coordinate; a malformed one is an error naming its place.
TEST(MotionBlur, SceneFileMotionIsReadAndChecked) {
  const Scene scene = loadScene(writeScene("ball.json", ballScene()));
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.instances[0].motion, vec3(0.f));
  EXPECT_EQ(scene.instances[1].motion, vec3(4.f, 0.f, 0.f));
  EXPECT_TRUE(scene.hasMotion());
  EXPECT_FALSE(loadScene(writeScene("still.json", edgeScene(0.f))).hasMotion());
  const auto failure = [&](const std::string& motion) {
    std::string text = edgeScene(1.f);
    const std::string good = "[1.000000, 0, 0]";
    text.replace(text.find(good), good.size(), motion);
    try {
      loadScene(writeScene("bad.json", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
  };
  for (const std::string bad : {"[1, 2]", "[1, \"a\", 0]", "3"}) {
    const std::string message = failure(bad);
    EXPECT_NE(message.find("objects[0].motion"), std::string::npos) << bad << ": " << message;
  }
  const std::string far = failure("[1e30, 0, 0]");
  EXPECT_NE(far.find("motion"), std::string::npos) << far;
  EXPECT_NE(far.find("magnitude"), std::string::npos) << far;
  // Motion and placement each within the limit, but the sweep reaches past it:
  // 6e11 + 40 + 9e11 / 2 > 1e12.
  const std::string swept = failure(R"([9e11, 0, 0], "transform": {"translate": [6e11, 0, 0]})");
  EXPECT_NE(swept.find("swept by the motion"), std::string::npos) << swept;
  // A glTF include's instances all move; a similarity transform scales the motion.
  const Scene included = loadScene(writeScene(
      "include.json", R"({"objects": [{"type": "gltf", "file": ")" + DIPTYCH_SAMPLES_DIR +
                          R"(/scenes/blender-point-light.gltf", "motion": [0, 2, 0]}]})"));
  ASSERT_FALSE(included.instances.empty());
  for (const Instance& inst : included.instances) EXPECT_EQ(inst.motion, vec3(0.f, 2.f, 0.f));
  const Scene scaled = similarityTransformed(scene, 3.0, glm::dvec3(5.0, 0.0, 0.0));
  EXPECT_EQ(scaled.instances[1].motion, vec3(12.f, 0.f, 0.f));
}

// Embree's motion-blurred instance at each ray's time, for the analytic sphere (user geometry
// inside the instance) and its tessellation: a ray straight down through x hits the ball
// exactly when |x - (t - 1/2) 4| < 1, at the height of the sphere there; occlusion agrees; and
// the surface point of the hit, moved to the ray's time, lies on the moved sphere.
TEST(MotionBlur, RaysMeetAMovingInstanceWhereTheirTimePutsIt) {
  for (const std::string kind : {"analytic", "tessellated", "sdf"}) {
    const Scene scene = loadScene(writeScene("ball.json", ballScene(kind)));
    const WorldGeometry world = flattenScene(scene);
    const RtDevice device;
    const RtScene rt(device, world, scene);
    EXPECT_EQ(rt.movingGeometries(), 1);
    const float inf = std::numeric_limits<float>::infinity();
    for (const float time : {0.f, 0.25f, 0.5f, 0.8f, 1.f}) {
      const float centre = (time - kFrameTime) * 4.f;
      for (const float dx : {-1.3f, -0.6f, 0.f, 0.45f, 0.9f, 1.2f}) {
        const Ray ray{vec3(centre + dx, 10.f, 0.f), vec3(0.f, -1.f, 0.f), time};
        Hit hit;
        ASSERT_TRUE(rt.intersect(ray, 0.f, inf, hit, true));
        const bool onBall = std::fabs(dx) < 1.f;
        EXPECT_EQ(hit.instance, onBall ? 1 : 0) << kind << " t " << time << " dx " << dx;
        EXPECT_EQ(rt.occluded(ray.origin, ray.direction, 0.f, 9.5f, time), onBall);
        if (!onBall) continue;
        const float height = 1.f + std::sqrt(1.f - dx * dx);  // the top of the sphere at dx
        // The tessellation's sag; sphere tracing's tolerance (1e-5 of the box diagonal).
        const float tol = kind == "analytic" ? 1e-5f : kind == "sdf" ? 2e-4f : 2e-3f;
        EXPECT_NEAR(hit.t, 10.f - height, tol) << "t " << time << " dx " << dx;
        SurfacePoint p = makeSurfacePoint(
            scene, world, {hit.instance, hit.primitive, hit.u, hit.v, hit.analytic}, ray.direction);
        atShutterTime(p, world, time);
        EXPECT_EQ(p.time, time);
        EXPECT_NEAR(p.position.x, centre + dx, 1e-5f);
        EXPECT_NEAR(p.position.y, height, tol);
        const Ray spawned = spawnRay(p, vec3(0.f, 1.f, 0.f));
        EXPECT_EQ(spawned.time, time);
      }
    }
  }
}

// Time is kept along the ray tree: a hit at time t shades its point where the ball is at t, and
// its shadow rays meet the ball where it is at t. So a ray at time t equals the same ray moved
// by -(t - 1/2) motion at the frame's instant wherever the floor does not matter (on the ball),
// and the floor under the ball's position at t (not at 1/2) is the one in shadow.
TEST(MotionBlur, ShadingAndShadowRaysKeepTheHitsTime) {
  const Scene scene = loadScene(writeScene("ball.json", ballScene()));
  const WorldGeometry world = flattenScene(scene);
  const RtDevice device;
  const RtScene rt(device, world, scene);
  const WhittedTracer tracer(scene, world, rt, {5, 1});
  const vec3 direction = glm::normalize(vec3(-0.3f, -1.f, -0.4f));
  int onBall = 0;
  std::vector<Ray> rays;  // every ray below, for the tile path at the end
  for (const float time : {0.1f, 0.75f, 1.f}) {
    const vec3 shift((time - kFrameTime) * 4.f, 0.f, 0.f);
    for (const float dx : {-0.5f, 0.f, 0.3f, 0.6f}) {
      const vec3 origin = vec3(dx, 1.f, 0.f) - 5.f * direction;
      rays.push_back(Ray{origin + shift, direction, time});
      const vec3 moving = tracer.radiance(rays.back(), 1, 0u);
      const vec3 still = tracer.radiance(Ray{origin, direction, kFrameTime}, 1, 0u);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(moving[c], still[c], 1e-4f) << time << " " << dx;
      onBall += moving != vec3(0.f);
    }
    // A floor point under the ball where it is at `time`: in shadow at `time`, and lit
    // at the frame's instant unless the ball is there then too.
    // (0.7 off its axis: the ball touches the floor at the axis, which a ray would graze; the
    // ray climbs 1 in 3 toward +z and stays clear of the ball.)
    const vec3 under = vec3(shift.x, 0.f, 0.7f);
    const vec3 eye = under + 8.f * glm::normalize(vec3(0.f, 1.f, 3.f));
    const vec3 toFloor = glm::normalize(under - eye);
    rays.push_back(Ray{eye, toFloor, time});
    EXPECT_EQ(tracer.radiance(rays.back(), 1, 0u), vec3(0.f)) << time;
    const float lit = tracer.radiance(Ray{eye, toFloor, kFrameTime}, 1, 0u).x;
    if (std::fabs(shift.x) > 1.f) {
      EXPECT_NEAR(lit, 0.8f, 1e-4f) << time;  // k_d C max(0, n.l) S = 0.8
    }
  }
  EXPECT_EQ(onBall, 12);
  // The tiles rt_distributed shades (radianceTile: the hits' shadow rays as one stream) keep
  // the times too: equal to the ray-by-ray recursion up to Embree's packet rounding.
  const std::size_t n = rays.size();
  std::vector<Hit> hits(n);
  std::vector<const Hit*> found(n);
  rt.intersectRays(rays, hits, found, false);
  const std::vector<std::uint32_t> seeds(n, 0u);
  std::vector<vec3> tiled(n);
  tracer.radianceTile(rays, found, seeds, 1, {}, tiled);
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(tiled[i][c], tracer.radiance(rays[i], 1, 0u)[c], 1e-5f) << "ray " << i;
}

// The analytic test: the half-plane's edge sweeps D = 1 world unit (11.8 pixels) to the right
// over the shutter, so a pixel centred at x (world units from the edge's middle position) is
// covered while (t - 1/2) D > x: a fraction 1/2 - x / D of the shutter. rt_distributed with 256
// stratified times per pixel follows that ramp to within a stratum plus Embree's edge rounding;
// beyond the sweep the image is exactly 1 and 0; rt_whitted, at the frame's instant, keeps the
// sharp edge of the static scene; rt_path's per-path times follow the ramp within its noise.
TEST(MotionBlur, AnEdgeSweepingTheShutterBecomesALinearRamp) {
  const double D = 1.0;
  const Scene scene = loadScene(writeScene("edge.json", edgeScene(float(D))));
  const CpuImage blurred =
      renderPass(scene, "rt_distributed", {{"spp", 256}, {"depth", 1}}, kW, kH);
  const CpuImage sharp = renderPass(scene, "rt_whitted", {{"spp", 1}}, kW, kH);
  const CpuImage path = renderPass(scene, "rt_path", {{"spp", 64}, {"max_depth", 1}}, kW, kH);
  const double halfSweep = 0.5 * D * kPixelsPerUnit;  // pixels either side of the centre line
  double worstRow = 0, worstMean = 0, worstPath = 0;
  for (int x = 0; x < kW; ++x) {
    const double offset = (x + 0.5 - 32.5) / kPixelsPerUnit;  // world units from the middle
    const double expected = std::clamp(0.5 - offset / D, 0.0, 1.0);
    double mean = 0, pathMean = 0;
    for (int y = 0; y < kH; ++y) {
      mean += blurred.f(x, y, 0) / kH;
      pathMean += path.f(x, y, 0) / kH;
      EXPECT_EQ(sharp.f(x, y, 0), x < 32 ? 1.f : x > 32 ? 0.f : sharp.f(x, y, 0)) << x;
    }
    const int y = kH / 2;
    const double fromCentre = std::fabs(x + 0.5 - 32.5);
    if (fromCentre > halfSweep + 1.0) {
      EXPECT_EQ(blurred.f(x, y, 0), expected > 0.5 ? 1.f : 0.f) << "column " << x;
    } else if (fromCentre < halfSweep - 1.0) {
      worstRow = std::max(worstRow, std::fabs(blurred.f(x, y, 0) - expected));
      worstMean = std::max(worstMean, std::fabs(mean - expected));
      worstPath = std::max(worstPath, std::fabs(pathMean - expected));
    }
  }
  std::printf(
      "ramp over %.1f px: rt_distributed max |error| %.4f in a row, %.4f in the column means;"
      " rt_path %.4f in the column means\n",
      2 * halfSweep, worstRow, worstMean, worstPath);
  // A pixel's ~22 time strata inside its own transition each add at most 1/256 of noise
  // (sigma <= 0.009); the column means over 49 rows shrink that by 7; rt_path's 64 independent
  // times per pixel: sigma of a column mean <= 0.5 / sqrt(64 * 49) = 0.009.
  EXPECT_LT(worstRow, 0.04);
  EXPECT_LT(worstMean, 0.01);
  EXPECT_LT(worstPath, 0.04);
}

// Nothing moves: a zero motion is no motion (no time drawn, no motion-blurred instance built),
// and a moving object at the frame's instant is where its transform puts it (the raster
// passes' and rt_whitted's view), bit for bit against the static scene.
TEST(MotionBlur, StaticScenesAndTheFrameInstantAreUnchanged) {
  const Scene zero = loadScene(writeScene("zero.json", edgeScene(0.f)));
  EXPECT_FALSE(zero.hasMotion());
  const WorldGeometry zeroWorld = flattenScene(zero);
  const RtDevice device;
  EXPECT_EQ(RtScene(device, zeroWorld, zero).movingGeometries(), 0);
  for (const std::string kind : {"analytic", "tessellated", "sdf"}) {
    const Scene moving = loadScene(writeScene("ball.json", ballScene(kind)));
    Scene still = moving;
    for (Instance& inst : still.instances) inst.motion = vec3(0.f);
    const nlohmann::json w = {{"spp", 1}, {"depth", 3}};
    const CpuImage m = renderPass(moving, "rt_whitted", w, 64, 48);
    const CpuImage s = renderPass(still, "rt_whitted", w, 64, 48);
    int differing = 0;
    for (std::size_t i = 0; i < m.words.size(); ++i) differing += m.words[i] != s.words[i];
    EXPECT_EQ(differing, 0) << kind;
  }
}

// The raster side's snapshots (sceneAtTime, the accumulation buffer's scenes): the scene at time
// t is static, its moving instances placed where the rays at t meet them, so that a ray at t on
// the moving scene and the same ray at the frame's instant on the snapshot see the same thing.
TEST(MotionBlur, SnapshotAtATimeIsWhatRaysAtThatTimeSee) {
  const Scene moving = loadScene(writeScene("ball.json", ballScene()));
  const WorldGeometry movingWorld = flattenScene(moving);
  const RtDevice device;
  const RtScene movingRt(device, movingWorld, moving);
  const WhittedTracer movingTracer(moving, movingWorld, movingRt, {5, 1});
  for (const float time : {0.f, 0.3f, 0.9f}) {
    const Scene snapshot = sceneAtTime(moving, time);
    EXPECT_FALSE(snapshot.hasMotion());
    EXPECT_EQ(vec3(snapshot.instances[1].transform[3]), vec3((time - 0.5f) * 4.f, 1.f, 0.f));
    EXPECT_EQ(snapshot.instances[0].transform, moving.instances[0].transform);
    const WorldGeometry world = flattenScene(snapshot);
    const RtScene rt(device, world, snapshot);
    EXPECT_EQ(rt.movingGeometries(), 0);
    const WhittedTracer tracer(snapshot, world, rt, {5, 1});
    for (int k = 0; k < 16; ++k) {
      const vec3 target((float(k % 4) - 1.5f) * 1.2f + (time - 0.5f) * 4.f, 0.6f,
                        (float(k / 4) - 1.5f) * 0.8f);
      const vec3 eye(0.f, 6.f, 9.f);
      const vec3 d = glm::normalize(target - eye);
      const vec3 a = movingTracer.radiance(Ray{eye, d, time}, 1, 0u);
      const vec3 b = tracer.radiance(Ray{eye, d, kFrameTime}, 1, 0u);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-4f) << "t " << time << " ray " << k;
    }
  }
}
}  // namespace DIPTYCH_UNITY_ID
