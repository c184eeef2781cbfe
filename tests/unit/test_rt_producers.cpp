// The exact producers of issue #3 through the real tracer and graph: refraction through a slab,
// soft shadows of area lights, and scene-driven culling of the slots on the samples.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <list>
#include <memory>

#include "engine/gl/context.h"
#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/whitted.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

std::filesystem::path writeScene(const std::string& name, const std::string& json) {
  const auto dir = ::diptych::testing::scratchDir("diptych_rt_producers");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << json;
  return dir / name;
}

// A glass slab of thickness 1 (y in [0,1]), n = 1.5, wide enough that nothing leaves its sides.
const char* kSlab = R"({
  "materials": {"glass": {"color": [0,0,0], "kd": 0, "kt": 1, "ior": 1.5}},
  "objects": [{"type": "box", "size": [200, 1, 200], "material": "glass",
               "transform": {"translate": [0, 0.5, 0]}}]
})";

TEST(RtTransmission, SlabAt45DegreesExitsParallelShiftedByTheAnalyticDistance) {
  const Scene scene = loadScene(writeScene("slab.json", kSlab));
  RenderWorld world(scene);
  WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {.maxDepth = 3, .areaSamples = 1});
  std::vector<RayTreeEvent> tree;
  tracer.setRayObserver([&](const RayTreeEvent& e) { tree.push_back(e); });
  const vec3 d1 = glm::normalize(vec3(1, -1, 0));
  const vec3 o1(-5.f, 6.f, 0.3f);
  tracer.radiance({o1, d1}, 1, 0);
  // depth 1: the camera ray hits the top; depth 2: inside, hits the bottom; depth 3: leaves.
  ASSERT_EQ(tree.size(), 3u);
  ASSERT_TRUE(tree[0].hit && tree[1].hit);
  EXPECT_FALSE(tree[2].hit);
  const vec3 d3 = tree[2].ray.direction, o3 = tree[2].ray.origin;
  EXPECT_NEAR(glm::length(d3 - d1), 0.f, 1e-6f) << "the exit ray must be parallel to the entry ray";
  // Lateral shift: distance of the exit line from the entry line,
  // d = t sin(theta_i - theta_t) / cos(theta_t) = 0.329142 for t = 1, 45 degrees, n = 1.5.
  const float shift = glm::length(glm::cross(o3 - o1, d1));
  EXPECT_NEAR(shift, 0.329142f, 1e-4f);
  // Inside the slab the ray follows Snell: sin(theta_t) = sin(45 deg) / 1.5.
  const vec3 d2 = tree[1].ray.direction;
  EXPECT_NEAR(std::sqrt(d2.x * d2.x + d2.z * d2.z), std::sin(glm::radians(45.f)) / 1.5f, 1e-6f);
}

TEST(RtTransmission, BeyondTheCriticalAngleTheRayIsReflectedInsideWithoutNaN) {
  const Scene scene = loadScene(writeScene("slab.json", kSlab));
  RenderWorld world(scene);
  WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {.maxDepth = 3, .areaSamples = 1});
  std::vector<RayTreeEvent> tree;
  tracer.setRayObserver([&](const RayTreeEvent& e) { tree.push_back(e); });
  // Start inside the glass, heading for the top face at 60 degrees (> 41.81, the critical angle).
  const vec3 d =
      glm::normalize(vec3(std::sin(glm::radians(60.f)), std::cos(glm::radians(60.f)), 0.f));
  const vec3 L = tracer.radiance({vec3(0.f, 0.5f, 0.f), d}, 1, 0);
  EXPECT_TRUE(std::isfinite(L.x) && std::isfinite(L.y) && std::isfinite(L.z));
  ASSERT_GE(tree.size(), 2u);
  EXPECT_LT(tree[1].ray.direction.y, 0.f) << "total internal reflection turns the ray back down";
  EXPECT_NEAR(tree[1].ray.direction.x, d.x, 1e-6f);
}

// A plane and a sphere under a 2 x 2 quad light at y = 10: `edgeV` (0, 0, 2) faces it down,
// (0, 0, -2) up (cross(edge_u, edge_v)). The hybrid's shadows node, run once.
struct QuadLitFrame {
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<RenderWorld> world;
  std::unique_ptr<GraphExecutor> executor;
  CompiledGraph graph;
  double shadowRays = -1.0, receivers = -1.0;
};
std::unique_ptr<QuadLitFrame> renderQuadLit(const std::string& name, const std::string& edgeV,
                                            int w, int h) {
  static std::list<Scene> scenes;  // a world refers to its scene: kept, unmoved, for the process
  scenes.push_back(loadScene(writeScene(name, R"({
    "camera": {"position": [0, 9, 9], "target": [0, 0, 0], "fov": 50},
    "materials": {"white": {"color": [0.8, 0.8, 0.8]}},
    "lights": [{"type": "quad", "position": [0, 10, 0], "edge_u": [2, 0, 0], "edge_v": )" +
                                                  edgeV + R"(, "intensity": 50}],
    "objects": [{"type": "plane", "size": [30, 30], "material": "white"},
                {"type": "sphere", "radius": 1, "segments": 64, "material": "white",
                 "transform": {"translate": [0, 2, 0]}}]
  })")));
  const Scene& scene = scenes.back();
  auto f = std::make_unique<QuadLitFrame>();
  FrameSettings frame{w, h, scene.camera};
  f->graph = compileGraph(defaultHybridRecipe(), builtinPasses(), scene, frame,
                          {"shadows.visibility", "gbuffer.hits"});
  f->context = gl::createContext(gl::ContextKind::Osmesa, w, h);
  f->world = std::make_unique<RenderWorld>(scene, f->context.get());
  f->executor = std::make_unique<GraphExecutor>(f->graph, *f->world);
  f->executor->runFrame();
  for (std::size_t i = 0; i < f->graph.nodes.size(); ++i) {
    const GraphNode& node = f->graph.nodes[i];
    if (node.kind != NodeKind::Pass || f->graph.passes[node.pass].type != "rt_shadows") continue;
    f->shadowRays = f->executor->timings()[i].counters.at("rays");
    f->receivers = f->executor->timings()[i].counters.at("receivers");
  }
  return f;
}

TEST(RtShadows, QuadAreaLightCastsUmbraPenumbraAndLitRegions) {
  const int w = 128, h = 128;
  const auto f = renderQuadLit("area.json", "[0, 0, 2]", w, h);
  ASSERT_EQ(f->world->scene().lights[0].type, LightType::QuadArea);
  const CpuImage& vis = f->executor->output("shadows.visibility");
  const CpuImage& gbuffer = f->executor->output("gbuffer.hits");
  int umbra = 0, penumbra = 0, lit = 0, plane = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = vis.f(x, y, 0);
      ASSERT_TRUE(v >= 0.f && v <= 1.f);
      if (gbuffer.u(x, y, 0) != 1u) continue;  // plane pixels only (instance 0)
      ++plane;
      umbra += v == 0.f;
      lit += v == 1.f;
      penumbra += v > 0.f && v < 1.f;
    }
  // Under the sphere the whole light is hidden (umbra), far away all of it is seen, and a ring
  // in between sees part of it: the penumbra only an area light produces. The light faces down
  // (cross(edge_u, edge_v) = -y): facing up it would send the plane nothing, and rt_shadows
  // traces no ray where a light sends nothing (next test).
  EXPECT_GT(umbra, 20);
  EXPECT_GT(penumbra, 50) << "an area light must give fractional visibility in a penumbra";
  EXPECT_GT(lit, plane / 2);
}

// As the Whitted reference (WhittedTracer::lightTerm), rt_shadows traces no ray toward a light
// that sends a point nothing (lightReaches): the same quad facing up lights nothing below it, so
// every pixel reads 1 and costs no ray. Facing down, every covered pixel gets its 16 stratified
// rays.
TEST(RtShadows, NoRaysTowardALightThatSendsThePointNothing) {
  const int w = 96, h = 96;
  const auto down = renderQuadLit("area-down.json", "[0, 0, 2]", w, h);
  const auto up = renderQuadLit("area-up.json", "[0, 0, -2]", w, h);
  ASSERT_GT(down->receivers, 1000.0);
  EXPECT_EQ(down->shadowRays, down->receivers * 16.0) << "every covered pixel is lit from below";
  EXPECT_EQ(up->receivers, down->receivers);
  const CpuImage& vis = up->executor->output("shadows.visibility");
  const CpuImage& gbuffer = up->executor->output("gbuffer.hits");
  int plane = 0, sphere = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint32_t id = gbuffer.u(x, y, 0);
      if (id == 1u) {
        ++plane;
        EXPECT_EQ(vis.f(x, y, 0), 1.f) << "plane pixel " << x << "," << y << " is not lit";
      }
      sphere += id == 2u;
    }
  ASSERT_GT(plane, 1000);
  ASSERT_GT(sphere, 100);
  EXPECT_EQ(up->shadowRays, 0.0) << "the light sends nothing to anything below it";
}

TEST(SceneDrivenCulling, SamplesCullExactlyTheSlotsTheyDoNotNeed) {
  const auto samples = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes";
  auto culled = [&](const char* file) {
    const Scene scene = loadScene(samples / file);
    const CompiledGraph g =
        compileGraph(defaultHybridRecipe(), builtinPasses(), scene, {64, 48, scene.camera});
    std::map<std::string, std::string> out;
    for (const GraphPass& p : g.passes)
      if (p.culled) out[p.name] = p.cullReason;
    return out;
  };
  const auto whitted = culled("whitted.json");  // a procedural checker is no colour texture
  EXPECT_EQ(whitted.size(), 1u);
  EXPECT_EQ(whitted.at("texture_filtering"), "scene has no colour-textured materials");
  const auto textures = culled("textures.json");
  EXPECT_EQ(textures.size(), 1u);
  EXPECT_EQ(textures.at("transmission"), "scene has no transmissive materials");
  const auto shadowSphere = culled("shadow-sphere.json");
  EXPECT_EQ(shadowSphere.at("reflection"), "scene has no reflective materials");
  EXPECT_EQ(shadowSphere.at("transmission"), "scene has no transmissive materials");
  EXPECT_EQ(shadowSphere.count("shadows"), 0u);
}
}  // namespace DIPTYCH_UNITY_ID
