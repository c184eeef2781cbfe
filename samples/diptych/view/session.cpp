#include "samples/diptych/view/session.h"

#include <chrono>
#include <cmath>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/metrics/metrics.h"
#include "engine/metrics/signal_metrics.h"
#include "engine/scene/camera_math.h"
#include "passes/registry.h"
#include "samples/diptych/compare/runner.h"
#include "samples/diptych/compare/variants.h"
#include "samples/diptych/sweep/geometry.h"
#include "samples/diptych/view/camera_control.h"
#include "samples/diptych/view/recipe_json.h"

namespace diptych::view {
namespace {

double msSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

const RecipePass* passNamed(const Recipe& r, const std::string& name) {
  for (const RecipePass& p : r.passes)
    if (p.name == name) return &p;
  return nullptr;
}

std::string gbufferHits(const Recipe& r) {
  for (const RecipePass& p : r.passes)
    if (p.type == "gbuffer") return p.name + "." + kHits;
  return "";
}

// Runs `recipe` once with `outputs` requested and returns copies of them (for the signal
// figures, which need resources the displayed graph does not output).
std::map<std::string, CpuImage> probe(const Recipe& recipe, RenderWorld& world,
                                      const FrameSettings& frame,
                                      const std::vector<std::string>& outputs) {
  return cli::runGraph(recipe, world, frame, outputs, 0, 1).outputs;
}

}  // namespace

nlohmann::json Figures::toJson() const {
  if (!valid) return nullptr;
  nlohmann::json j = {{"rmse", rmse}, {"flip_mean", flipMean}};
  if (referenceSamples > 0) j["reference_samples"] = referenceSamples;
  if (visibility)
    j["visibility"] = {{"acne_rate", acneRate},
                       {"peter_panning_rate", peterPanningRate},
                       {"light_leak_rate", lightLeakRate}};
  return j;
}

Session::Session(Scene& scene, std::string scenePath, gl::GlContext& context, Recipe base,
                 const std::string& reference)
    : scene_(scene),
      scenePath_(std::move(scenePath)),
      world_(scene, &context),
      sceneCamera_(scene.hasCamera ? scene.camera : frameBounds(scene.bounds())),
      camera_(sceneCamera_),
      base_(std::move(base)),
      referenceText_(reference) {
  snapFov(sceneCamera_);  // a glTF camera's radians may have no exact float degrees
  camera_ = sceneCamera_;
  // The hybrid and Whitted references take each pixel's texture colour over its footprint, the
  // texture_filtering slot's exact answer, as compare's do (docs/compare.md): against the pixel
  // centre's lookup the texture filters' error would favour the aliased point sample.
  if (reference == "hybrid") {
    referenceRecipe_ = cli::exactHybridRecipe(cli::kExactTextureSamples);
  } else if (reference.ends_with(".json")) {
    referenceRecipe_ = loadRecipe(reference);
  } else {
    std::string text = reference;
    progressiveReference_ = text == "path" || text.starts_with("path:");
    if (text == "path") text = "path:1";
    cli::ReferenceSpec spec = cli::parseReference(text, builtinPasses());
    spec.textureSamples = cli::kExactTextureSamples;
    referenceRecipe_ = spec.recipe();
    if (progressiveReference_) referenceRecipe_.outputs = {"reference.color"};
  }
  // Both recipes must compile for this scene before a window frame is spent on them.
  const FrameSettings probeFrame{.width = 16, .height = 16, .camera = camera_};
  compileGraph(recipe(), builtinPasses(), scene_, probeFrame);
  compileGraph(referenceRecipe_, builtinPasses(), scene_, probeFrame);
}

void Session::cameraChanged() {
  fitNearFar(camera_, scene_.bounds());
  stale_ = referenceStale_ = true;
}

Recipe Session::recipe() const {
  Recipe r = base_;
  for (const auto& [slot, o] : overrides_) applySlotOverride(r, o, builtinPasses());
  return r;
}

std::optional<Session::SlotState> Session::slotState(const std::string& slot) const {
  const Recipe r = recipe();
  const std::string signal = cli::slotSignal(r, slot);
  if (signal.empty()) return std::nullopt;
  const RecipePass* p = passNamed(r, signal.substr(0, signal.find('.')));
  if (!p) return std::nullopt;
  return SlotState{p->type, p->params};
}

std::optional<std::string> Session::setSlot(const SlotOverride& given) {
  const auto previous = overrides_;
  SlotOverride o = given;
  // --slot text gives every number as a double; integers are stored as integers so that the
  // state and the written recipe read "resolution": 256, not 256.0.
  if (const PassTypeInfo* info = builtinPasses().find(o.type))
    for (const ParamSpec& spec : info->params)
      if (auto it = o.params.find(spec.name);
          it != o.params.end() && spec.type == ParamSpec::Type::Integer && it->is_number_float() &&
          it->get<double>() == std::floor(it->get<double>()))
        *it = static_cast<long long>(it->get<double>());
  try {
    overrides_[o.slot] = o;
    const Recipe r = recipe();  // applySlotOverride checks slot and type
    compileGraph(r, builtinPasses(), scene_, {.width = 16, .height = 16, .camera = camera_});
  } catch (const Error& e) {
    overrides_ = previous;
    return std::string(e.what());
  }
  live_.reset();
  stale_ = true;
  return std::nullopt;
}

std::optional<std::string> Session::setParam(const std::string& slot, const std::string& key,
                                             const nlohmann::json& value) {
  const auto state = slotState(slot);
  if (!state) return "the recipe has no producer for slot '" + slot + "'";
  SlotOverride o{.slot = slot, .type = state->type, .params = state->params};
  o.params[key] = value;
  o.text = slot + "=" + o.type + ":" + key + "=" + value.dump();
  return setSlot(o);
}

void Session::compile(int width, int height) {
  auto live = std::make_unique<LiveGraph>();
  live->graph = compileGraph(recipe(), builtinPasses(), scene_,
                             {.width = width, .height = height, .camera = camera_});
  live->executor = std::make_unique<GraphExecutor>(live->graph, world_);
  live_ = std::move(live);
}

bool Session::render(int width, int height, bool withReference, bool wantFigures) {
  const bool resized =
      !live_ || live_->graph.frame.width != width || live_->graph.frame.height != height;
  if (resized) {
    compile(width, height);
    stale_ = referenceStale_ = true;
  }
  bool changed = false;
  if (stale_) {
    // Passes read the camera in execute(), never in setup() (setups read only the frame size),
    // so a moved camera is a new frame of the same compiled graph.
    live_->graph.frame.camera = camera_;
    const auto start = std::chrono::steady_clock::now();
    if (live_->executor->timings().front().cpuMs.size() >= 32) live_->executor->clearTimings();
    live_->executor->runFrame();
    current_ =
        live_->executor->output(live_->graph.resources[live_->graph.outputs[0]].name).toImage();
    lastFrameMs_ = msSince(start);
    // The first frame's one-time work stays out of the timing panel, as render's --warmup.
    if (++live_->frames == 1) live_->executor->clearTimings();
    stale_ = false;
    measured_ = false;
    figures_ = Figures{};  // they described the previous frame
    errorMap_ = Image();
    changed = true;
  }
  // The path reference refines while the camera rests, up to kMaxReferenceSamples; its figures
  // are recomputed at 1, 2, 4, 8... samples (FLIP on every frame would halve the refinement).
  constexpr int kMaxReferenceSamples = 4096;
  if (withReference &&
      (referenceStale_ || (progressiveReference_ && referenceSamples_ < kMaxReferenceSamples))) {
    renderReference(width, height);
    if ((referenceSamples_ & (referenceSamples_ - 1)) == 0) measured_ = false;
    changed = true;
  }
  if (wantFigures && withReference && !measured_) {
    measure();
    changed = true;
  }
  return changed;
}

void Session::timeFrames(int frames) {
  if (!live_) return;
  live_->executor->clearTimings();
  for (int f = 0; f < frames; ++f) live_->executor->runFrame();
  live_->frames += frames;
}

void Session::renderReference(int width, int height) {
  if (referenceStale_) {
    referenceSamples_ = 0;
    referenceSum_ = Image();
  }
  Recipe r = referenceRecipe_;
  if (progressiveReference_) r.passes[0].params = {{"spp", 1}, {"seed", referenceSamples_}};
  const bool reuse = liveReference_ && !progressiveReference_ &&
                     liveReference_->graph.frame.width == width &&
                     liveReference_->graph.frame.height == height;
  if (!reuse) {
    auto live = std::make_unique<LiveGraph>();
    live->graph = compileGraph(r, builtinPasses(), scene_,
                               {.width = width, .height = height, .camera = camera_});
    live->executor = std::make_unique<GraphExecutor>(live->graph, world_);
    liveReference_ = std::move(live);
  }
  liveReference_->graph.frame.camera = camera_;
  liveReference_->executor->runFrame();
  const Image frame =
      liveReference_->executor
          ->output(liveReference_->graph.resources[liveReference_->graph.outputs[0]].name)
          .toImage();
  if (!progressiveReference_) {
    reference_ = frame;
  } else {  // the running mean of one-sample frames with distinct seeds
    if (referenceSum_.empty()) referenceSum_ = Image(frame.width, frame.height, frame.channels);
    for (std::size_t i = 0; i < frame.pixels.size(); ++i)
      referenceSum_.pixels[i] += frame.pixels[i];
    reference_ = referenceSum_;
    ++referenceSamples_;
    for (float& v : reference_.pixels) v /= float(referenceSamples_);
  }
  referenceStale_ = false;
}

void Session::measure() {
  measured_ = true;
  figures_ = Figures{};
  if (current_.empty() || reference_.width != current_.width ||
      reference_.height != current_.height)
    return;
  MetricOptions options;
  options.metrics = {"rmse", "flip"};
  const auto m = computeMetrics(current_, reference_, options);
  figures_.rmse = m.at("rmse");
  figures_.flipMean = m.at("flip_mean");
  errorMap_ = flipErrorMap(current_, reference_, options);
  figures_.valid = true;
  figures_.referenceSamples = progressiveReference_ ? referenceSamples_ : 0;
  // The visibility slot's artifacts (docs/shadow-bias.md) against the exact producer's signal
  // on the exact hybrid's G-buffer, as `diptych sweep` measures them; light 0.
  const Recipe mine = recipe();
  const auto state = slotState("visibility");
  const TechniqueSlot* slot = findTechniqueSlot("visibility");
  if (!state || !slot || state->type == slot->exact || gbufferHits(mine).empty()) return;
  const FrameSettings frame{.width = current_.width, .height = current_.height, .camera = camera_};
  const Recipe exactRecipe = defaultHybridRecipe();
  const std::string exactSignal = cli::slotSignal(exactRecipe, "visibility");
  const std::string hits = gbufferHits(exactRecipe);
  auto exact = probe(exactRecipe, world_, frame, {hits, exactSignal});
  const std::string signal = cli::slotSignal(mine, "visibility");
  auto approx = probe(mine, world_, frame, {signal});
  const std::vector<float> exactVisibility = cli::layer(exact.at(exactSignal), 0);
  double contactDistance = -1;  // the sweep's default (docs/shadow-bias.md §3)
  const ShadowContacts contacts = world_.scene().lights.empty()
                                      ? ShadowContacts{}
                                      : cli::shadowContacts(world_, exact.at(hits), camera_, 0,
                                                            exactVisibility, contactDistance);
  const ShadowArtifacts a = classifyShadows(
      cli::layer(approx.at(signal), 0), exactVisibility, cli::coverage(exact.at(hits)), frame.width,
      frame.height, {}, 2, 16, contacts.contact.empty() ? nullptr : &contacts);
  figures_.visibility = true;
  figures_.acneRate = a.acneRate();
  figures_.peterPanningRate = a.peterPanningRate();
  figures_.lightLeakRate = a.lightLeakRate();
}

nlohmann::json Session::stateJson() const {
  nlohmann::json slots = nlohmann::json::object();
  for (const TechniqueSlot& s : techniqueSlots())
    if (auto state = slotState(s.name))
      slots[s.name] = {{"type", state->type}, {"params", state->params}};
  nlohmann::json j = {{"scene", scenePath_},
                      {"camera", cameraToJson(camera_, scene_.worldOrigin)},
                      {"recipe", recipeToJson(recipe())},
                      {"slots", slots},
                      {"reference", referenceText_},
                      {"figures", figures_.toJson()}};
  if (progressiveReference_) j["reference_samples"] = referenceSamples_;
  if (live_) j["size"] = {live_->graph.frame.width, live_->graph.frame.height};
  return j;
}

}  // namespace diptych::view
