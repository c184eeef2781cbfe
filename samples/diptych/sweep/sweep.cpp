#include "samples/diptych/sweep/sweep.h"

#include "samples/diptych/sweep/geometry.h"

#include "samples/diptych/shading_option.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <tuple>

#include "engine/core/error.h"
#include "engine/core/image.h"
#include "engine/core/output_file.h"
#include "engine/gl/context.h"
#include "engine/metrics/signal_metrics.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "passes/slots.h"
#include "samples/diptych/compare/runner.h"
#include "samples/diptych/compare/variants.h"
#include "samples/diptych/parse_size.h"

namespace diptych::cli {
namespace {

bool isStateKey(const std::string& k) {
  return std::find(lightKeys().begin(), lightKeys().end(), k) != lightKeys().end() ||
         std::find(viewKeys().begin(), viewKeys().end(), k) != viewKeys().end();
}

// The point's scene-state part (light and view keys: state = true) or its pass part.
nlohmann::json splitPoint(const nlohmann::json& point, bool state) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [k, v] : point.items())
    if (isStateKey(k) == state) out[k] = v;
  return out;
}

// The frame of a point: --size and the scene's camera, changed by its view keys. The camera
// orbits its target about the world y axis by camera_azimuth degrees and moves along its line
// of sight to camera_distance times its distance.
FrameSettings frameAt(const FrameSettings& base, const nlohmann::json& point) {
  FrameSettings f = base;
  if (point.contains("size"))
    std::tie(f.width, f.height) = parseSize(point["size"].get<std::string>(), kMaxSweepSide);
  Camera& c = f.camera;
  glm::dvec3 offset = glm::dvec3(c.position) - glm::dvec3(c.target);
  if (point.contains("camera_azimuth")) {
    const double a = point["camera_azimuth"].get<double>() * kRadiansPerDegree;
    offset = glm::dvec3(std::cos(a) * offset.x + std::sin(a) * offset.z, offset.y,
                        -std::sin(a) * offset.x + std::cos(a) * offset.z);
  }
  offset *= point.value("camera_distance", 1.0);
  c.position = vec3(glm::dvec3(c.target) + offset);
  if (point.contains("camera_distance")) {  // keep the geometry between the clip planes
    const double k = point["camera_distance"].get<double>();
    c.znear = float(c.znear * std::min(k, 1.0));
    c.zfar = float(c.zfar * std::max(k, 1.0));
  }
  return f;
}

Recipe pointRecipe(const SlotOverride& base, const nlohmann::json& params) {
  Recipe recipe = defaultHybridRecipe();
  SlotOverride o = base;
  o.params.update(params);
  applySlotOverride(recipe, o, builtinPasses());
  return recipe;
}

std::string sweepCsv(const nlohmann::json& results) {
  std::vector<std::string> keys, signal;
  for (const auto& a : results["spec"]["axes"]) keys.push_back(a["key"]);
  for (const auto& p : results["points"])
    for (const auto& [k, _] : p["signal"].items())
      if (std::find(signal.begin(), signal.end(), k) == signal.end()) signal.push_back(k);
  std::string csv = "index";
  for (const auto& k : keys) csv += "," + k;
  csv += ",producer_ms,total_ms,one_time_ms,texel_world,incidence_deg";
  for (const auto& k : signal) csv += "," + k;
  csv += "\n";
  for (const auto& p : results["points"]) {
    csv += std::to_string(p["index"].get<int>());
    for (const auto& k : keys) {
      const auto& v = p["params"][k];
      csv += "," + (v.is_string() ? v.get<std::string>() : v.dump());
    }
    csv += fmt::format(",{},{},{},{},{}", p["producer_ms"].dump(), p["total_ms"].dump(),
                       p.value("one_time_total_ms", nlohmann::json(0.0)).dump(),
                       p["geometry"]["texel_world"].dump(), p["geometry"]["incidence_deg"].dump());
    for (const auto& k : signal)
      csv += "," + (p["signal"].contains(k) ? p["signal"][k].dump() : "");
    csv += "\n";
  }
  return csv;
}

}  // namespace

// The scene with the swept light turned to (elevation, azimuth): elevation above the xz plane,
// azimuth from +x toward +z; the light travels toward the scene.
Scene sceneAt(const Scene& base, const nlohmann::json& point, int light) {
  Scene s = base;
  if (!point.contains("elevation") && !point.contains("azimuth")) return s;
  Light& l = s.lights[light];
  const vec3 toLight = -glm::normalize(l.direction);
  double elevation = std::asin(std::clamp(double(toLight.y), -1.0, 1.0)) / kRadiansPerDegree;
  double azimuth = std::atan2(double(toLight.z), double(toLight.x)) / kRadiansPerDegree;
  elevation = point.value("elevation", elevation);
  azimuth = point.value("azimuth", azimuth);
  const double e = elevation * kRadiansPerDegree, a = azimuth * kRadiansPerDegree;
  l.direction =
      -vec3(float(std::cos(e) * std::cos(a)), float(std::sin(e)), float(std::cos(e) * std::sin(a)));
  return s;
}

nlohmann::json runSweep(const SweepOptions& o) {
  const PassRegistry& registry = builtinPasses();
  if (o.axes.empty()) throw InputError("--vary", "", "nothing to sweep: give at least one --vary");
  if (o.frames < 1 || o.warmup < 0)
    throw InputError("--frames", "", "need at least one measured frame");
  // The classification's band filters cost (2 band + 1) per pixel: bounded by the image.
  if (o.band < 0 || o.band > o.width + o.height)
    throw InputError("--band", std::to_string(o.band), "must be in 0..width + height");
  if (o.reach < 0 || o.reach > o.width + o.height)
    throw InputError("--reach", std::to_string(o.reach), "must be in 0..width + height");
  if (!std::isfinite(o.contact))
    throw InputError("--contact", std::to_string(o.contact), "must be a finite world distance");
  const SlotOverride base = parseSlotOverride(o.producer);
  const std::vector<nlohmann::json> points = cartesianProduct(o.axes);
  checkShadingOption(o.shading);
  Scene scene = loadScene(o.scene);
  applyShadingOption(scene, o.shading);
  const FrameSettings baseFrame{o.width, o.height,
                                scene.hasCamera ? scene.camera : frameBounds(scene.bounds())};

  // Every check before any rendering: the light, the receiver, and each point's recipe compiled
  // (the producer's own parameter checks reject unknown keys and bad values).
  if (o.light < 0 || (o.light >= int(scene.lights.size()) && !scene.lights.empty()))
    throw InputError("--light", std::to_string(o.light), "the scene has no such light");
  auto sweepsLight = [](const SweepAxis& a) { return a.kind == AxisKind::Light; };
  if (std::any_of(o.axes.begin(), o.axes.end(), sweepsLight)) {
    const auto& axis = *std::find_if(o.axes.begin(), o.axes.end(), sweepsLight);
    if (o.light < 0 || o.light >= int(scene.lights.size()))
      throw InputError("--light", std::to_string(o.light), "the scene has no such light");
    if (scene.lights[o.light].type != LightType::Directional)
      throw InputError("--vary-light", axis.text,
                       "light " + std::to_string(o.light) + " '" + scene.lights[o.light].name +
                           "' is not directional: elevation and azimuth turn a directional light");
  }
  std::vector<int> receivers;
  if (!o.receiver.empty()) {
    std::string known;
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
      if (scene.instances[i].name == o.receiver) receivers.push_back(int(i));
      known += (known.empty() ? "" : ", ") + scene.instances[i].name;
    }
    if (receivers.empty())
      throw InputError("--receiver", o.receiver, "no object of that name (objects: " + known + ")");
  }
  std::string signal;
  for (const nlohmann::json& point : points) {
    const Recipe recipe = pointRecipe(base, splitPoint(point, false));
    signal = slotSignal(recipe, base.slot);
    try {
      compileGraph(recipe, registry, sceneAt(scene, point, o.light), frameAt(baseFrame, point),
                   {signal});
    } catch (const InputError& e) {
      // e.place() names the key ("passes[1].params.kernel"), e.message() what is wrong with it.
      throw InputError("--vary", point.dump(),
                       (e.place().empty() ? "" : e.place() + ": ") + e.message());
    }
  }

  nlohmann::json spec = {{"scene", o.scene},
                         {"producer", o.producer},
                         {"size", {o.width, o.height}},
                         {"frames", o.frames},
                         {"warmup", o.warmup},
                         {"light", o.light},
                         {"band_px", o.band},
                         {"reach_px", o.reach},
                         {"contact_world", o.contact},
                         {"receiver", o.receiver},
                         {"axes", nlohmann::json::array()}};
  for (const SweepAxis& a : o.axes)
    spec["axes"].push_back({{"key", a.key}, {"text", a.text}, {"option", axisOption(a.kind)}});
  nlohmann::json results = {
      {"spec", spec},
      {"method",
       fmt::format("each point: the producer beside the exact producer of slot '{}' on the same "
                   "G-buffer ({}x{} unless the point sets size); times: median CPU ms of {} "
                   "frames after {} warm-up frames",
                   base.slot, o.width, o.height, o.frames, o.warmup)},
      {"points", nlohmann::json::array()}};
  const auto resultsFile = o.out / "results.json";
  std::map<std::string, nlohmann::json> done;
  if (std::filesystem::exists(resultsFile)) {
    nlohmann::json old;
    try {
      old = nlohmann::json::parse(std::ifstream(resultsFile));
    } catch (const nlohmann::json::exception& e) {
      throw InputError(resultsFile.string(), "", std::string("cannot resume: ") + e.what());
    }
    if (!old.contains("spec") || old["spec"] != spec)
      throw InputError(resultsFile.string(), "spec",
                       "belongs to a different sweep (scene, producer, axes or settings differ): "
                       "use another --out or remove it");
    for (const auto& p : old["points"]) done[p["params"].dump()] = p;
  }
  std::filesystem::create_directories(o.out / "classes");
  const OutputFolderLock lock(o.out);  // resuming runs must not interleave their writes

  // Passes render into their own framebuffers: the context's size does not bound the frame.
  auto context = gl::createContext(gl::ContextKind::Osmesa, o.width, o.height);
  std::unique_ptr<StateReference> state;
  std::string stateKey;
  int resumed = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const nlohmann::json& point = points[i];
    const std::string key = point.dump();
    if (auto it = done.find(key); it != done.end()) {
      results["points"].push_back(it->second);
      ++resumed;
      continue;
    }
    const nlohmann::json statePart = splitPoint(point, true), passPart = splitPoint(point, false);
    const FrameSettings frame = frameAt(baseFrame, point);
    const int width = frame.width, height = frame.height;
    if (!state || statePart.dump() != stateKey) {  // a new scene state: its exact reference
      progress(o.label, int(i), int(points.size()), "exact reference " + statePart.dump());
      state.reset();
      state = std::make_unique<StateReference>();
      state->scene = std::make_unique<Scene>(sceneAt(scene, point, o.light));
      state->world = std::make_unique<RenderWorld>(*state->scene, context.get());
      // The texture_filtering slot's exact answer is the footprint's mean, not the built-in
      // recipe's pixel-centre lookup (against which point sampling would look best).
      const Recipe exactRecipe = exactHybridRecipe(kExactTextureSamples);
      state->exactSignal = slotSignal(exactRecipe, base.slot);
      state->exact =
          runGraph(exactRecipe, *state->world, frame, {"gbuffer.hits", state->exactSignal}, 0, 1);
      state->mask = coverage(state->exact.outputs.at("gbuffer.hits"));
      if (!receivers.empty()) {
        const CpuImage& gb = state->exact.outputs.at("gbuffer.hits");
        for (int y = 0; y < height; ++y)
          for (int x = 0; x < width; ++x) {
            auto& m = state->mask[std::size_t(y) * width + x];
            m = m && std::count(receivers.begin(), receivers.end(), int(gb.u(x, y, 0)) - 1);
          }
      }
      measureGeometry(*state, frame, o.light, o.contact, base.slot == "visibility");
      if (!state->contacts.contact.empty()) {  // the contacts of this state, for the docs/report
        state->contactFile = fmt::format("classes/contacts-p{:04d}.png", i);
        writeImage(o.out / state->contactFile, contactImage(*state, width, height));
      }
      stateKey = statePart.dump();
    }
    const Recipe recipe = pointRecipe(base, passPart);
    const GraphRun run = runGraph(recipe, *state->world, frame, {signal}, o.warmup, o.frames);
    const std::string node = signal.substr(0, signal.find('.'));
    // What this point built once (a static shadow map at this point's resolution, ...): outside
    // the frame medians (runMeasured), so a resolution sweep shows the cost of resolution here.
    const nlohmann::json oneTime = run.oneTimeMs;
    double oneTimeTotal = 0;
    for (const auto& [what, ms] : run.oneTimeMs) oneTimeTotal += ms;
    nlohmann::json row = {{"index", int(i)},
                          {"params", point},
                          {"producer_ms", run.passMs.value(node, 0.0)},
                          {"total_ms", run.totalMs},
                          {"one_time_ms", oneTime},
                          {"one_time_total_ms", oneTimeTotal},
                          {"pass_ms", run.passMs}};
    const CpuImage& mine = run.outputs.at(signal);
    const CpuImage& exact = state->exact.outputs.at(state->exactSignal);
    nlohmann::json measured = nlohmann::json::object();
    if (base.slot == "visibility") {
      const int l = std::min(o.light, mine.desc.layers - 1);
      const ShadowArtifacts a = classifyShadows(
          layer(mine, l), layer(exact, l), state->mask, width, height, state->footprint, o.band,
          o.reach, state->contacts.contact.empty() ? nullptr : &state->contacts);
      measured = {{"acne_rate", a.acneRate()},
                  {"peter_panning_rate", a.peterPanningRate()},
                  {"light_leak_rate", a.lightLeakRate()},
                  {"misclassified", a.misclassified()},
                  {"mean_abs_error", a.meanAbsError},
                  {"displacement_px", a.displacementPx},
                  {"displacement_world", a.displacementWorld},
                  {"acne", a.acne},
                  {"peter_panning", a.peterPanning},
                  {"light_leak", a.lightLeak},
                  {"boundary_errors", a.boundaryErrors},
                  {"lit_outside", a.litOutside},
                  {"shadow_outside", a.shadowOutside},
                  {"contact_pixels", a.contacts}};
      const std::string classFile = fmt::format("classes/p{:04d}.png", i);
      writeImage(o.out / classFile, shadowClassImage(a, width, height));
      row["files"] = {{"classes", classFile}};
      if (!state->contactFile.empty()) row["files"]["contacts"] = state->contactFile;
    } else {
      const SignalError e = compareRadiance(mine.toImage(), exact.toImage(), state->mask);
      measured = {{"pixels", e.pixels}, {"rmse", e.rmse}, {"relative_rmse", e.relativeRmse}};
    }
    row["signal"] = measured;
    // The receivers' geometry for the analytic predictions (docs/shadow-bias.md §4); the acne
    // rate is predicted for constant bias (and none, b = 0) only.
    nlohmann::json params = base.params;
    params.update(passPart);
    const std::string mode = params.value("bias", std::string());
    const double bias = mode == "none" ? 0.0
                        : mode == "constant" && params.contains("constant_bias")
                            ? params["constant_bias"].get<double>()
                            : -1.0;
    const TexelPrediction t = predictTexel(*state, params.value("resolution", 2048), o.light, bias);
    std::vector<double> footprints = state->receiverFootprints;
    row["geometry"] = {{"texel_world", t.texelWorld},
                       {"incidence_deg", t.incidenceDeg},
                       {"pixel_world", upperMedian(std::move(footprints))},
                       {"contact_world", state->contactDistance},
                       {"unreached_pixels", state->unreachedPixels}};
    if (t.acneRate >= 0) row["geometry"]["predicted_acne_rate"] = t.acneRate;
    results["points"].push_back(row);
    writeTextFile(resultsFile, results.dump(1));
    writeTextFile(o.out / "results.csv", sweepCsv(results));
    progress(o.label, int(i) + 1, int(points.size()), passPart.dump() + " " + statePart.dump());
  }
  // A completed resume rewrites the files in point order.
  writeTextFile(resultsFile, results.dump(1));
  writeTextFile(o.out / "results.csv", sweepCsv(results));
  std::fprintf(stderr, "%s: %zu points, %d resumed from %s\n", o.label, points.size(), resumed,
               resultsFile.string().c_str());
  return results;
}

}  // namespace diptych::cli
