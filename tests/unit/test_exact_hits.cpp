// The frame's exact-hit buffer (passes/common/exact_hits.h): every exact consumer of a hybrid
// frame reads the G-buffer texels lifted onto the analytic surfaces from one buffer, built once
// per frame (and per distinct hits image and camera), and equal texel for texel to lifting each
// texel itself.
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
using namespace diptych::testing;

constexpr int kW = 160, kH = 120;

std::unique_ptr<HybridFrame> whittedFrame() {
  return renderHybridFrame(std::filesystem::path(samplesDir()) / "scenes/whitted.json", kW, kH,
                           {"shade.color", "gbuffer.hits"});
}

bool sameHit(const std::optional<SurfaceHit>& a, const std::optional<SurfaceHit>& b) {
  if (!a || !b) return !a && !b;
  return a->instance == b->instance && a->primitive == b->primitive && a->u == b->u &&
         a->v == b->v && a->analytic == b->analytic;
}

TEST(ExactHits, EqualsLiftingEachTexel) {
  auto f = whittedFrame();
  const CpuImage& hits = f->output("gbuffer.hits");
  const Camera camera = cameraOf(f->scene);
  const ExactHitBuffer& exact = exactHits(*f->world, hits, camera);
  int lifted = 0, background = 0;
  for (int y = 0; y < kH; ++y) {
    for (int x = 0; x < kW; ++x) {
      const auto expected =
          exactTexel(hits, f->world->geometry(), camera, x, y, &f->world->rtScene());
      ASSERT_TRUE(sameHit(exact.at(x, y), expected)) << "pixel " << x << "," << y;
      lifted += expected && expected->analytic ? 1 : 0;
      background += expected ? 0 : 1;
    }
  }
  EXPECT_GT(lifted, 500) << "whitted.json's spheres should cover many pixels";
  EXPECT_GT(background, 0);
}

// The points kept for the frame's consumers (ExactHitBuffer::point) are makeSurfacePoint's, on
// exactly the pixels of a material with reflection or transmission, made once and kept: the
// second call and keptPoint return the same point.
TEST(ExactHits, KeepsTheSharedPixelsSurfacePointsAsMadeOnce) {
  auto f = whittedFrame();
  const CpuImage& hits = f->output("gbuffer.hits");
  const Camera camera = cameraOf(f->scene);
  const ExactHitBuffer& exact = exactHits(*f->world, hits, camera);  // a new build: none kept
  const Scene& scene = f->scene;
  const WorldGeometry& geometry = f->world->geometry();
  const PinholeFrame pinhole(camera, kW, kH);
  int shared = 0, other = 0, sx = -1, sy = -1;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      ASSERT_EQ(exact.keptPoint(x, y), nullptr) << "pixel " << x << "," << y;
      const auto hit = exact.at(x, y);
      const vec3 incoming = pinhole.ray(float(x) + 0.5f, float(y) + 0.5f).direction;
      const SurfacePoint* kept = exact.point(scene, geometry, x, y, incoming);
      bool sharedMaterial = false;
      if (hit) {
        const Material& m =
            scene.material(scene.meshes[scene.instances[hit->instance].mesh].material);
        sharedMaterial = shading::materialHasReflection(m) || shading::materialHasTransmission(m);
      }
      if (!sharedMaterial) {
        EXPECT_EQ(kept, nullptr) << "pixel " << x << "," << y;
        other += hit ? 1 : 0;
        continue;
      }
      ++shared;
      sx = x;
      sy = y;
      ASSERT_NE(kept, nullptr) << "pixel " << x << "," << y;
      const SurfacePoint made = makeSurfacePoint(scene, geometry, *hit, incoming);
      EXPECT_EQ(kept->position, made.position);
      EXPECT_EQ(kept->positionMagnitude, made.positionMagnitude);
      EXPECT_EQ(kept->geometricNormal, made.geometricNormal);
      EXPECT_EQ(kept->shadingNormal, made.shadingNormal);
      EXPECT_EQ(kept->frontFacing, made.frontFacing);
      EXPECT_EQ(kept->material, made.material);
      EXPECT_EQ(kept->resolved.kps, made.resolved.kps);
      EXPECT_EQ(kept->resolved.kt, made.resolved.kt);
      EXPECT_EQ(kept->resolved.color, made.resolved.color);
      EXPECT_EQ(exact.point(scene, geometry, x, y, incoming), kept) << "made once";
      EXPECT_EQ(exact.keptPoint(x, y), kept);
    }
  EXPECT_GT(shared, 500) << "whitted.json's mirror and glass spheres";
  EXPECT_GT(other, 500) << "its diffuse floor";
  // The next build forgets them (a frame's points are that frame's).
  CpuImage edited = hits;
  edited.setU(sx, sy, 0, 0u);  // now background
  const ExactHitBuffer& rebuilt = exactHits(*f->world, edited, camera);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) ASSERT_EQ(rebuilt.keptPoint(x, y), nullptr);
}

// In a hybrid frame rt_reflection keeps its mirror pixels' points for rt_transmission and shade.
TEST(ExactHits, AHybridFrameKeepsItsMirrorPixelsPoints) {
  auto f = whittedFrame();
  const ExactHitBuffer& exact = f->world->cpuCached<ExactHitBuffer>();
  int kept = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) kept += exact.keptPoint(x, y) != nullptr;
  EXPECT_GT(kept, 500);
}

TEST(ExactHits, BuiltOncePerFrameForAllConsumers) {
  // The default hybrid recipe: rt_shadows, rt_reflection, rt_transmission and the CPU shade all
  // read it; texture_supersample needs coverage only.
  auto f = whittedFrame();
  const ExactHitBuffer& exact = f->world->cpuCached<ExactHitBuffer>();
  const int first = exact.builds();
  EXPECT_GE(first, 1);
  // Same G-buffer, same camera: the next frame pays for its own buffer (as a moving camera
  // would), once for its four consumers.
  f->executor->runFrame();
  EXPECT_EQ(exact.builds(), first + 1);
  f->executor->runFrame();
  EXPECT_EQ(exact.builds(), first + 2);
}

TEST(ExactHits, RebuiltWhenTheHitsOrTheCameraChange) {
  auto f = whittedFrame();
  CpuImage hits = f->output("gbuffer.hits");
  const Camera camera = cameraOf(f->scene);
  int ax = -1, ay = -1;  // a texel on an analytic sphere
  for (int y = 0; y < kH && ax < 0; ++y)
    for (int x = 0; x < kW && ax < 0; ++x)
      if (const auto h = exactHits(*f->world, hits, camera).at(x, y); h && h->analytic) {
        ax = x;
        ay = y;
      }
  ASSERT_GE(ax, 0);
  const int before = f->world->cpuCached<ExactHitBuffer>().builds();

  hits.setU(ax, ay, 0, 0u);  // now background
  EXPECT_FALSE(exactHits(*f->world, hits, camera).at(ax, ay));
  EXPECT_EQ(f->world->cpuCached<ExactHitBuffer>().builds(), before + 1);

  hits = f->output("gbuffer.hits");
  Camera moved = camera;
  moved.position += vec3(0.f, 0.05f, 0.f);
  const auto there = exactHits(*f->world, hits, moved).at(ax, ay);
  const auto expected = exactTexel(hits, f->world->geometry(), moved, ax, ay, &f->world->rtScene());
  EXPECT_TRUE(sameHit(there, expected));
  EXPECT_FALSE(
      sameHit(there, exactTexel(hits, f->world->geometry(), camera, ax, ay, &f->world->rtScene())));
  EXPECT_EQ(f->world->cpuCached<ExactHitBuffer>().builds(), before + 2);
}

// The pass-keyed path (frame serial + resource version, no look at the texels): a camera moved
// between runFrame calls gives a new G-buffer and a new buffer, built once for that frame's
// consumers and equal to lifting the new texels along the new camera's pixel rays.
TEST(ExactHits, PassKeyedBufferFollowsTheCameraBetweenFrames) {
  auto f = whittedFrame();
  const ExactHitBuffer& exact = f->world->cpuCached<ExactHitBuffer>();
  const Camera before = f->graph.frame.camera;
  const int builds = exact.builds();
  // The executor reads the compiled graph's frame settings by reference, as the viewer does.
  f->graph.frame.camera.position += vec3(0.f, 0.3f, 0.f);
  const Camera moved = f->graph.frame.camera;
  f->executor->runFrame();
  EXPECT_EQ(exact.builds(), builds + 1) << "once per frame for all its consumers";
  const CpuImage& hits = f->output("gbuffer.hits");
  int differ = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      ASSERT_TRUE(sameHit(exact.at(x, y), exactTexel(hits, f->world->geometry(), moved, x, y,
                                                     &f->world->rtScene())))
          << "pixel " << x << "," << y;
      differ += !sameHit(exact.at(x, y), exactTexel(hits, f->world->geometry(), before, x, y,
                                                    &f->world->rtScene()));
    }
  EXPECT_GT(differ, 0) << "the old camera's rays would lift the texels elsewhere";
}

// A hits texel naming an instance or a primitive the world does not have (a G-buffer of another
// scene, a corrupt texture) is the project's Error naming it, never an out-of-range read.
TEST(ExactHits, AForgedTexelIsAnErrorNamingIt) {
  auto f = whittedFrame();
  const Camera camera = cameraOf(f->scene);
  const WorldGeometry& geometry = f->world->geometry();
  const PinholeFrame pinhole(camera, kW, kH);
  auto message = [&](const CpuImage& hits) -> std::string {
    try {
      exactHits(*f->world, hits, camera);
    } catch (const Error& e) {
      EXPECT_THROW(triangleTexel(hits, geometry, pinhole, 3, 2), Error);
      return e.what();
    }
    return "no Error";
  };
  CpuImage hits = f->output("gbuffer.hits");
  const std::uint32_t nan = std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN());
  hits.setU(3, 2, 0, std::uint32_t(geometry.meshes.size()) + 1);  // instance = meshes.size()
  hits.setU(3, 2, 2, nan);
  EXPECT_NE(
      message(hits).find("instance " + std::to_string(geometry.meshes.size()) + " out of range"),
      std::string::npos)
      << message(hits);
  hits.setU(3, 2, 0, 1u);  // instance 0
  hits.setU(3, 2, 1, 1u << 30);
  EXPECT_NE(message(hits).find("primitive 1073741824 out of range"), std::string::npos)
      << message(hits);
}

// Two hits resources in one frame: a recipe with a second G-buffer pass (gbuffer2) whose hits
// the reflection and shade passes read, the shadows and transmission passes reading gbuffer's.
// One frame has one camera and size, so the recipe format cannot make the two resources' texels
// differ: what a buffer keyed on the frame alone would get wrong is which resource it names, so
// the test counts builds (one per switch of resource, at least two a frame; one if the key
// ignored the resource) and checks the image equals the one-G-buffer recipe's, byte for byte.
TEST(ExactHits, TwoHitsResourcesInOneFrameEachGetTheirOwnBuffer) {
  Recipe two = defaultHybridRecipe();
  two.passes.insert(two.passes.begin() + 1, RecipePass{.name = "gbuffer2", .type = "gbuffer"});
  int repointed = 0;
  for (RecipePass& p : two.passes)
    if (p.type == "rt_reflection" || p.type == "shade") {
      p.inputs["hits"] = "gbuffer2.hits";
      ++repointed;
    }
  ASSERT_EQ(repointed, 2);
  const auto scene = std::filesystem::path(samplesDir()) / "scenes/whitted.json";
  auto f = renderHybridFrame(scene, kW, kH, {"shade.color"}, two);
  ASSERT_NE(f->pass("gbuffer2"), nullptr);
  const ExactHitBuffer& exact = f->world->cpuCached<ExactHitBuffer>();
  const int before = exact.builds();
  f->executor->runFrame();
  EXPECT_GE(exact.builds() - before, 2) << "one build per frame: the key ignored the resource";
  const auto one = whittedFrame();
  EXPECT_TRUE(f->output("shade.color").words == one->output("shade.color").words)
      << "a consumer read the other resource's buffer wrongly";
}
}  // namespace DIPTYCH_UNITY_ID
