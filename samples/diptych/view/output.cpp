// What the viewer writes: screenshots with their state, the current configuration as a recipe
// and a `diptych compare` variants entry, and cameras in the JSON scene format.
#include <fstream>

#include "engine/core/error.h"
#include "engine/core/timing.h"
#include "engine/gl/context.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "samples/diptych/view/camera_control.h"
#include "samples/diptych/view/recipe_json.h"
#include "samples/diptych/view/viewer.h"

namespace diptych::view {
namespace {

void writeJson(const std::filesystem::path& path, const nlohmann::json& j) {
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out) throw Error(path.string() + ": cannot write file");
}

}  // namespace

// The window's pixels as drawn (frame, wipe and panels): the default framebuffer is blitted
// into a texture, read back bottom-up, flipped and decoded from sRGB so that writeImage's
// encoding gives back the same bytes.
Image Viewer::windowPixels() const {
  const int w = context_.width(), h = context_.height();
  gl::Texture t = gl::Texture::create2D(gl::TextureFormat::RGBA8, w, h);
  gl::Framebuffer fb = gl::Framebuffer::create();
  fb.attachColor(0, t);
  gl::glBlitNamedFramebuffer(0, fb.id(), 0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  std::vector<std::uint8_t> bytes(std::size_t(w) * h * 4);
  gl::glPixelStorei(GL_PACK_ALIGNMENT, 1);
  gl::glGetTextureSubImage(t.id(), 0, 0, 0, 0, w, h, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                           GLsizei(bytes.size()), bytes.data());
  Image image(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        image.at(x, h - 1 - y, c) = srgbToLinear(bytes[(std::size_t(y) * w + x) * 4 + c] / 255.f);
  return image;
}

// NAME.png: the current recipe's frame at its full render size, tone mapped as `diptych render`
// writes a PNG; NAME.window.png: the window as shown; NAME.json: the full state.
void Viewer::screenshot(const std::string& name) {
  const std::filesystem::path base = options_.outDir / name;
  const ToneMap tone{state_.exposure, state_.tone};
  writeImage(base.string() + ".png", session_.current(), tone);
  writeImage(base.string() + ".window.png", windowPixels());
  nlohmann::json j = session_.stateJson();
  j["view"] = {{"split", state_.split},
               {"wipe", state_.wipe},
               {"overlay", state_.overlay == Overlay::Flip  ? "flip"
                           : state_.overlay == Overlay::Abs ? "abs"
                                                            : "none"},
               {"fly", state_.fly},
               {"exposure", state_.exposure},
               {"window", {context_.width(), context_.height()}}};
  j["images"] = {{"frame", name + ".png"}, {"window", name + ".window.png"}};
  if (const LiveGraph* live = session_.live()) {  // the timing panel's numbers
    nlohmann::json nodes = nlohmann::json::object();
    for (std::size_t i = 0; i < live->graph.nodes.size(); ++i) {
      const NodeTiming& t = live->executor->timings()[i];
      if (t.cpuMs.empty()) continue;
      nlohmann::json& node = nodes[live->graph.nodes[i].name];
      node = {{"cpu_ms", summarize(t.cpuMs).median}, {"frames", t.cpuMs.size()}};
      if (!t.gpuMs.empty()) node["gpu_ms"] = summarize(t.gpuMs).median;
      if (!t.glWaitMs.empty()) node["gl_wait_ms"] = summarize(t.glWaitMs).median;
    }
    nlohmann::json culled = nlohmann::json::object();
    for (const GraphPass& p : live->graph.passes)
      if (p.culled) culled[p.name] = p.cullReason;
    j["timings"] = {{"method",
                     "median over the frames since the graph's first (at most 32); CPU "
                     "steady_clock per node, GL_TIME_ELAPSED for GL nodes and transfers"},
                    {"nodes", nodes},
                    {"culled", culled}};
  }
  writeJson(base.string() + ".json", j);
  say("wrote " + base.string() + ".png, .window.png, .json");
}

// NAME.recipe.json (loadRecipe reads it), NAME.camera.json, and NAME.variants.json with one
// entry naming that recipe: `diptych compare SCENE --variants NAME.variants.json`.
void Viewer::writeRecipe(const std::string& name) {
  const std::filesystem::path base = options_.outDir / name;
  nlohmann::json recipe = recipeToJson(session_.recipe());
  recipe["description"] = "written by diptych view from " + session_.scenePath();
  writeJson(base.string() + ".recipe.json", recipe);
  saveCamera(base.string() + ".camera.json");
  writeJson(base.string() + ".variants.json",
            {{"variants", {{{"name", name}, {"recipe", name + ".recipe.json"}}}}});
  say("wrote " + base.string() + ".recipe.json, .camera.json, .variants.json");
}

void Viewer::saveCamera(const std::filesystem::path& file) {
  writeJson(file, {{"camera", cameraToJson(session_.camera(), session_.scene().worldOrigin)}});
  say("saved camera to " + file.string());
}

void Viewer::loadCamera(const std::filesystem::path& file) {
  Camera c = readCameraFile(file, session_.scene().worldOrigin);  // InputError: file and key
  if (c.znear == 0.f) fitNearFar(c, session_.scene().bounds());
  session_.camera() = c;
  session_.cameraChanged();
  say("loaded camera from " + file.string());
}

}  // namespace diptych::view
