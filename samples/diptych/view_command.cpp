#include "samples/diptych/view_command.h"

#include <filesystem>
#include <memory>
#include <optional>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/core/tonemap.h"
#include "engine/gl/context.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "samples/diptych/parse_size.h"
#include "samples/diptych/shading_option.h"
#include "samples/diptych/view/script.h"
#include "samples/diptych/view/session.h"
#include "samples/diptych/view/viewer.h"

namespace diptych::cli {
namespace {

struct ViewOptions {
  std::string scene, recipe, reference = "hybrid", size = "960x600", script, camera, out = ".";
  std::vector<std::string> slots;
  float exposure = 0.f;
  std::string tonemap = "clamp";
  std::string shading;  // --shading lecture|gltf (empty: each material its own)
  LightingOptions lighting;
  bool verbose = false;
};

void runView(const ViewOptions& o) {
  if (o.verbose) setLogLevel(spdlog::level::debug);
  // Every input is read and checked before a window opens, so a bad one is one error line.
  const auto [width, height] = parseSize(o.size, 8192);
  const auto tone = parseToneOperator(o.tonemap);
  if (!tone) throw InputError("--tonemap", "", "expected clamp, reinhard or aces");
  if (!std::filesystem::is_directory(o.out))
    throw InputError("--out", "", o.out + ": folder does not exist");
  checkShadingOption(o.shading);
  view::ViewerOptions viewer{.outDir = o.out, .scriptPath = o.script};
  if (!o.script.empty()) viewer.script = view::loadScript(o.script);
  Scene scene = loadScene(o.scene);
  for (const std::string& w : scene.warnings) log().warn("{}", w);
  const Camera camera = scene.hasCamera ? scene.camera : frameBounds(scene.bounds());
  if (auto line = applyLighting(scene, camera, o.lighting)) log().warn("{}", *line);
  if (auto hint = darkEnvironmentHint(scene)) log().warn("{}", *hint);
  applyShadingOption(scene, o.shading);  // as render does: after the default lighting
  Recipe recipe = o.recipe.empty() ? defaultHybridRecipe() : loadRecipe(o.recipe);
  for (const std::string& text : o.slots)
    applySlotOverride(recipe, parseSlotOverride(text), builtinPasses());
  for (const view::ScriptCommand& c : viewer.script)  // a producer that does not exist
    if (c.verb == "slot") try {
        Recipe copy = recipe;
        applySlotOverride(copy, parseSlotOverride(c.args[0]), builtinPasses());
      } catch (const InputError& e) {
        throw InputError(o.script, "line " + std::to_string(c.line), e.message());
      }
  std::optional<Camera> start;
  if (!o.camera.empty()) {
    start = readCameraFile(o.camera, scene.worldOrigin);
    if (start->znear == 0.f) fitNearFar(*start, scene.bounds());
  }

  auto context = gl::createContext(gl::ContextKind::Glfw, width, height, /*visible=*/true);
  view::Session session(scene, o.scene, *context, std::move(recipe), o.reference);
  if (start) {
    session.camera() = *start;
    session.cameraChanged();
  }
  view::ViewState state{.exposure = o.exposure, .tone = *tone};
  view::Viewer(session, *context, std::move(viewer), state).run();
}

}  // namespace

void addViewCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view",
      "Interactive viewer: a window over the frame graph, with slots, split view, "
      "error heat maps and timings (docs/viewer.md)");
  cmd->add_option("scene", options->scene, "Scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("--recipe", options->recipe, "Frame-graph recipe (JSON); default: hybrid");
  cmd->add_option("--slot", options->slots, "Override a technique slot: SLOT=TYPE[:key=value,...]");
  cmd->add_option("--reference", options->reference,
                  "Right side of the split view: hybrid (every slot exact), whitted, "
                  "distributed:SPP, path (accumulates while the camera rests) or a recipe file")
      ->capture_default_str();
  cmd->add_option("--size", options->size, "Window size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--camera", options->camera, "Start from the \"camera\" of this JSON file");
  cmd->add_option("--script", options->script,
                  "Run these commands, one per frame (docs/viewer.md, \"Script\")");
  cmd->add_option("--out", options->out, "Folder for screenshots, recipes and cameras")
      ->capture_default_str();
  cmd->add_option("--exposure", options->exposure, "Display exposure in stops")
      ->capture_default_str();
  cmd->add_option("--tonemap", options->tonemap, "clamp, reinhard or aces")->capture_default_str();
  cmd->add_option("--env", options->lighting.environmentFile, "Equirect environment image");
  cmd->add_option("--light", options->lighting.lightJson, "Add a light (JSON, as in a scene)");
  addShadingOption(cmd, options->shading);
  cmd->add_flag("-v,--verbose", options->verbose, "Log debug messages");
  cmd->callback([options, &exitCode] {
    runView(*options);
    exitCode = 0;
  });
}

}  // namespace diptych::cli
