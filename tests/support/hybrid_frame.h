#pragma once
// One frame of a real frame graph (real OSMesa context, real Embree) for integration tests:
// loads a scene file, compiles `recipe` for it at w x h with the requested outputs, runs one
// frame. Everything the executor refers to lives in this object, so keep it behind the
// unique_ptr that renderHybridFrame returns (RenderWorld holds a reference to `scene`).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "engine/gl/context.h"
#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "passes/registry.h"

namespace diptych::testing {

struct HybridFrame {
  // Declaration order is destruction order reversed: the executor and world (which release GL
  // objects with their context current) go before the context, the scene last.
  Scene scene;
  std::unique_ptr<gl::GlContext> context;
  std::unique_ptr<RenderWorld> world;
  CompiledGraph graph;
  std::unique_ptr<GraphExecutor> executor;

  const CpuImage& output(const std::string& name) const { return executor->output(name); }
  const GraphPass* pass(const std::string& name) const {
    for (const GraphPass& p : graph.passes)
      if (p.name == name) return &p;
    return nullptr;
  }
};

inline Camera cameraOf(const Scene& scene) {
  return scene.hasCamera ? scene.camera : frameBounds(scene.bounds());
}

// Compiles `recipe` for `scene` and runs one frame. `outputs` overrides the recipe's outputs when
// not empty.
inline std::unique_ptr<HybridFrame> renderHybridFrame(
    Scene scene, int width, int height, const std::vector<std::string>& outputs,
    const Recipe& recipe = defaultHybridRecipe()) {
  auto f = std::make_unique<HybridFrame>();
  f->scene = std::move(scene);
  const FrameSettings frame{.width = width, .height = height, .camera = cameraOf(f->scene)};
  f->graph = compileGraph(recipe, builtinPasses(), f->scene, frame, outputs);
  if (f->graph.usesGl()) f->context = gl::createContext(gl::ContextKind::Osmesa, width, height);
  f->world = std::make_unique<RenderWorld>(f->scene, f->context.get());
  f->executor = std::make_unique<GraphExecutor>(f->graph, *f->world);
  f->executor->runFrame();
  return f;
}

// The same for a scene file, loaded with loadScene (what `diptych render` does).
inline std::unique_ptr<HybridFrame> renderHybridFrame(
    const std::filesystem::path& file, int width, int height,
    const std::vector<std::string>& outputs, const Recipe& recipe = defaultHybridRecipe()) {
  return renderHybridFrame(loadScene(file), width, height, outputs, recipe);
}

// `recipe` with its G-buffer drawing analytic spheres as triangles in a visibility buffer too
// (parameter impostors false, passes/raster/gbuffer.h): for tests of the rasterized triangles.
inline Recipe withoutImpostors(Recipe recipe) {
  for (RecipePass& p : recipe.passes)
    if (p.type == "gbuffer") p.params["impostors"] = false;
  return recipe;
}

// `recipe` with its shade pass duplicated: shade_gl forced to GL and shade_cpu to the CPU, both
// reading the same resources, so one frame gives both sides the same inputs.
inline Recipe withShadeInBothDomains(Recipe recipe) {
  RecipePass shade;
  for (const RecipePass& p : recipe.passes)
    if (p.type == "shade") shade = p;
  std::erase_if(recipe.passes, [](const RecipePass& p) { return p.type == "shade"; });
  for (const char* domain : {"gl", "cpu"}) {
    RecipePass p = shade;
    p.name = std::string("shade_") + domain;
    p.params["domain"] = domain;
    recipe.passes.push_back(p);
  }
  recipe.outputs = {"shade_gl.color", "shade_cpu.color", "gbuffer.hits"};
  return recipe;
}

// The node of the compiled schedule called `name` ("default:shadows.visibility"), or null.
inline const GraphNode* scheduledNode(const CompiledGraph& graph, const std::string& name) {
  for (const GraphNode& n : graph.nodes)
    if (n.name == name) return &n;
  return nullptr;
}

}  // namespace diptych::testing
