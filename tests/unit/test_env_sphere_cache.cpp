// env_sphere's map is view-dependent, its GGX-prefiltered levels are not
// (docs/environment-maps.md): the levels are integrated once per environment as world-space cubes,
// and turning the camera only resamples the map. Checked by the pass's per-frame counters
// map_builds and prefilter_builds (counts, not times), over three frames on one RenderWorld: a
// first frame, the same camera again, the camera moved without turning, and the camera turned.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/registry.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

namespace fs = std::filesystem;

Scene roughMetalUnderSky() {
  const nlohmann::json scene = {
      {"camera", {{"position", {0, 0, 3}}, {"target", {0, 0, 0}}, {"fov", 45}}},
      {"environment", {{"sky", {{"width", 64}}}}},
      {"materials", {{"metal", {{"model", "gltf"}, {"metallic", 1}, {"roughness", 0.5}}}}},
      {"objects", {{{"type", "sphere"}, {"radius", 1}, {"material", "metal"}}}}};
  const fs::path path =
      fs::temp_directory_path() / ("diptych_sphere_cache_" + std::to_string(::getpid()) + ".json");
  std::ofstream(path) << scene.dump(1);
  Scene s = loadScene(path);
  fs::remove(path);
  return s;
}

// One frame of gbuffer -> env_sphere -> shade on `world` with `camera`: env's counters, plus
// its CPU time as "cpu_ms" (printed, never asserted).
std::map<std::string, double> envCounters(const Scene& scene, RenderWorld& world,
                                          const Camera& camera) {
  const nlohmann::json recipe = {
      {"passes",
       {{{"name", "gbuffer"}, {"type", "gbuffer"}},
        {{"name", "env"},
         {"type", "env_sphere"},
         {"params", {{"resolution", 64}}},
         {"inputs", {{"hits", "gbuffer.hits"}}}},
        {{"name", "shade"},
         {"type", "shade"},
         {"inputs", {{"hits", "gbuffer.hits"}, {"reflection", "env.reflection"}}}}}},
      {"outputs", {"shade.color"}}};
  const FrameSettings frame{.width = 32, .height = 32, .camera = camera};
  const CompiledGraph graph =
      compileGraph(parseRecipe(recipe, "test"), builtinPasses(), scene, frame);
  GraphExecutor executor(graph, world);
  executor.runFrame();
  for (std::size_t i = 0; i < graph.nodes.size(); ++i)
    if (graph.nodes[i].name == "env") {
      std::map<std::string, double> c = executor.timings()[i].counters;
      c["cpu_ms"] = executor.timings()[i].cpuMs.back();
      return c;
    }
  ADD_FAILURE() << "no env node";
  return {};
}

TEST(EnvSphereCache, PrefiltersOncePerEnvironmentAndRebuildsOnlyWhenTheCameraTurns) {
  const Scene scene = roughMetalUnderSky();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  Camera camera = scene.camera;

  auto first = envCounters(scene, world, camera);
  EXPECT_EQ(first["map_builds"], 1.0);
  EXPECT_EQ(first["prefilter_builds"], 1.0);

  auto same = envCounters(scene, world, camera);
  EXPECT_EQ(same["map_builds"], 0.0) << "same camera: the map is reused";
  EXPECT_EQ(same["prefilter_builds"], 0.0);

  Camera moved = camera;  // translated, same orientation: the eye frame is unchanged
  moved.position += vec3(0.5f, 0.f, 0.f);
  moved.target += vec3(0.5f, 0.f, 0.f);
  auto translated = envCounters(scene, world, moved);
  EXPECT_EQ(translated["map_builds"], 0.0) << "a sphere map depends on the rotation only";
  EXPECT_EQ(translated["prefilter_builds"], 0.0);

  Camera turned = camera;
  turned.target = vec3(0.4f, 0.2f, 0.f);
  auto rotated = envCounters(scene, world, turned);
  EXPECT_EQ(rotated["map_builds"], 1.0) << "the map is resampled for the new eye frame";
  EXPECT_EQ(rotated["prefilter_builds"], 0.0) << "the GGX integration is not repeated";
  std::printf(
      "[ measured ] env_sphere 64^2 pass CPU time: first frame %.1f ms (prefilter %.1f ms), same "
      "camera %.1f ms, turned %.1f ms (loaded machine)\n",
      first["cpu_ms"], first["prefilter_ms"], same["cpu_ms"], rotated["cpu_ms"]);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
