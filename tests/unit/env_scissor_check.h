#pragma once
// Runs gbuffer -> one env_* producer and checks its scissor against the G-buffer: every pixel
// whose material may reflect gets a non-zero reflection, every other pixel 0, and each such
// pixel lies inside its own mesh's window rectangle (screen_rect.h, as the producers compute it).
// Shared by tests/unit/test_env_scissor.cpp and tests/shared_scenes/test_env_scissor_gltf.cpp.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/shading/shading.h"
#include "passes/raster/screen_rect.h"
#include "passes/registry.h"
#include "tests/unit/gl_test_context.h"

namespace diptych::testing {

struct EnvScissorRun {
  int reflective = 0;  // pixels showing a material that may reflect
  std::map<std::string, double> counters;
  CpuImage reflection;
};

// `lobe`: which materials count as reflective (shading::materialHasReflection), as the producer
// decides it (env_*: prefiltered levels present).
inline EnvScissorRun checkEnvScissor(const Scene& scene, const Camera& camera,
                                     const std::string& type, bool lobe, int w = 160, int h = 120,
                                     const nlohmann::json& params = nlohmann::json::object()) {
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "env",
                    .type = type,
                    .params = params,
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"}};
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, FrameSettings{w, h, camera},
                   {"env.reflection", "gbuffer.hits"});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor ex(graph, world);
  ex.runFrame();
  EnvScissorRun run{.reflection = ex.output("env.reflection")};
  const CpuImage& hits = ex.output("gbuffer.hits");
  std::map<int, int> meshOf;  // instance -> mesh index, for meshes whose material may reflect
  const std::vector<WorldMesh>& meshes = world.geometry().meshes;
  for (std::size_t m = 0; m < meshes.size(); ++m)
    if (shading::materialHasReflection(scene.material(meshes[m].material), lobe))
      meshOf[meshes[m].instance] = int(m);
  const mat4 viewProj = reversedZProjection(camera, float(w) / float(h)) * viewMatrix(camera);
  const std::vector<Aabb>& bounds = meshBounds(world);
  int wrong = 0;  // pixels failing a check: the first is reported, not thousands
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::uint32_t id = hits.u(x, y, 0);
      const auto it = id != 0 ? meshOf.find(int(id) - 1) : meshOf.end();
      const float sum =
          run.reflection.f(x, y, 0) + run.reflection.f(x, y, 1) + run.reflection.f(x, y, 2);
      if (it == meshOf.end()) {
        if (sum != 0.f && wrong++ == 0)
          ADD_FAILURE() << type << ": non-reflective pixel (" << x << ", " << y << ") is " << sum;
        continue;
      }
      ++run.reflective;
      if (!(sum > 0.f) && wrong++ == 0)
        ADD_FAILURE() << type << ": reflective pixel (" << x << ", " << y << ") left out";
      // CpuImage rows run top down (transfer.h), window coordinates bottom up.
      const PixelRect r = windowRect(bounds[std::size_t(it->second)], viewProj, w, h);
      const int yw = h - 1 - y;
      if (!(x >= r.lo.x && x < r.hi.x && yw >= r.lo.y && yw < r.hi.y) && wrong++ == 0)
        ADD_FAILURE() << type << ": pixel (" << x << ", " << y << ") outside its mesh's rectangle";
    }
  EXPECT_EQ(wrong, 0) << type;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n)
    if (graph.nodes[n].name == "env") run.counters = ex.timings()[n].counters;
  return run;
}

// The world bounds of mesh `m` of `scene`, without a GL context.
inline Aabb meshBox(const Scene& scene, std::size_t m) {
  const WorldGeometry geometry = flattenScene(scene);  // kept: the loop reads its positions
  Aabb box;
  for (const vec3& p : geometry.meshes[m].positions) box.extend(p);
  return box;
}

}  // namespace diptych::testing
