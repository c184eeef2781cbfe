// Environment-map reflection producers (env_cube, env_sphere, env_equirect) in the one case where
// an environment map is exact: a convex mirror (a finely tessellated sphere, k_ps = 1) under an
// environment at infinity, so nothing local can appear in a reflection. Each producer runs in a
// real frame graph (OSMesa G-buffer + the producer's compute pass) and is compared per pixel with
// a CPU reference: r from the same hits texel's exact point and shading normal
// (makeSurfacePoint), then sampleEnvironment(env, r). What remains is filtering/resampling error.
// A second reference uses the analytic sphere normal, which adds the tessellation error.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "engine/gl/debug.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/environment.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/common/hits_texel.h"
#include "passes/raster/env_maps.h"
#include "passes/registry.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;
constexpr int kSize = 192;  // frame side

// A smooth, strictly positive pattern by direction (values in [0.1, 1.0]): a gradient along
// each axis plus a product term, so no channel is linear in the map's texel coordinates.
vec3 pattern(vec3 d) {
  d = glm::normalize(d);
  return vec3(0.55f + 0.35f * d.x + 0.1f * d.y * d.z, 0.55f + 0.35f * d.y + 0.1f * d.x * d.z,
              0.55f + 0.35f * d.z + 0.1f * d.x * d.y);
}

Image patternImage(int width, int height, const std::function<vec3(vec2)>& direction) {
  Image img(width, height, 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const vec3 c = pattern(direction(vec2((x + 0.5f) / width, (y + 0.5f) / height)));
      for (int k = 0; k < 3; ++k) img.at(x, y, k) = c[k];
    }
  return img;
}

// A temp folder with the synthetic equirect and cube faces, and JSON scenes using them.
class EnvFixture : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("diptych_env_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    writeImage(dir_ / "env.exr", patternImage(1024, 512, [](vec2 uv) {
                 const float phi = (uv.x - 0.5f) * 2.f * glm::pi<float>();
                 const float theta = uv.y * glm::pi<float>();
                 return vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                             std::sin(theta) * std::sin(phi));
               }));
    for (int f = 0; f < 6; ++f)
      writeImage(dir_ / ("face" + std::to_string(f) + ".exr"),
                 patternImage(256, 256, [f](vec2 st) { return envmap::cubeFaceDirection(f, st); }));
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  // A unit mirror sphere at the origin seen from +z, with the given "environment" object.
  // With `floor`, a diffuse (k_ps = 0) box under the sphere, whose pixels must stay 0.
  static Scene mirrorScene(const nlohmann::json& environment, const std::string& name,
                           bool floor = false) {
    nlohmann::json scene = {
        {"camera", {{"position", {0.4, 0.5, 3.2}}, {"target", {0, 0, 0}}, {"fov", 45}}},
        {"environment", environment},
        {"materials", {{"mirror", {{"kd", 0}, {"kps", 1}, {"color", {0, 0, 0}}}}}},
        {"objects",
         {{{"type", "sphere"}, {"radius", 1}, {"segments", {384, 192}}, {"material", "mirror"}}}}};
    if (floor)
      scene["objects"].push_back(
          {{"type", "box"}, {"size", {4, 0.2, 4}}, {"transform", {{"translate", {0, -1.2, 0}}}}});
    const fs::path path = dir_ / name;
    std::ofstream(path) << scene.dump(1);
    return loadScene(path);
  }
  static Scene equirectScene() { return mirrorScene({{"equirect", "env.exr"}}, "equirect.json"); }
  static Scene cubeScene() {
    nlohmann::json faces = nlohmann::json::array();
    for (int f = 0; f < 6; ++f) faces.push_back("face" + std::to_string(f) + ".exr");
    return mirrorScene({{"cube", faces}}, "cube.json");
  }

  static fs::path dir_;
};
fs::path EnvFixture::dir_;

struct Frame {
  CpuImage hits, reflection;
};

Frame render(const Scene& scene, const std::string& type, int resolution) {
  const nlohmann::json recipe = {{"passes",
                                  {{{"name", "gbuffer"}, {"type", "gbuffer"}},
                                   {{"name", "env"},
                                    {"type", type},
                                    {"params", {{"resolution", resolution}}},
                                    {"inputs", {{"hits", "gbuffer.hits"}}}}}},
                                 {"outputs", {"env.reflection", "gbuffer.hits"}}};
  const FrameSettings frame{.width = kSize, .height = kSize, .camera = scene.camera};
  const CompiledGraph graph =
      compileGraph(parseRecipe(recipe, "test"), builtinPasses(), scene, frame);
  gl::GlContext& context = gl::testing::osmesaContext();
  const int errors = gl::glDebugErrorCount();
  RenderWorld world(scene, &context);
  GraphExecutor executor(graph, world);
  executor.runFrame();
  EXPECT_EQ(gl::glDebugErrorCount(), errors);
  return {executor.output("gbuffer.hits"), executor.output("env.reflection")};
}

struct Errors {
  double mean = 0, p99 = 0, max = 0;
  int pixels = 0;
};

// Relative error per pixel: max_c |a_c - b_c| / max_c |b_c| (the pattern is >= 0.1, so the
// denominator never approaches 0).
Errors measure(const Frame& f, const std::function<std::optional<vec3>(int, int)>& reference) {
  std::vector<double> e;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const auto ref = reference(x, y);
      if (!ref) continue;
      const vec3 got(f.reflection.f(x, y, 0), f.reflection.f(x, y, 1), f.reflection.f(x, y, 2));
      const vec3 diff = glm::abs(got - *ref);
      e.push_back(std::max({diff.x, diff.y, diff.z}) / std::max({ref->x, ref->y, ref->z}));
    }
  Errors out;
  out.pixels = int(e.size());
  if (e.empty()) return out;
  std::sort(e.begin(), e.end());
  for (double v : e) out.mean += v / double(e.size());
  out.p99 = e[std::min(e.size() - 1, std::size_t(0.99 * double(e.size())))];
  out.max = e.back();
  return out;
}

// The reference a ray tracer's reflection ray would see: same hits texel, exact point and
// shading normal (makeSurfacePoint), r = reflect(-v, n), sampleEnvironment(env, r).
Errors againstSurfaceReference(const Scene& scene, const Frame& f) {
  const WorldGeometry world = flattenScene(scene);
  return measure(f, [&](int x, int y) -> std::optional<vec3> {
    const auto hit = hitsTexel(f.hits, x, y);
    if (!hit) return std::nullopt;
    const vec3 eye = scene.camera.position;
    const SurfacePoint sp = makeSurfacePoint(scene, world, *hit, glm::vec3(0.f));
    const vec3 v = glm::normalize(eye - sp.position);
    const vec3 n = glm::dot(sp.faceNormal, v) < 0.f ? -sp.shadingNormal : sp.shadingNormal;
    return sampleEnvironment(scene.environment, shading::reflectAbout(v, n));
  });
}

// The same with the analytic unit sphere (double-precision ray-sphere hit and normal): adds the
// tessellation error of the mesh's interpolated normals.
Errors againstAnalyticSphere(const Scene& scene, const Frame& f) {
  return measure(f, [&](int x, int y) -> std::optional<vec3> {
    if (!hitsTexel(f.hits, x, y)) return std::nullopt;
    const Ray ray = primaryRay(scene.camera, kSize, kSize, x + 0.5f, y + 0.5f);
    const glm::dvec3 o(ray.origin), d(ray.direction);
    const double b = glm::dot(o, d), c = glm::dot(o, o) - 1.0, disc = b * b - c;
    if (disc <= 0) return std::nullopt;
    const glm::dvec3 n = glm::normalize(o + (-b - std::sqrt(disc)) * d);
    const glm::dvec3 r = glm::reflect(d, n);
    return sampleEnvironment(scene.environment, vec3(r));
  });
}

void report(const char* what, const Errors& e) {
  std::cout << "[ measured ] " << what << ": " << e.pixels << " px, relative error mean " << e.mean
            << ", p99 " << e.p99 << ", max " << e.max << "\n";
}

TEST(EnvMaps, CubeFaceDirectionInvertsCubeFace) {
  for (int f = 0; f < 6; ++f)
    for (float s : {0.05f, 0.3f, 0.5f, 0.93f})
      for (float t : {0.02f, 0.5f, 0.71f}) {
        vec2 st;
        ASSERT_EQ(cubeFace(envmap::cubeFaceDirection(f, vec2(s, t)), st), f);
        EXPECT_NEAR(st.x, s, 1e-6f);
        EXPECT_NEAR(st.y, t, 1e-6f);
      }
}

TEST(EnvMaps, SphereMapCoordInvertsSphereMapDirection) {
  for (float s = 0.05f; s < 1.f; s += 0.1f)
    for (float t = 0.05f; t < 1.f; t += 0.1f) {
      const vec2 p = 2.f * vec2(s, t) - 1.f;
      if (glm::dot(p, p) > 0.98f) continue;  // the rim: every point there is r = -z
      const vec3 r = envmap::sphereMapDirection(vec2(s, t));
      EXPECT_NEAR(glm::length(r), 1.f, 1e-5f);
      const vec2 back = envmap::sphereMapCoord(r);
      EXPECT_NEAR(back.x, s, 1e-5f);
      EXPECT_NEAR(back.y, t, 1e-5f);
    }
  EXPECT_EQ(envmap::sphereMapCoord(vec3(0.f, 0.f, 1.f)), vec2(0.5f));  // straight back: centre
}

TEST_F(EnvFixture, EquirectLookupMatchesTheCpuReference) {
  const Scene scene = equirectScene();
  const Frame f = render(scene, "env_equirect", 512);
  const Errors e = againstSurfaceReference(scene, f);
  report("env_equirect (lat-long 1024x512 as is) vs CPU", e);
  const Errors analytic = againstAnalyticSphere(scene, f);
  report("env_equirect vs analytic sphere", analytic);
  // Tessellation: 384 x 192 segments put vertices 0.94 degrees apart; the interpolated normal and
  // the chord-to-sphere offset of the point tilt r by up to ~1e-3 rad at the worst pixels, and
  // the pattern changes by < 0.5 per radian, so 2e-3 relative bounds the tail.
  EXPECT_LT(analytic.p99, 2e-3);
  EXPECT_GT(e.pixels, kSize * kSize / 3);
  // The same texels and the same bilinear formula as the CPU: what differs is the direction's
  // rounding and llvmpipe's atan/acos. One texel of this lat-long is 2pi/1024 rad, over which
  // the pattern changes by ~2e-3 relative, so 1e-4 relative is a 0.05-texel shift.
  EXPECT_LT(e.mean, 1e-4);
  EXPECT_LT(e.p99, 5e-4);
}

TEST_F(EnvFixture, CubeConvertedFromEquirectMatchesTheCpuReference) {
  const Scene scene = equirectScene();
  const Frame f = render(scene, "env_cube", 256);
  const Errors e = againstSurfaceReference(scene, f);
  report("env_cube (256^2 faces resampled from lat-long) vs CPU", e);
  report("env_cube (resampled) vs analytic sphere", againstAnalyticSphere(scene, f));
  // Two bilinear resamplings of a smooth pattern: error ~ h^2/8 |f''| per resampling, with
  // h = 2/256 on a face and |f''| < 1: ~1e-5 relative; the bound leaves room for face edges,
  // where seamless GL filtering blends two faces and the CPU clamps to one.
  EXPECT_LT(e.mean, 1e-4);
  EXPECT_LT(e.p99, 1e-3);
}

TEST_F(EnvFixture, CubeFromSceneFacesMatchesTheCpuReference) {
  const Scene scene = cubeScene();
  const Frame f = render(scene, "env_cube", 256);
  const Errors e = againstSurfaceReference(scene, f);
  report("env_cube (scene faces 256^2 as is) vs CPU", e);
  // Same texels, same face selection: only face-edge pixels (seamless vs clamped) differ.
  EXPECT_LT(e.mean, 1e-4);
  EXPECT_LT(e.p99, 1e-4);
}

TEST_F(EnvFixture, EquirectConvertedFromCubeFacesMatchesTheCpuReference) {
  const Scene scene = cubeScene();
  const Frame f = render(scene, "env_equirect", 512);
  const Errors e = againstSurfaceReference(scene, f);
  report("env_equirect (1024x512 resampled from cube faces) vs CPU", e);
  // Resampling error (as for the converted cube) plus the direct lookup's atan/acos shift.
  EXPECT_LT(e.mean, 1e-4);
  EXPECT_LT(e.p99, 5e-4);
}

TEST_F(EnvFixture, SphereMapIsCloseExceptNearItsSingularity) {
  const Scene scene = equirectScene();
  const Frame f = render(scene, "env_sphere", 512);
  const Errors e = againstSurfaceReference(scene, f);
  report("env_sphere (512^2, camera frame) vs CPU", e);
  // Looser: a sphere-map texel covers a solid angle that grows without bound toward the rim
  // (ds/d(angle from -z) -> 0 there; all of the rim is the one direction -z), so the bilinear
  // error grows at grazing reflections. With a camera-aligned map those are exactly the
  // silhouette pixels, so they sit in the tail; the bound is 10x the lat-long one.
  EXPECT_LT(e.mean, 1e-3);
  EXPECT_LT(e.p99, 5e-3);
}

TEST_F(EnvFixture, SolidColourIsConstantAndBackgroundIsZero) {
  const Scene scene =
      mirrorScene({{"color", {0.2, 0.4, 0.8}}, {"intensity", 2}}, "solid.json", true);
  for (const char* type : {"env_cube", "env_sphere", "env_equirect"}) {
    const Frame f = render(scene, type, 64);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto hit = hitsTexel(f.hits, x, y);
        const bool mirror = hit && hit->instance == 0;  // instance 1 is the diffuse floor
        const vec3 expected = mirror ? vec3(0.4f, 0.8f, 1.6f) : vec3(0.f);
        for (int k = 0; k < 3; ++k)
          ASSERT_NEAR(f.reflection.f(x, y, k), expected[k], 1e-6f) << type << " " << x << "," << y;
      }
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
