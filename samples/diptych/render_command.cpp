#include "samples/diptych/render_command.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>

#include "engine/core/error.h"
#include "engine/core/image_check.h"
#include "engine/core/known.h"
#include "engine/core/log.h"
#include "engine/core/output_file.h"
#include "engine/core/timing.h"
#include "engine/core/tonemap.h"
#include "engine/gl/context.h"
#include "engine/graph/device_info.h"
#include "engine/graph/executor.h"
#include "engine/graph/export.h"
#include "engine/graph/render_world.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/default_lighting.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "passes/slots.h"
#include "samples/diptych/parse_size.h"
#include "samples/diptych/shading_option.h"

namespace diptych::cli {
namespace {

struct RenderOptions {
  std::string scene, recipe, cameraFile, size = "640x480", out = "out.png", graphOut, timingsOut;
  std::vector<std::string> outputs;  // --output, repeatable
  std::string context = "auto";
  std::string glSync = "auto";  // --gl-sync node|frame|auto
  std::vector<std::string> slots;
  int frames = 5, warmup = 2;
  std::string exposure = "0", tonemap = "clamp";
  LightingOptions lighting;
  std::string shading;  // --shading lecture|gltf (empty: each material its own)
  bool verbose = false;
};

std::string extensionOf(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

void printTimingTable(const CompiledGraph& g, const GraphExecutor& ex, const RenderOptions& o) {
  std::printf(
      "per-node timings: median of %d frames after %d warm-up frames (CPU: steady_clock; GPU: "
      "the node's own GL_TIME_ELAPSED, read after the measured frames, so no node waits on its "
      "query; gl wait: before a GL node or transfer starts, the wait for GL work that earlier "
      "nodes issued, kept out of its cpu ms; CPU nodes do not wait, GL work overlaps them; "
      "all-thread cpu: CPU time of all the process's threads over the node plus over the wait "
      "for its own GL work to complete, i.e. on llvmpipe the node's rasterization too; "
      "overlap: wall time the CPU nodes after a GL node ran while its GL work was pending)\n",
      o.frames, o.warmup);
  std::printf("%-34s %-9s %-4s %11s %11s %11s %15s %11s %14s\n", "node", "kind", "dom", "cpu ms",
              "gpu ms", "gl wait ms", "all-thread cpu", "overlap ms", "Mrays/s");
  double total = 0, totalThreads = 0;
  for (std::size_t n = 0; n < g.nodes.size(); ++n) {
    const NodeTiming& t = ex.timings()[n];
    const double cpu = summarize(t.cpuMs).median;
    total += cpu;
    const std::string gpu =
        t.gpuMs.empty() ? "-" : fmt::format("{:.3f}", summarize(t.gpuMs).median);
    const std::string wait =
        t.glWaitMs.empty() ? "-" : fmt::format("{:.3f}", summarize(t.glWaitMs).median);
    std::string rate = "-";
    if (auto it = t.counters.find("rays"); it != t.counters.end() && cpu > 0)
      rate = fmt::format("{:.2f}", it->second / (cpu * 1e3));
    const double threads =
        summarize(t.processCpuMs).median +
        (t.glCompletionCpuMs.empty() ? 0.0 : summarize(t.glCompletionCpuMs).median);
    totalThreads += threads;
    const std::string overlap =
        t.glOverlapMs.empty() ? "-" : fmt::format("{:.3f}", summarize(t.glOverlapMs).median);
    std::printf("%-34s %-9s %-4s %11.3f %11s %11s %15.3f %11s %14s\n", g.nodes[n].name.c_str(),
                nodeKindName(g.nodes[n].kind), domainName(g.nodes[n].domain), cpu, gpu.c_str(),
                wait.c_str(), threads, overlap.c_str(), rate.c_str());
  }
  std::printf("%-34s %-9s %-4s %11.3f %11s %11s %15.3f\n", "total (sum of medians)", "", "", total,
              "", "", totalThreads);
  if (!ex.frameGlWaitMs().empty())
    std::printf("%-34s %-9s %-4s %11.3f\n", "gl wait at frame end", "", "",
                summarize(ex.frameGlWaitMs()).median);
  std::printf("%-34s %-9s %-4s %11.3f\n", "frame wall (median)", "", "",
              summarize(ex.frameMs()).median);
  std::printf("gl sync: %s\n", ex.glSyncReason().c_str());
  for (const GraphPass& p : g.passes)
    if (!p.culled && !p.variant.empty())
      std::printf("variant: %s (%s): %s\n", p.name.c_str(), p.type.c_str(), p.variant.c_str());
  for (const GraphPass& p : g.passes)
    if (p.culled)
      std::printf("culled: %s (%s): %s\n", p.name.c_str(), p.type.c_str(), p.cullReason.c_str());
}

void runRender(const RenderOptions& o) {
  if (o.verbose) setLogLevel(spdlog::level::debug);
  if (o.frames < 1 || o.frames > 10000)
    throw InputError("--frames", "", "must be in 1..10000 (got " + std::to_string(o.frames) + ")");
  if (o.warmup < 0 || o.warmup > 10000)
    throw InputError("--warmup", "", "must be in 0..10000 (got " + std::to_string(o.warmup) + ")");
  const std::string outExt = extensionOf(o.out);
  if (outExt != ".png" && outExt != ".exr" && outExt != ".hdr" && outExt != ".jpg")
    throw InputError("--out", "",
                     "unsupported image extension '" + outExt + "' (use .png, .exr, .hdr or .jpg)");
  if (!o.graphOut.empty() && extensionOf(o.graphOut) != ".dot" &&
      extensionOf(o.graphOut) != ".json")
    throw InputError("--graph-out", "", "expected a .dot or .json file name");
  const auto [width, height] = parseSize(o.size, 16384);
  gl::ContextKind contextKind{};
  try {
    contextKind = gl::parseContextKind(o.context);
  } catch (const Error& e) {
    throw InputError("--context", o.context, e.what());
  }
  const std::optional<GlSync> glSync = parseGlSync(o.glSync);
  if (!glSync)
    throw InputError("--gl-sync", "", "expected node, frame or auto, got '" + o.glSync + "'");
  const std::optional<ToneOperator> toneOperator = parseToneOperator(o.tonemap);
  if (!toneOperator)
    throw InputError("--tonemap", "", "expected clamp, reinhard or aces, got '" + o.tonemap + "'");
  std::optional<float> fixedExposure;  // nullopt: auto
  if (o.exposure != "auto") {
    std::size_t used = 0;
    float ev = 0.f;
    try {
      ev = std::stof(o.exposure, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != o.exposure.size() || !std::isfinite(ev) || std::abs(ev) > 64.f)
      throw InputError(
          "--exposure", "",
          "expected 'auto' or a number of stops in [-64, 64], got '" + o.exposure + "'");
    fixedExposure = ev;
  }
  checkShadingOption(o.shading);
  checkOutputPath("--out", o.out);
  if (!o.graphOut.empty()) checkOutputPath("--graph-out", o.graphOut);
  if (!o.timingsOut.empty()) checkOutputPath("--timings", o.timingsOut);

  Scene scene = loadScene(o.scene);
  for (const std::string& w : scene.warnings) log().warn("{}", w);
  Camera camera = scene.hasCamera ? scene.camera : frameBounds(scene.bounds());
  if (auto line = applyLighting(scene, camera, o.lighting)) log().warn("{}", *line);
  if (auto hint = darkEnvironmentHint(scene)) log().warn("{}", *hint);
  applyShadingOption(scene, o.shading);
  if (!o.cameraFile.empty()) {  // after the default lighting, which the scene's camera placed
    camera = readCameraFile(o.cameraFile, scene.worldOrigin);
    if (camera.znear == 0.f) fitNearFar(camera, scene.bounds());
  }
  Recipe recipe = o.recipe.empty() ? defaultHybridRecipe() : loadRecipe(o.recipe);
  for (const std::string& text : o.slots)
    applySlotOverride(recipe, parseSlotOverride(text), builtinPasses());
  FrameSettings frame{.width = width, .height = height, .camera = camera};
  const CompiledGraph graph = compileGraph(recipe, builtinPasses(), scene, frame, o.outputs);
  for (ResourceId id : graph.outputs)  // refuse before rendering, not after
    if (formatIsInteger(graph.resources[id].desc.format))
      throw InputError(
          "--output", "",
          "'" + graph.resources[id].name + "' holds integers and cannot be written as an image");

  std::unique_ptr<gl::GlContext> context;
  if (graph.usesGl()) context = gl::createContext(contextKind, width, height);
  RenderWorld world(scene, context.get());
  const nlohmann::json devices = describeDevices(context.get());
  GraphExecutor executor(graph, world, *glSync);
  const bool tty = isatty(fileno(stderr));
  const GraphExecutor::MeasuredRun measured =
      executor.runMeasured(o.warmup, o.frames, [&](int done, int total) {
        if (tty) std::fprintf(stderr, "\rframe %d/%d%s", done, total, done == total ? "\n" : "");
      });

  // The first output goes to --out; any further one beside it, named after the resource
  // (out.png + "shade.variance" -> out.shade.variance.png). All are checked before any is
  // written.
  std::vector<Image> images;
  for (ResourceId id : graph.outputs) {
    images.push_back(executor.output(graph.resources[id].name).toImage());
    requireFinite(images.back(), "render: output '" + graph.resources[id].name + "'");
  }
  for (std::size_t i = 0; i < graph.outputs.size(); ++i) {
    const std::string name = graph.resources[graph.outputs[i]].name;
    std::filesystem::path file(o.out);
    if (i > 0) file.replace_filename(file.stem().string() + "." + name + file.extension().string());
    const Image& image = images[i];
    if (!fixedExposure) {  // from the first output, then the same for every other one
      fixedExposure = autoExposure(image);
      std::printf(
          "--exposure auto: %+.2f EV (log-average luminance of '%s' to 0.18, Reinhard "
          "et al. 2002)\n",
          *fixedExposure, name.c_str());
    }
    writeImage(file, image, ToneMap{*fixedExposure, *toneOperator});
    std::printf("wrote %s (%s, %dx%d)\n", file.string().c_str(), name.c_str(), width, height);
  }

  if (!o.graphOut.empty()) {
    writeTextFile(o.graphOut, extensionOf(o.graphOut) == ".dot"
                                  ? graphToDot(graph, &executor.timings())
                                  : graphToJson(graph, &executor.timings()).dump(2));
    std::printf("wrote %s\n", o.graphOut.c_str());
  }
  if (!o.timingsOut.empty()) {
    nlohmann::json j = graphToJson(graph, &executor.timings());
    j["method"] = fmt::format(
        "median of {} frames after {} warm-up frames; per node: cpu_ms (steady_clock), "
        "process_cpu_ms (CPU time of all threads), gpu_ms (the node's own GL_TIME_ELAPSED "
        "query, read after the measured frames: no node waits on its query) and, for GL "
        "nodes and transfers, gl_wait_ms (the wait, before the node's clocks, for GL work "
        "earlier nodes issued; that work is in their gpu_ms), gl_completion_ms and "
        "gl_completion_cpu_ms (the same wait charged to the node whose GL work it was, taken "
        "before the next GL node or at the frame's end; process_cpu_ms + gl_completion_cpu_ms "
        "is a node's whole CPU cost, on llvmpipe its rasterization included); with gl_sync "
        "frame, no wait per node but one at the frame's end (frame_gl_wait_ms, and its CPU time "
        "frame_gl_wait_cpu_ms). frame_ms: wall "
        "time per frame",
        o.frames, o.warmup);
    j["gl_sync"] = executor.glSyncReason();
    j["frame_ms"] = timingStatsJson(executor.frameMs());
    if (!executor.frameGlWaitMs().empty()) {
      j["frame_gl_wait_ms"] = timingStatsJson(executor.frameGlWaitMs());
      j["frame_gl_wait_cpu_ms"] = timingStatsJson(executor.frameGlWaitCpuMs());
    }
    j["scene"] = o.scene;
    j["devices"] = devices;
    j["one_time_ms"] = world.oneTimeMs;
    j["measured_again"] = measured.repeatedAFrame;
    j["first_frame"] = firstFrameJson(graph, measured);
    writeTextFile(o.timingsOut, j.dump(2));
    std::printf("wrote %s\n", o.timingsOut.c_str());
  }
  printTimingTable(graph, executor, o);
  if (scene.hasMotion()) {  // which frame of a moving scene this is (docs/reference-renderers.md)
    const int moving = scene.movingInstances();
    std::string blurredBy;
    for (const GraphPass& p : graph.passes)
      if (!p.culled && (p.type == "rt_distributed" || p.type == "rt_path"))
        blurredBy += (blurredBy.empty() ? "" : ", ") + p.name + " (" + p.type + ")";
    std::printf("motion: %d moving instance(s), %s\n", moving,
                blurredBy.empty()
                    ? "shown at the frame's instant t = 0.5 (rt_distributed and rt_path blur them)"
                    : ("blurred over the shutter by " + blurredBy).c_str());
  }
  for (const auto& [what, ms] : world.oneTimeMs)  // not in the frame medians above
    std::printf("one-time: %s %.3f ms\n", what.c_str(), ms);
  std::printf("%s\n", firstFrameLine(graph, measured).c_str());
  if (measured.repeatedAFrame)  // runMeasured's rule (executor.h)
    std::printf(
        "a measured frame did one-time work: its samples were dropped and the frames measured "
        "again\n");
  std::printf("devices: %s\n", deviceSummary(devices).c_str());
}

}  // namespace

void addRenderCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a scene through a frame-graph recipe");
  cmd->add_option("scene", options->scene, "Scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("--recipe", options->recipe,
                  "Frame-graph recipe (JSON); default: the hybrid frame");
  cmd->add_option("--size", options->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--camera", options->cameraFile,
                  "Camera from a JSON file's \"camera\" object (a scene, or one `diptych view` "
                  "saved) instead of the scene's");
  cmd->add_option("--out", options->out, "Output image (.png sRGB tone-mapped, .exr/.hdr linear)")
      ->capture_default_str();
  cmd->add_option("--slot", options->slots,
                  "Override a technique slot: SLOT=TYPE[:key=value,...]; SLOT is one of " +
                      joinNames(techniqueSlotNames()) +
                      " ('diptych passes' lists each slot's producers and their parameters)");
  cmd->add_option(
      "--output", options->outputs,
      "Graph resource(s) to write (repeatable; default: the recipe's outputs). The first "
      "goes to --out, others to OUT_STEM.RESOURCE.EXT");
  cmd->add_option("--graph-out", options->graphOut, "Write the compiled graph (.dot or .json)");
  cmd->add_option("--timings", options->timingsOut, "Write per-node timings and the graph as JSON");
  cmd->add_option("--frames", options->frames, "Measured frames (median reported)")
      ->capture_default_str();
  cmd->add_option("--warmup", options->warmup, "Warm-up frames before measuring")
      ->capture_default_str();
  cmd->add_option("--exposure", options->exposure,
                  "PNG/JPEG: multiply by 2^EV before tone mapping; 'auto' maps the log-average "
                  "luminance to middle grey 0.18 (Reinhard et al. 2002). EXR/HDR stay linear")
      ->capture_default_str();
  cmd->add_option("--tonemap", options->tonemap,
                  "PNG/JPEG tone map after exposure: clamp, reinhard or aces (docs/materials.md)")
      ->capture_default_str();
  addShadingOption(cmd, options->shading);
  cmd->add_option("--env", options->lighting.environmentFile,
                  "Equirect environment image (.hdr/.exr); replaces the scene's (see "
                  "docs/materials.md, default lighting)");
  cmd->add_option("--light", options->lighting.lightJson,
                  "Add a light, JSON as in a scene's \"lights\" array, e.g. "
                  "'{\"type\":\"directional\",\"direction\":[0,-1,0],\"intensity\":3}'");
  cmd->add_option(
         "--context", options->context,
         "OpenGL context: auto (EGL on a GPU, else OSMesa), osmesa, egl (headless) or glfw")
      ->capture_default_str();
  cmd->add_option("--gl-sync", options->glSync,
                  "When to wait for GL work: node (before every GL node; its CPU time charged to "
                  "the node that issued it), frame (at the frame's end only: pipelined), auto "
                  "(node on a software rasterizer, else frame)")
      ->capture_default_str();
  cmd->add_flag("-v,--verbose", options->verbose, "Log debug messages");
  cmd->callback([options, &exitCode] {
    runRender(*options);
    exitCode = 0;
  });
}

}  // namespace diptych::cli
