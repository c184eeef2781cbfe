#include "samples/diptych/compare_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/core/output_file.h"
#include "engine/core/timing.h"
#include "engine/gl/context.h"
#include "engine/graph/device_info.h"
#include "engine/graph/export.h"
#include "engine/graph/scene_needs.h"
#include "engine/metrics/metrics.h"
#include "engine/metrics/signal_metrics.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/load.h"
#include "engine/scene/primitives.h"
#include "engine/scene/scene_transform.h"
#include "engine/shading/shading.h"
#include "engine/shading/surface_detail.h"
#include "passes/registry.h"
#include "passes/rt/sdf_steps.h"
#include "passes/slots.h"
#include "samples/diptych/compare/report.h"
#include "samples/diptych/compare/runner.h"
#include "samples/diptych/compare/same_frame.h"
#include "samples/diptych/compare/same_image.h"
#include "samples/diptych/compare/sdf_steps_report.h"
#include "samples/diptych/compare/variants.h"
#include "samples/diptych/parse_size.h"
#include "samples/diptych/shading_option.h"

namespace diptych::cli {
namespace {

struct CompareOptions {
  std::string scene, variants, reference = "whitted", out = "out", size = "640x480",
                               metric = "flip_mean", context = "auto", shading;
  int frames = 3, warmup = 1, rounds = 1;
  // N: each pixel's texture colour over N x N sub-pixel rays in the reference and the
  // all-exact texture producer (the texture_filtering slot's exact answer; docs/compare.md).
  int textureSamples = kExactTextureSamples;
};

// The median over timing rounds of a variant's frame and of each pass, and its speed-up paired
// with the reference of the same round: a change of machine load between rounds moves both
// sides of each ratio (docs/compare.md, "Timing rounds").
struct RoundTimes {
  std::vector<double> totalMs;
  std::vector<nlohmann::json> passMs;
};

nlohmann::json medianPassMs(const std::vector<nlohmann::json>& rounds) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [pass, _] : rounds.front().items()) {
    std::vector<double> ms;
    for (const nlohmann::json& r : rounds)
      if (r.contains(pass)) ms.push_back(r[pass].get<double>());
    out[pass] = summarize(ms).median;
  }
  return out;
}

// Per round, reference / variant, each timed in that round.
std::vector<double> pairedRatios(const std::vector<double>& referenceMs,
                                 const std::vector<double>& totalMs) {
  std::vector<double> ratios;
  for (std::size_t r = 0; r < totalMs.size() && r < referenceMs.size(); ++r)
    if (totalMs[r] > 0) ratios.push_back(referenceMs[r] / totalMs[r]);
  return ratios;
}

// The all-exact frame among the variants: the first with the built-in recipe, no slot override
// and the scene as authored (the default set's `hybrid-exact`). Where it is an earlier variant's
// frame (same_frame.h), that variant is the one timed, and the one returned.
std::optional<std::size_t> exactVariant(const std::vector<Variant>& variants,
                                        const std::vector<int>& sameAs) {
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Variant& v = variants[i];
    if (v.recipeFile.empty() && v.slots.empty() && v.tessellation == 0 && v.surfaceDetail.empty() &&
        v.shutterSamples == 0)
      return sameAs[i] < 0 ? i : std::size_t(sameAs[i]);
  }
  return std::nullopt;
}

nlohmann::json culledPasses(const CompiledGraph& graph) {
  nlohmann::json culled = nlohmann::json::array();
  for (const GraphPass& p : graph.passes)
    if (p.culled) culled.push_back({{"pass", p.name}, {"reason", p.cullReason}});
  return culled;
}

// Pixels whose material has the coefficient `pick` > 0 (k_ps for reflection, k_t for transmission).
std::vector<std::uint8_t> materialMask(const Scene& scene, const CpuImage& gbuffer,
                                       const std::function<float(const Material&)>& pick) {
  std::vector<std::uint8_t> mask(std::size_t(gbuffer.desc.width) * gbuffer.desc.height, 0);
  for (int y = 0; y < gbuffer.desc.height; ++y)
    for (int x = 0; x < gbuffer.desc.width; ++x) {
      const std::uint32_t id = gbuffer.u(x, y, 0);
      if (!id) continue;
      const Material& m = scene.material(scene.meshes[scene.instances[id - 1].mesh].material);
      mask[std::size_t(y) * gbuffer.desc.width + x] = pick(m) > 0.f;
    }
  return mask;
}

// Each slot's signal against the exact signal on the same G-buffer (docs/metrics.md).
nlohmann::json signalErrors(const Scene& scene, const GraphRun& run, const Recipe& recipe,
                            const GraphRun& exact, const Recipe& exactRecipe) {
  nlohmann::json out = nlohmann::json::object();
  const CpuImage& gbuffer = exact.outputs.at("gbuffer.hits");
  auto signalPair = [&](const std::string& slot) -> std::pair<const CpuImage*, const CpuImage*> {
    const std::string mine = slotSignal(recipe, slot), ref = slotSignal(exactRecipe, slot);
    if (mine.empty() || ref.empty() || !run.outputs.count(mine) || !exact.outputs.count(ref))
      return {nullptr, nullptr};
    return {&run.outputs.at(mine), &exact.outputs.at(ref)};
  };
  if (auto [mine, ref] = signalPair("visibility"); mine && mine->desc == ref->desc) {
    const auto mask = coverage(gbuffer);
    for (int l = 0; l < mine->desc.layers; ++l) {
      const VisibilityConfusion c = compareVisibility(layer(*mine, l), layer(*ref, l), mask,
                                                      gbuffer.desc.width, gbuffer.desc.height, 2);
      out["visibility"].push_back({{"light", l},
                                   {"band_px", c.band},
                                   {"receivers", c.receivers},
                                   {"false_shadow_outside", c.falseShadowOutside},
                                   {"false_lit_outside", c.falseLitOutside},
                                   {"false_shadow_inside", c.falseShadowInside},
                                   {"false_lit_inside", c.falseLitInside},
                                   {"false_shadow_rate", c.falseShadowRate()},
                                   {"false_lit_rate", c.falseLitRate()},
                                   {"mean_boundary_displacement_px", c.meanBoundaryDisplacement}});
    }
  }
  const std::pair<const char*, std::function<float(const Material&)>> radianceSlots[] = {
      {"reflection",
       [](const Material& m) { return shading::materialHasReflection(m) ? 1.f : 0.f; }},
      {"transmission",
       [](const Material& m) { return shading::materialHasTransmission(m) ? 1.f : 0.f; }},
      // The filtered colour where a colour texture is read (SceneNeed::TexturedMaterial's test).
      {"texture_filtering",
       [&](const Material& m) { return readsColorTexture(scene, m) ? 1.f : 0.f; }}};
  for (const auto& [slot, pick] : radianceSlots) {
    auto [mine, ref] = signalPair(slot);
    if (!mine || !(mine->desc == ref->desc)) continue;
    const SignalError e =
        compareRadiance(mine->toImage(), ref->toImage(), materialMask(scene, gbuffer, pick));
    out[slot] = {{"pixels", e.pixels}, {"rmse", e.rmse}, {"relative_rmse", e.relativeRmse}};
  }
  return out;
}

// Bytes of a file ("" when it cannot be read): the cache key covers contents, not names or dates.
std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The reference cache key: every file the scene was read from (an edited texture or included
// glTF invalidates it), this program's own bytes (a new build never reuses a stale reference),
// the reference's recipe and the frame size.
std::string cacheKey(const Scene& scene, const ReferenceSpec& ref, const FrameSettings& frame) {
  std::string key = std::to_string(std::hash<std::string>{}(fileBytes("/proc/self/exe")));
  for (const std::string& file : scene.sourceFiles)
    key += "|" + file + ":" + std::to_string(std::hash<std::string>{}(fileBytes(file)));
  key += "|models:";  // --shading changes the reference without changing a file
  for (const Material& m : scene.materials) key += std::to_string(int(m.model));
  key += "|" + ref.recipe().passes[0].params.dump() + "|" + ref.passType + "|" +
         std::to_string(frame.width) + "x" + std::to_string(frame.height);
  return fmt::format("{:016x}", std::hash<std::string>{}(key));
}

void runCompare(const CompareOptions& o) {
  const std::string sceneFile =
      o.scene.empty() ? std::string(DIPTYCH_SAMPLES_DIR) + "/scenes/whitted.json" : o.scene;
  if (o.frames < 1) throw InputError("--frames", "", "need at least one measured frame");
  if (o.warmup < 0) throw InputError("--warmup", "", "must not be negative");
  if (o.rounds < 1) throw InputError("--rounds", "", "need at least one timing round");
  const auto [width, height] = parseSize(o.size, 8192);
  const PassRegistry& registry = builtinPasses();
  if (o.textureSamples < 1 || o.textureSamples > 64)
    throw InputError("--texture-samples", std::to_string(o.textureSamples),
                     "expected a whole number of samples per axis in 1..64");
  ReferenceSpec reference = parseReference(o.reference, registry);
  reference.textureSamples = o.textureSamples;
  std::vector<Variant> variants =
      o.variants.empty() ? defaultVariants(registry) : loadVariants(o.variants, registry);
  std::vector<Recipe> recipes;
  for (const Variant& v : variants)  // errors before any work
    recipes.push_back(v.build(registry, o.textureSamples));

  checkShadingOption(o.shading);
  Scene scene = loadScene(sceneFile);
  applyShadingOption(scene, o.shading);
  // The geometry axis joins the defaults where the scene has analytic quadrics or SDF objects.
  const bool analytic = std::any_of(scene.meshes.begin(), scene.meshes.end(),
                                    [](const Mesh& m) { return m.analytic || m.sdf; });
  if (o.variants.empty() && analytic) {
    for (const Variant& v : geometryVariants()) {
      variants.push_back(v);
      recipes.push_back(v.build(registry, o.textureSamples));
    }
  }
  // And the surface-detail axis where it has bump maps; their exact answer, the reference, is
  // the displaced surface (docs/materials.md#bump-vs-normal-maps).
  const bool bumped = hasBumpMaps(scene);
  const bool textured = sceneSatisfies(scene, SceneNeed::TexturedMaterial);
  // rt_whitted takes --texture-samples; distributed and path references integrate the pixel.
  const bool referenceFootprint = textured && reference.passType == "rt_whitted";
  // Motion blur (docs/reference-renderers.md): only the distributed and path references draw
  // times over the shutter; rt_whitted and every variant show the frame's instant. Said once,
  // so that an error that is mostly the missing blur is read as such.
  const int moving = scene.movingInstances();
  const bool blurredReference = moving > 0 && reference.passType != "rt_whitted";
  if (moving > 0)
    std::fprintf(stderr, "compare: %d moving instance(s): %s\n", moving,
                 blurredReference
                     ? "the reference integrates them over the shutter (motion blur); every "
                       "variant shows the frame's instant t = 0.5, so its error includes the "
                       "missing blur"
                     : "the reference (whitted) and every variant show the frame's instant "
                       "t = 0.5, so no motion blur is compared (--reference distributed:SPP or "
                       "path:SPP blurs them)");
  // And the motion-blur axis where something moves: the accumulation buffer (variants.h).
  if (o.variants.empty() && moving > 0) {
    for (const Variant& v : motionVariants(registry)) {
      variants.push_back(v);
      recipes.push_back(v.build(registry, o.textureSamples));
    }
  }
  if (o.variants.empty() && bumped) {
    for (const Variant& v : surfaceDetailVariants()) {
      variants.push_back(v);
      recipes.push_back(v.build(registry, o.textureSamples));
    }
  }
  // And the texture-LOD axis at traced hits where colour textures can be seen in a mirror or
  // through glass: level 0 and ray cones against the footprint.
  if (o.variants.empty() && textured) {
    for (const Variant& v :
         textureLodVariants(sceneSatisfies(scene, SceneNeed::ReflectiveMaterial),
                            sceneSatisfies(scene, SceneNeed::TransmissiveMaterial))) {
      variants.push_back(v);
      recipes.push_back(v.build(registry, o.textureSamples));
    }
  }
  const FrameSettings frame{width, height,
                            scene.hasCamera ? scene.camera : frameBounds(scene.bounds())};
  if (auto line = applyLighting(scene, frame.camera, {})) log().warn("{}", *line);
  if (auto hint = darkEnvironmentHint(scene)) log().warn("{}", *hint);
  // One-time costs, measured apart from every frame: context creation, the Embree BVH build, the
  // GL scene upload. Frames (reference and variants alike) are medians after warm-up.
  nlohmann::json oneTime;
  Stopwatch clock;
  auto context = gl::createContext(gl::parseContextKind(o.context), width, height);
  oneTime["gl_context_ms"] = clock.milliseconds();
  RenderWorld world(scene, context.get());
  clock.restart();
  world.rtScene();
  oneTime["embree_bvh_build_ms"] = clock.milliseconds();
  clock.restart();
  world.glScene();
  world.glShading();
  oneTime["gl_scene_upload_ms"] = clock.milliseconds();
  const nlohmann::json devices = describeDevices(context.get());
  std::fprintf(stderr, "compare: %s\n", deviceSummary(devices).c_str());
  const std::filesystem::path dir(o.out);
  std::filesystem::create_directories(dir / "cache");
  const int steps = int(variants.size()) + 2 + (o.rounds - 1) * (int(variants.size()) + 1);
  int step = 0;

  // The reference, cached by scene contents + settings.
  progress(
      "compare", step, steps,
      "reference " + reference.text + (bumped ? " on the displaced surfaces" : "") +
          (referenceFootprint && o.textureSamples > 1
               ? fmt::format(", each pixel's texture colour over {0} x {0} rays", o.textureSamples)
               : ""));
  const auto cached = dir / "cache" / ("reference-" + cacheKey(scene, reference, frame) + ".exr");
  Image referenceImage;
  double referenceMs = 0;
  std::vector<double> referenceRounds;  // this run's reference timings, one per round
  const Recipe referenceRecipe = reference.recipe();
  std::unique_ptr<Scene> displaced;
  std::unique_ptr<RenderWorld> displacedWorld;
  const auto referenceWorld = [&]() -> RenderWorld& {
    if (bumped && !displacedWorld) {
      clock.restart();
      displaced = std::make_unique<Scene>(withSurfaceDetail(scene, SurfaceDetail::Displaced));
      displacedWorld = std::make_unique<RenderWorld>(*displaced, context.get());
      displacedWorld->rtScene();
      oneTime["displaced_reference_build_ms"] = clock.milliseconds();
      log().info("reference traces the bump-mapped surfaces displaced ({} triangles)",
                 displacedWorld->geometry().triangleCount());
    }
    return displacedWorld ? *displacedWorld : world;
  };
  // Per-pixel sphere-tracing steps (passes/rt/sdf_steps.h), cached beside the reference.
  const bool sdfSteps = sceneHasSdf(scene) && reference.passType != "rt_path";
  // The same graph in every round (the steps image is an output of it where there are SDFs).
  std::vector<std::string> referenceOutputs = referenceRecipe.outputs;
  if (sdfSteps) referenceOutputs.push_back("reference.sdf_steps");
  const auto timeReference = [&] {
    return runGraph(referenceRecipe, referenceWorld(), frame, referenceOutputs, o.warmup, o.frames);
  };
  bool referenceCached = std::filesystem::exists(cached) &&
                         std::filesystem::exists(cached.string() + ".json") &&
                         (!sdfSteps || std::filesystem::exists(cached.string() + ".sdf_steps.exr"));
  if (referenceCached) {
    referenceImage = readImage(cached);
    referenceMs =
        nlohmann::json::parse(std::ifstream(cached.string() + ".json"))["ms"].get<double>();
    // Paired speed-ups need this run's reference time in every round: the image stays cached.
    if (o.rounds > 1) referenceRounds.push_back(timeReference().totalMs);
  } else {
    const GraphRun ref = timeReference();
    referenceImage = ref.outputs.at("reference.color").toImage();
    referenceMs = ref.totalMs;
    referenceRounds.push_back(ref.totalMs);
    oneTime["reference_first_frame_ms"] = ref.firstFrameMs;
    writeImage(cached, referenceImage);
    if (ref.outputs.count("reference.variance"))  // path tracing: the per-pixel variance too
      writeImage(cached.string() + ".variance.exr", ref.outputs.at("reference.variance").toImage());
    if (sdfSteps)
      writeImage(cached.string() + ".sdf_steps.exr",
                 ref.outputs.at("reference.sdf_steps").toImage());
    writeTextFile(cached.string() + ".json",
                  nlohmann::json{{"ms", referenceMs}, {"reference", reference.text}}.dump());
  }
  if (std::filesystem::exists(cached.string() + ".variance.exr")) {
    std::filesystem::create_directories(dir / "images");
    std::filesystem::copy_file(cached.string() + ".variance.exr",
                               dir / "images/reference-variance.exr",
                               std::filesystem::copy_options::overwrite_existing);
  }
  progress("compare", ++step, steps, "exact slot signals");

  // Exact slot signals on the shared G-buffer: the all-exact hybrid, its texture producer at N.
  const Recipe exactRecipe = exactHybridRecipe(o.textureSamples);
  auto signalOutputs = [](const Recipe& r) {
    std::vector<std::string> outs = {r.outputs.front(), "gbuffer.hits"};
    for (const std::string& slot : techniqueSlotNames())
      if (const std::string s = slotSignal(r, slot); !s.empty()) outs.push_back(s);
    return outs;
  };
  const GraphRun exact = runGraph(exactRecipe, world, frame, signalOutputs(exactRecipe), 0, 1);
  progress("compare", ++step, steps, "variants");

  std::vector<ReportVariant> results;
  std::vector<RoundTimes> rounds(variants.size());
  // Per variant: its own world where it has one (kept for the later timing rounds) and the
  // outputs its graph was compiled with (the same graph in every round).
  std::vector<std::unique_ptr<Scene>> variantScenes(variants.size());
  std::vector<std::unique_ptr<RenderWorld>> variantWorlds(variants.size());
  std::vector<std::vector<std::string>> variantOutputs(variants.size());
  // Per variant: the earlier variant whose compiled frame it is (same_frame.h), or -1 where it
  // is timed itself. Only timed variants are matched, so a same-frame variant names one that was.
  std::vector<int> sameAs(variants.size(), -1);
  std::vector<FrameIdentity> identities;
  const auto variantWorld = [&](std::size_t i) -> RenderWorld& {
    return variantWorlds[i] ? *variantWorlds[i] : world;
  };
  // Per accumulation-buffer variant (Variant::shutterSamples): its snapshots' scenes and worlds.
  std::vector<std::vector<std::unique_ptr<Scene>>> instantScenes(variants.size());
  std::vector<std::vector<std::unique_ptr<RenderWorld>>> instantWorlds(variants.size());
  // A variant's frame: through its accumulation buffer where it has one (runAccumulated).
  const auto runVariant = [&](std::size_t i, CompiledGraph* compiled) {
    if (!instantWorlds[i].empty())
      return runAccumulated(recipes[i], instantWorlds[i], frame, variantOutputs[i], o.warmup,
                            o.frames);
    if (compiled)
      return runCompiled(std::move(*compiled), variantWorld(i), variantOutputs[i], o.warmup,
                         o.frames);
    return runGraph(recipes[i], variantWorld(i), frame, variantOutputs[i], o.warmup, o.frames);
  };
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Variant& v = variants[i];
    const Recipe& recipe = recipes[i];
    if (std::find(recipe.outputs.begin(), recipe.outputs.end(), "shade.color") ==
            recipe.outputs.end() &&
        recipe.outputs.empty())
      throw InputError(v.name, "", "variant recipe has no output");
    std::vector<std::string> outs = signalOutputs(recipe);
    const bool hasGbuffer = std::any_of(recipe.passes.begin(), recipe.passes.end(),
                                        [](const RecipePass& p) { return p.type == "gbuffer"; });
    if (!hasGbuffer) outs = {recipe.outputs.front()};
    // A geometry variant runs on its own world: the scene with the quadrics tessellated.
    if (auto own = variantScene(scene, v)) {
      variantScenes[i] = std::make_unique<Scene>(std::move(*own));
      const Scene& tessellated = *variantScenes[i];
      for (std::size_t w = scene.warnings.size(); w < tessellated.warnings.size(); ++w)
        log().warn("{}: {}", v.name, tessellated.warnings[w]);
      variantWorlds[i] = std::make_unique<RenderWorld>(tessellated, context.get());
    }
    // The accumulation buffer: the scene's snapshot at each of its instants, on a world of its
    // own (its BVH build and GL upload are one-time costs); only the image is averaged, so the
    // per-slot signals, which belong to one instant, are not compared.
    for (int k = 0; k < v.shutterSamples; ++k) {
      const float time = (float(k) + 0.5f) / float(v.shutterSamples);
      instantScenes[i].push_back(
          std::make_unique<Scene>(sceneAtTime(variantWorld(i).scene(), time)));
      instantWorlds[i].push_back(
          std::make_unique<RenderWorld>(*instantScenes[i].back(), context.get()));
    }
    if (v.shutterSamples > 0) outs = {recipe.outputs.front()};
    variantOutputs[i] = outs;
    // The geometry the ray tracers hold (Embree's input, without its BVH): 12 bytes per vertex
    // and per triangle; an analytic or SDF instance is its AnalyticInstance.
    std::size_t tracedTriangles = 0, tracedBytes = 0;
    for (const WorldMesh& m : variantWorld(i).geometry().meshes) {
      if (m.analytic) {
        tracedBytes += sizeof(AnalyticInstance);
        continue;
      }
      tracedTriangles += m.indices.size() / 3;
      tracedBytes += 12 * (m.positions.size() + m.indices.size() / 3);
    }
    CompiledGraph graph =
        compileGraph(recipe, registry, variantWorld(i).scene(), frame, variantOutputs[i]);
    identities.push_back(
        frameIdentity(graph, recipe, registry, variantSceneState(scene, v), v.surfaceDetail));
    for (std::size_t j = 0; j < i && sameAs[i] < 0; ++j)
      if (sameAs[j] < 0 && identities[j].signature == identities[i].signature) sameAs[i] = int(j);
    if (sameAs[i] >= 0) {
      // The frame of an earlier variant: its image, metrics, signals and timings, not run again.
      const ReportVariant& same = results[std::size_t(sameAs[i])];
      ReportVariant rv{v.name, same.image, same.heatmap, graphToDot(graph), same.result};
      rv.result.update(
          {{"name", v.name},
           {"recipe", v.recipeFile.empty() ? "<built-in hybrid>" : v.recipeFile},
           {"slots", v.slots},
           {"tessellation", v.tessellation},
           {"surface_detail", v.surfaceDetail.empty() ? "as authored" : v.surfaceDetail},
           {"one_time_ms", nlohmann::json::object()},  // it built nothing
           {"culled", culledPasses(graph)},
           {"graph", graphToJson(graph)},
           {"same_frame_as", same.name},
           {"same_frame_reason",
            sameFrameReason(identities[i], identities[std::size_t(sameAs[i])])},
           {"timings_from", same.name}});
      progress("compare", ++step, steps, v.name + " (same frame as " + same.name + ")");
      results.push_back(std::move(rv));  // `same` may move with it
      continue;
    }
    const GraphRun run = runVariant(i, &graph);
    rounds[i].totalMs.push_back(run.totalMs);
    rounds[i].passMs.push_back(run.passMs);
    // Work this variant did once for the world (a static shadow map, a prefiltered environment),
    // outside its frame medians. Variants share the world: what an earlier one built is reused.
    const nlohmann::json variantOneTime = run.oneTimeMs;
    ReportVariant rv;
    rv.name = v.name;
    rv.image = run.outputs.at(recipe.outputs.front()).toImage();
    const auto metrics = computeMetrics(rv.image, referenceImage);
    rv.heatmap = heatMap(flipErrorMap(rv.image, referenceImage), 1.f);
    rv.dot = graphToDot(run.graph, &run.timings);
    rv.result = {{"name", v.name},
                 {"recipe", v.recipeFile.empty() ? "<built-in hybrid>" : v.recipeFile},
                 {"slots", v.slots},
                 {"tessellation", v.tessellation},
                 {"surface_detail", v.surfaceDetail.empty() ? "as authored" : v.surfaceDetail},
                 {"traced_triangles", tracedTriangles},
                 {"traced_geometry_bytes", tracedBytes},
                 {"total_ms", run.totalMs},
                 {"first_frame_ms", run.firstFrameMs},
                 {"first_frame", run.firstFrame},
                 {"gl_sync", run.glSync},
                 {"one_time_ms", variantOneTime},
                 {"pass_ms", run.passMs},
                 {"rays", run.rays},
                 {"speedup_vs_reference", run.totalMs > 0 ? referenceMs / run.totalMs : 0.0},
                 {"metrics", metrics},
                 {"shutter_samples", v.shutterSamples},
                 {"signals", hasGbuffer && v.shutterSamples == 0
                                 ? signalErrors(scene, run, recipe, exact, exactRecipe)
                                 : nlohmann::json::object()},
                 {"culled", culledPasses(run.graph)},
                 {"graph", graphToJson(run.graph, &run.timings)}};
    results.push_back(std::move(rv));
    progress("compare", ++step, steps, v.name);
  }

  // A variant timed on its own whose image is an earlier timed variant's (same_image.h): said
  // so, with the difference and the reason, instead of error columns equal with nothing said.
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (sameAs[i] >= 0) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (sameAs[j] >= 0 || results[j].result.contains("same_image_as")) continue;
      const double difference =
          largestRelativeDifference(results[i].image, results[j].image, kSameImageTolerance);
      if (!(difference <= kSameImageTolerance)) continue;
      results[i].result["same_image_as"] = results[j].name;
      results[i].result["same_image_difference"] = difference;
      results[i].result["same_image_reason"] = sameImageReason(identities[i], identities[j], scene);
      break;
    }
  }

  // Timing rounds 2..R: the reference and every variant again, in the same order, so that a
  // change of load between the first variant and the last reaches every figure alike. Images and
  // metrics are the first round's (the frames are deterministic).
  for (int r = 1; r < o.rounds; ++r) {
    const std::string round = fmt::format("round {}/{}: ", r + 1, o.rounds);
    progress("compare", ++step, steps, round + "reference");
    referenceRounds.push_back(timeReference().totalMs);
    for (std::size_t i = 0; i < variants.size(); ++i) {
      if (sameAs[i] >= 0) {
        progress("compare", ++step, steps, round + variants[i].name + " (same frame)");
        continue;
      }
      const GraphRun run = runVariant(i, nullptr);
      rounds[i].totalMs.push_back(run.totalMs);
      rounds[i].passMs.push_back(run.passMs);
      progress("compare", ++step, steps, round + variants[i].name);
    }
  }
  if (o.rounds > 1) {
    referenceMs = summarize(referenceRounds).median;
    for (std::size_t i = 0; i < results.size(); ++i) {
      if (sameAs[i] >= 0) continue;
      nlohmann::json& v = results[i].result;
      v["total_ms"] = summarize(rounds[i].totalMs).median;
      v["total_ms_rounds"] = rounds[i].totalMs;
      v["pass_ms"] = medianPassMs(rounds[i].passMs);
      const std::vector<double> ratios = pairedRatios(referenceRounds, rounds[i].totalMs);
      v["speedup_rounds"] = ratios;  // the report prints their range beside the median
      v["speedup_vs_reference"] = ratios.empty() ? 0.0 : summarize(ratios).median;
    }
  }
  // What a technique saves against the all-exact frame whose slot it replaces, in the same
  // round: exact / variant per round (the time axis of "how wrong is the trick and what does it
  // save"; the reference is a different renderer, whose speed-up mixes in the G-buffer's cost).
  if (const auto allExact = exactVariant(variants, sameAs)) {
    for (std::size_t i = 0; i < results.size(); ++i) {
      if (sameAs[i] >= 0 || i == *allExact) continue;
      const std::vector<double> ratios = pairedRatios(rounds[*allExact].totalMs, rounds[i].totalMs);
      if (ratios.empty()) continue;
      results[i].result["exact_variant"] = variants[*allExact].name;
      results[i].result["speedup_vs_exact"] = summarize(ratios).median;
      results[i].result["speedup_vs_exact_rounds"] = ratios;
      // And in milliseconds (exact - variant per round): unlike the ratio, not diluted by the
      // costs every frame of the run carries (the exact texture producers on a textured scene).
      std::vector<double> saved;
      for (std::size_t r = 0; r < rounds[i].totalMs.size() && r < rounds[*allExact].totalMs.size();
           ++r)
        saved.push_back(rounds[*allExact].totalMs[r] - rounds[i].totalMs[r]);
      results[i].result["saved_ms_vs_exact"] = summarize(saved).median;
      results[i].result["saved_ms_vs_exact_rounds"] = saved;
    }
  }
  // A same-frame variant's timings are those of the variant whose frame it is (said so by
  // "timings_from"); it is no point of its own on the Pareto front or the plot.
  for (std::size_t i = 0; i < results.size(); ++i) {
    if (sameAs[i] < 0) continue;
    const nlohmann::json& same = results[std::size_t(sameAs[i])].result;
    for (const char* key :
         {"total_ms", "total_ms_rounds", "pass_ms", "speedup_vs_reference", "speedup_rounds",
          "exact_variant", "speedup_vs_exact", "speedup_vs_exact_rounds", "saved_ms_vs_exact",
          "saved_ms_vs_exact_rounds", "first_frame_ms", "gl_sync", "rays"})
      if (same.contains(key)) results[i].result[key] = same[key];
  }

  // Pareto front in (time, error): no other variant is at least as fast and as accurate, and
  // strictly better in one.
  for (ReportVariant& a : results) {
    const double ta = a.result["total_ms"], ea = a.result["metrics"].value(o.metric, 0.0);
    bool dominated = a.result.contains("same_frame_as");
    for (const ReportVariant& b : results) {
      const double tb = b.result["total_ms"], eb = b.result["metrics"].value(o.metric, 0.0);
      if (tb <= ta && eb <= ea && (tb < ta || eb < ea)) dominated = true;
    }
    a.result["pareto"] = !dominated;
  }
  nlohmann::json header = {
      {"scene", sceneFile},
      {"size", {{"width", width}, {"height", height}}},
      {"reference",
       {{"spec", reference.text},
        {"ms", referenceMs},
        {"ms_rounds", referenceRounds},
        {"cached", referenceCached},
        // The time too, from the run that cached the image; with rounds it is this run's.
        {"ms_cached", referenceCached && o.rounds == 1},
        {"surfaces", bumped ? "displaced" : "as authored"},
        // "shutter": the reference integrates moving instances over the shutter [0, 1];
        // "instant": it shows t = 0.5 as the variants do; null: nothing moves.
        {"time", moving == 0        ? nlohmann::json()
                 : blurredReference ? nlohmann::json("shutter")
                                    : nlohmann::json("instant")},
        // The footprint each pixel's texture colour is averaged over, N x N rays (rt_whitted's
        // texture_samples; null: no colour textures, or a reference whose own samples
        // integrate the pixel).
        {"texture_samples",
         referenceFootprint ? nlohmann::json(o.textureSamples) : nlohmann::json()}}},
      // The same N in the exact texture producer (texture_supersample) of every variant that
      // keeps it; null on a scene without colour textures, where the slot is culled.
      {"exact_texture_samples", textured ? nlohmann::json(o.textureSamples) : nlohmann::json()},
      {"frames", o.frames},
      {"warmup", o.warmup},
      {"rounds", o.rounds},
      {"load_average_end", loadAverage()},
      {"pareto_metric", o.metric},
      {"devices", devices},
      {"one_time_ms", oneTime},
      {"method",
       fmt::format(
           "reference and variants alike: per pass, median of {} frames after {} warm-up frames "
           "(steady_clock); total = sum of per-pass medians{}. One-time costs (context, BVH "
           "build, scene upload; each recipe's first frame) are reported apart, never inside a "
           "frame{}{}",
           o.frames, o.warmup,
           o.rounds > 1 ? fmt::format("; {} timing rounds (reference, then every variant, in "
                                      "turn): medians over rounds, speed-ups paired per round",
                                      o.rounds)
                        : std::string(),
           // runMeasured repeats a frame that recorded one-time work, but a driver's first-use
           // work (llvmpipe compiles programs at their first draw) is recorded nowhere: without
           // warm-up the first frame is a sample, and with fewer than 3 frames it moves the median.
           o.warmup == 0 && o.frames < 3
               ? "; NO WARM-UP: the first frame's unrecorded first-use work (a GL driver "
                 "compiling programs at their first draw) is inside these medians, so the times "
                 "are not steady-state figures"
               : "",
           !textured ? ""
           : referenceFootprint
               ? fmt::format("; texture colour in the reference and the exact texture producer: "
                             "each pixel's footprint mean over {0} x {0} rays (--texture-samples)",
                             o.textureSamples)
               : fmt::format("; texture colour in the exact texture producer: each pixel's "
                             "footprint mean over {0} x {0} rays (--texture-samples); the "
                             "reference's own samples integrate each pixel",
                             o.textureSamples))}};
  std::vector<std::string> stepFiles;
  if (sdfSteps)
    header["sdf_steps"] =
        writeSdfStepReport(dir, readImage(cached.string() + ".sdf_steps.exr"), stepFiles);
  auto written = writeReport(dir, header, referenceImage, results, o.metric);
  written.insert(written.end(), stepFiles.begin(), stepFiles.end());

  printSummaryTable(results, o.metric, o.rounds);
  std::printf("reference %s: %.2f ms%s; %s\nwrote %zu files to %s (open %s)\n",
              reference.text.c_str(), referenceMs,
              !referenceCached ? ""
              : o.rounds == 1  ? " (cached)"
                               : " (image cached; timed in this run)",
              header["method"].get<std::string>().c_str(), written.size(), dir.string().c_str(),
              (dir / "report.html").string().c_str());
}

}  // namespace

void addCompareCommand(CLI::App& app, int& exitCode) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* cmd =
      app.add_subcommand("compare",
                         "Measure variants against an exact reference: images, error maps, "
                         "tables, error-vs-time plot, report.html");
  cmd->add_option("scene", o->scene,
                  "Scene (.json, .gltf, .glb); default: the built-in Whitted sample");
  cmd->add_option("--variants", o->variants,
                  "Variants: a .json file or comma-separated default names");
  cmd->add_option("--reference", o->reference, "whitted | distributed:SPP | path:SPP")
      ->capture_default_str();
  cmd->add_option("--texture-samples", o->textureSamples,
                  "N: on scenes with colour textures, each pixel's texture colour averaged over "
                  "N x N sub-pixel rays in the reference and the exact texture producer (the "
                  "texture_filtering slot's exact answer); 1: the pixel centre's lookup")
      ->capture_default_str();
  cmd->add_option("--frames", o->frames, "Measured frames per variant (median)")
      ->capture_default_str();
  cmd->add_option("--warmup", o->warmup, "Warm-up frames per variant")->capture_default_str();
  cmd->add_option("--rounds", o->rounds,
                  "Timing rounds: the reference and every variant timed R times in turn; medians "
                  "over rounds, speed-ups paired per round (R > 1 re-times a cached reference)")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder")->capture_default_str();
  cmd->add_option("--pareto-metric", o->metric, "Error metric of the plot and Pareto front")
      ->capture_default_str();
  addShadingOption(cmd, o->shading);
  cmd->add_option("--context", o->context, "OpenGL context: auto, osmesa, egl or glfw")
      ->capture_default_str();
  cmd->callback([o, &exitCode] {
    runCompare(*o);
    exitCode = 0;
  });
}

}  // namespace diptych::cli
