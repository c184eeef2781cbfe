// Forward-renderer producers on real OSMesa GL, checked against analytic values (blending) and
// against Embree reflection rays shaded with the same model (planar mirror, dynamic cube).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "engine/gl/forward_renderer.h"
#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/environment.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/common/hits_texel.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Scene sceneFromJson(const std::string& name, const std::string& json) {
  const auto dir = ::diptych::testing::scratchDir("diptych_forward_producers");
  std::filesystem::create_directories(dir);
  const auto path = dir / (name + ".json");
  std::ofstream(path) << json;
  return loadScene(path);
}

struct ProducerRun {
  CpuImage signal, hits;
};

// gbuffer -> producer; returns the producer's signal and the G-buffer hits.
ProducerRun runProducer(const Scene& scene, const std::string& type, const std::string& signal,
                        int width, int height) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "p", .type = type, .inputs = {{"hits", "gbuffer.hits"}}, .place = "passes[1]"}};
  recipe.outputs = {"p." + signal, "gbuffer.hits"};
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, {width, height, scene.camera});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor executor(graph, world);
  executor.runFrame();
  return {executor.output("p." + signal), executor.output("gbuffer.hits")};
}

vec3 rgb(const CpuImage& s, int x, int y) {
  return {s.f(x, y, 0), s.f(x, y, 1), s.f(x, y, 2)};
}
float maxDiff(const vec3& a, const vec3& b) {
  const vec3 d = glm::abs(a - b);
  return std::max({d.x, d.y, d.z});
}

// ---- Blending -------------------------------------------------------------------------------

// Background (emissive 1) at z = -2, a transmissive front quad F at z = 1 covering the view,
// and behind F two overlapping emissive transmissive quads: A at z = 0 (x in [-1.2, 0.4]) and
// B at z = -0.5 (x in [-0.4, 1.2]). No lights: I_m = M_E exactly.
std::string layeredQuads(bool frontToBack) {
  const std::string a =
      R"({"type": "quad", "material": "a", "corners": [[-1.2,-0.8,0],[0.4,-0.8,0],[0.4,0.8,0],[-1.2,0.8,0]]})";
  const std::string b =
      R"({"type": "quad", "material": "b", "corners": [[-0.4,-0.8,-0.5],[1.2,-0.8,-0.5],[1.2,0.8,-0.5],[-0.4,0.8,-0.5]]})";
  return R"({"camera": {"position": [0,0,5], "target": [0,0,0], "fov": 45},
    "materials": {
      "bg": {"kd": 0, "emission": [1,1,1]},
      "front": {"kd": 0, "kt": 0.5, "emission": [3,3,3]},
      "a": {"kd": 0, "kt": 0.5, "emission": [0.2,0,0]},
      "b": {"kd": 0, "kt": 0.5, "emission": [0,0.2,0]}},
    "objects": [
      {"type": "quad", "material": "bg", "corners": [[-10,-10,-2],[10,-10,-2],[10,10,-2],[-10,10,-2]]},
      {"type": "quad", "material": "front", "corners": [[-10,-10,1],[10,-10,1],[10,10,1],[-10,10,1]]},
      )" +
         (frontToBack ? a + "," + b : b + "," + a) + "]}";
}

// Which of A, B the pixel-centre ray crosses; pixels within `margin` of an edge are ambiguous.
struct Coverage {
  bool a, b, ambiguous;
};
Coverage coverage(const Camera& camera, int w, int h, int x, int y) {
  const Ray r = primaryRay(camera, w, h, x + 0.5f, y + 0.5f);
  const auto inside = [&](float z, float x0, float x1, bool& amb) {
    const vec3 p = r.origin + (z - r.origin.z) / r.direction.z * r.direction;
    const float margin = 0.08f;  // about 1.5 pixels at these depths
    const float dx = std::min(std::abs(p.x - x0), std::abs(p.x - x1));
    const float dy = std::abs(std::abs(p.y) - 0.8f);
    amb = amb || dx < margin || dy < margin;
    return p.x > x0 && p.x < x1 && std::abs(p.y) < 0.8f;
  };
  Coverage c{false, false, false};
  c.a = inside(0.f, -1.2f, 0.4f, c.ambiguous);
  c.b = inside(-0.5f, -0.4f, 1.2f, c.ambiguous);
  return c;
}

TEST(BlendTransmission, SortedIsOrderIndependentUnsortedIsNotWhereQuadsOverlap) {
  constexpr int W = 64, H = 48;
  const Scene frontToBack = sceneFromJson("f2b", layeredQuads(true));
  const Scene backToFront = sceneFromJson("b2f", layeredQuads(false));
  const CpuImage sortedF2B = runProducer(frontToBack, "sorted_blend", "transmission", W, H).signal;
  const CpuImage sortedB2F = runProducer(backToFront, "sorted_blend", "transmission", W, H).signal;
  const CpuImage unsortedF2B =
      runProducer(frontToBack, "unsorted_blend", "transmission", W, H).signal;
  const CpuImage unsortedB2F =
      runProducer(backToFront, "unsorted_blend", "transmission", W, H).signal;

  // Lecture: I = I_m + k_t M_t I from the back: background 1, B: (0, 0.2, 0) + 0.5 I,
  // A: (0.2, 0, 0) + 0.5 I. Correct overlap (0.45, 0.35, 0.25); A drawn first: (0.35, 0.45, 0.25).
  const vec3 bg(1.f), onlyA(0.7f, 0.5f, 0.5f), onlyB(0.5f, 0.7f, 0.5f);
  const vec3 both(0.45f, 0.35f, 0.25f), bothWrong(0.35f, 0.45f, 0.25f);
  float sortedErr = 0.f, unsortedOutsideErr = 0.f, unsortedOverlapErr = 0.f;
  float minOverlapDiff = 1e30f;
  int overlap = 0, single = 0;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const Coverage c = coverage(frontToBack.camera, W, H, x, y);
      if (c.ambiguous) continue;
      const vec3 expected = c.a && c.b ? both : c.a ? onlyA : c.b ? onlyB : bg;
      sortedErr = std::max({sortedErr, maxDiff(rgb(sortedF2B, x, y), expected),
                            maxDiff(rgb(sortedB2F, x, y), expected)});
      if (c.a && c.b) {
        ++overlap;
        unsortedOverlapErr =
            std::max({unsortedOverlapErr, maxDiff(rgb(unsortedF2B, x, y), bothWrong),
                      maxDiff(rgb(unsortedB2F, x, y), both)});
        minOverlapDiff =
            std::min(minOverlapDiff, maxDiff(rgb(unsortedF2B, x, y), rgb(sortedF2B, x, y)));
      } else {
        single += c.a || c.b;
        unsortedOutsideErr =
            std::max({unsortedOutsideErr, maxDiff(rgb(unsortedF2B, x, y), rgb(sortedF2B, x, y)),
                      maxDiff(rgb(unsortedB2F, x, y), rgb(sortedF2B, x, y))});
      }
    }
  }
  std::printf(
      "blend: %d overlap px, %d single px; sorted max err %g; unsorted outside overlap "
      "max diff %g; unsorted overlap max err vs wrong/right order %g, min |unsorted - "
      "sorted| in overlap %g\n",
      overlap, single, sortedErr, unsortedOutsideErr, unsortedOverlapErr, minOverlapDiff);
  EXPECT_GT(overlap, 50);
  EXPECT_GT(single, 100);
  EXPECT_LE(sortedErr, 1e-5f);
  EXPECT_LE(unsortedOutsideErr, 1e-5f);
  EXPECT_LE(unsortedOverlapErr, 1e-5f);
  EXPECT_GE(minOverlapDiff, 0.1f - 1e-5f);  // |0.45 - 0.35|
}

// A directional light (E = 2 along -z) on a diffuse plane (C, k_d = 1) at z = -2; a lit
// transmissive quad T (k_d = 0.5, C_T, k_t = 0.6, M_T) at z = 0 over the left half (x < 0); a
// transmissive front quad F at z = 1 for |x| < 1. Through F:
//   only the plane behind: I = E C;   T and the plane: I = E k_d,T C_T + k_t M_T E C.
// Outside F the first surface is T (transmission = E C) or the plane (k_t = 0: 0).
TEST(BlendTransmission, ComposesTheLectureFormulaOverALitPlane) {
  constexpr int W = 64, H = 48;
  const Scene scene = sceneFromJson("formula", R"({
    "camera": {"position": [0,0,5], "target": [0,0,0], "fov": 45},
    "lights": [{"type": "directional", "direction": [0,0,-1], "intensity": 2}],
    "materials": {
      "plane": {"color": [0.5,0.6,0.7]},
      "t": {"color": [0.2,0.4,0.6], "kd": 0.5, "kt": 0.6, "transmit_color": [1,0.5,0.25]},
      "f": {"color": [1,1,1], "kt": 0.9}},
    "objects": [
      {"type": "quad", "material": "plane", "corners": [[-10,-10,-2],[10,-10,-2],[10,10,-2],[-10,10,-2]]},
      {"type": "quad", "material": "t", "corners": [[-10,-10,0],[0,-10,0],[0,10,0],[-10,10,0]]},
      {"type": "quad", "material": "f", "corners": [[-1,-10,1],[1,-10,1],[1,10,1],[-1,10,1]]}]})");
  const vec3 plane = 2.f * vec3(0.5f, 0.6f, 0.7f);
  const vec3 throughT = 2.f * 0.5f * vec3(0.2f, 0.4f, 0.6f) + 0.6f * vec3(1.f, 0.5f, 0.25f) * plane;
  const ProducerRun run = runProducer(scene, "sorted_blend", "transmission", W, H);
  float err = 0.f;
  int counts[3] = {0, 0, 0};
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const Ray r = primaryRay(scene.camera, W, H, x + 0.5f, y + 0.5f);
      const float xF = r.origin.x + (1.f - 5.f) / r.direction.z * r.direction.x;
      const float xT = r.origin.x + (0.f - 5.f) / r.direction.z * r.direction.x;
      if (std::abs(xF) > 0.95f && std::abs(xF) < 1.05f) continue;  // edge pixels of F
      if (std::abs(xT) < 0.05f) continue;                          // edge pixels of T
      const bool inF = std::abs(xF) < 1.f, inT = xT < 0.f;
      const vec3 expected = inF ? (inT ? throughT : plane) : (inT ? plane : vec3(0.f));
      ++counts[inF ? (inT ? 0 : 1) : 2];
      err = std::max(err, maxDiff(rgb(run.signal, x, y), expected));
    }
  }
  std::printf("formula: %d px through F and T, %d through F only, %d outside F; max err %g\n",
              counts[0], counts[1], counts[2], err);
  EXPECT_GT(counts[0], 50);
  EXPECT_GT(counts[1], 50);
  EXPECT_LE(err, 1e-5f);
}

// ---- Reflections against Embree --------------------------------------------------------------

// L along a reflected ray from the exact G-buffer point, shaded as the forward renderer does
// (no shadows, no secondary terms); the environment on a miss.
vec3 referenceReflection(RenderWorld& world, const Camera& camera, int w, int h, int x, int y,
                         const SurfaceHit& hit) {
  const Scene& scene = world.scene();
  const Ray eye = primaryRay(camera, w, h, x + 0.5f, y + 0.5f);
  const SurfacePoint sp = makeSurfacePoint(scene, world.geometry(), hit, eye.direction);
  const vec3 r = glm::normalize(shading::reflectAbout(-eye.direction, sp.shadingNormal));
  const Ray ray{offsetRayOrigin(sp.position, sp.geometricNormal, sp.positionMagnitude), r};
  const auto next = world.rtScene().intersect(ray, 0.f, std::numeric_limits<float>::infinity());
  if (!next) return sampleEnvironment(scene.environment, r);
  const SurfacePoint q = makeSurfacePoint(scene, world.geometry(),
                                          {next->instance, next->primitive, next->u, next->v}, r);
  vec3 radiance = shading::emittedAndAmbient(q.resolved, scene.ambient);
  for (const Light& l : scene.lights) {
    const auto s = shading::sampleLight(shading::toShadingLight(l), q.position);
    radiance += shading::lightContribution(q.resolved, q.shadingNormal, -r, s, 1.f);
  }
  return radiance;
}

struct Agreement {
  int pixels = 0, objectPixels = 0, within = 0;
  double meanError = 0.0;
  float maxError = 0.f;
};

// Compares a reflection signal with the reference on every pixel of `instance`; "within" counts
// pixels whose largest channel error is <= tolerance; objectPixels: reference ray hit geometry.
Agreement compareReflection(const Scene& scene, const ProducerRun& run, int instance, int w, int h,
                            float tolerance) {
  RenderWorld world(scene);
  Agreement a;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto hit = hitsTexel(run.hits, x, y);
      if (!hit || hit->instance != instance) continue;
      const vec3 ref = referenceReflection(world, scene.camera, w, h, x, y, *hit);
      const float e = maxDiff(rgb(run.signal, x, y), ref);
      ++a.pixels;
      a.objectPixels += maxDiff(ref, scene.environment.color) > 0.f;
      a.within += e <= tolerance;
      a.meanError += e;
      a.maxError = std::max(a.maxError, e);
    }
  }
  a.meanError /= std::max(a.pixels, 1);
  return a;
}

// A floor mirror (y = 0) and a lit red box standing on it, a dim blue background.
constexpr const char* kMirrorScene = R"({
  "camera": {"position": [0,2,6], "target": [0,0.3,0], "fov": 45},
  "environment": {"color": [0.1,0.1,0.3]},
  "lights": [{"type": "point", "position": [2,4,4], "intensity": 30}],
  "materials": {
    "mirror": {"kd": 0, "kps": 1, "color": [0,0,0]},
    "red": {"color": [0.9,0.2,0.1], "ka": 0.1, "ks": 0.5, "exponent": 20}},
  "objects": [
    {"type": "plane", "material": "mirror", "size": [6,6]},
    {"type": "box", "material": "red", "size": [1,1,1], "transform": {"translate": [0,0.8,0], "rotate": [0,30,0]}}]})";

TEST(PlanarMirror, MirrorPixelsMatchEmbreeReflectionRays) {
  constexpr int W = 96, H = 72;
  const Scene scene = sceneFromJson("mirror", kMirrorScene);
  const ProducerRun run = runProducer(scene, "planar_mirror", "reflection", W, H);
  const Agreement a = compareReflection(scene, run, 0, W, H, 1e-4f);
  std::printf(
      "planar_mirror: %d mirror px (%d see the box), %d within 1e-4 (%.2f%%), mean err "
      "%g, max err %g\n",
      a.pixels, a.objectPixels, a.within, 100.0 * a.within / a.pixels, a.meanError, a.maxError);
  EXPECT_GT(a.objectPixels, 100);
  EXPECT_GE(a.within, int(0.97 * a.pixels));  // the rest: box silhouette pixels
  EXPECT_LE(a.meanError, 0.02);
}

// A mirror sphere at the origin and an emissive green box beside it on +x, a dim background.
std::string cubeScene(float distance, float size) {
  const std::string d = std::to_string(distance), sz = std::to_string(size);
  return R"({
  "camera": {"position": [0,0.5,5], "target": [0,0,0], "fov": 40},
  "environment": {"color": [0.1,0.1,0.3]},
  "materials": {
    "mirror": {"kd": 0, "kps": 1, "color": [0,0,0]},
    "green": {"kd": 0, "emission": [0.2,1,0.3]}},
  "objects": [
    {"type": "sphere", "material": "mirror", "radius": 1},
    {"type": "box", "material": "green", "size": [)" +
         sz + "," + sz + "," + sz + R"(], "transform": {"translate": [)" + d + R"(,0,0]}}]})";
}

// The same box seen under about the same angle, near (parallax) and 5x farther away.
class DynamicCube : public ::testing::TestWithParam<float> {};

TEST_P(DynamicCube, CaptureShowsTheBoxInTheReflectedDirection) {
  constexpr int W = 128, H = 96;
  const float scale = GetParam();
  const Scene scene = sceneFromJson("cube", cubeScene(2.6f * scale, 1.5f * scale));
  const ProducerRun run = runProducer(scene, "env_dynamic_cube", "reflection", W, H);
  const Agreement a = compareReflection(scene, run, 0, W, H, 1e-2f);
  // Direction: where the exact reflected ray sees the box, does the cube lookup see it too
  // (green channel above half of the box's 1), and on which side of the image is it?
  RenderWorld world(scene);
  int refBox = 0, bothBox = 0, cubeBox = 0, cubeBoxRight = 0;
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      const auto hit = hitsTexel(run.hits, x, y);
      if (!hit || hit->instance != 0) continue;
      const bool ref = referenceReflection(world, scene.camera, W, H, x, y, *hit).y > 0.5f;
      const bool cube = run.signal.f(x, y, 1) > 0.5f;
      refBox += ref, bothBox += ref && cube, cubeBox += cube, cubeBoxRight += cube && x > W / 2;
    }
  }
  std::printf(
      "env_dynamic_cube (box at %g): %d sphere px (%d see the box), %d within 1e-2 (%.2f%%), mean "
      "err %g, max err %g; box px: reference %d, cube %d, both %d, cube box px right of "
      "centre %d\n",
      2.6 * scale, a.pixels, a.objectPixels, a.within, 100.0 * a.within / a.pixels, a.meanError,
      a.maxError, refBox, cubeBox, bothBox, cubeBoxRight);
  EXPECT_GT(refBox, 50);
  EXPECT_EQ(cubeBoxRight, cubeBox);  // the box is on +x: only the right side shows it
  // Parallax: the cube sees the box from the centre, not from the surface point; it fades as
  // the box moves away (the error of a cube map is its distance to the centre vs the scene's).
  EXPECT_GE(bothBox, int((scale > 1.f ? 0.8 : 0.4) * refBox));
  EXPECT_GE(a.within, int(0.9 * a.pixels));
  EXPECT_LE(a.meanError, 0.1);
}
INSTANTIATE_TEST_SUITE_P(NearAndFar, DynamicCube, ::testing::Values(1.f, 5.f));

TEST(DynamicCubeFaces, FaceDirectionsFollowTheGlCubeConvention) {
  for (int face = 0; face < 6; ++face) {
    for (const vec2 ab : {vec2(0.f), vec2(0.5f, -0.25f), vec2(-0.75f, 0.6f)}) {
      vec2 st;
      EXPECT_EQ(cubeFace(gl::cubeFaceDirection(face, ab.x, ab.y), st), face);
      EXPECT_NEAR(st.x, 0.5f * (ab.x + 1.f), 1e-6f);
      EXPECT_NEAR(st.y, 0.5f * (ab.y + 1.f), 1e-6f);
    }
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
