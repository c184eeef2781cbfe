// GL timer queries in the executor (engine/graph/executor.cpp) are read after the frame, not
// waited on per node: every GL node and transfer still gets one GL sample per frame (once
// llvmpipe's first-scene garbage value is past), CPU nodes get none, and the samples are
// bounded by the frame they were taken in.
#include <gtest/gtest.h>

#include <filesystem>
#include <numeric>
#include <optional>

#include "engine/graph/executor.h"
#include "engine/graph/export.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

Recipe shadowRecipe() {
  Recipe recipe;
  recipe.passes = {{.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
                   {.name = "sm",
                    .type = "shadow_map",
                    .params = {{"resolution", 256}},
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[1]"},
                   {.name = "rt",
                    .type = "rt_shadows",
                    .inputs = {{"hits", "gbuffer.hits"}},
                    .place = "passes[2]"}};
  return recipe;
}

// The shadow sphere at 96x72 through `recipe`, one warm-up frame (the first query of a context
// may read garbage and be dropped) and `frames` measured ones.
struct TimedRun {
  Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/shadow-sphere.json");
  CompiledGraph graph;
  RenderWorld world{scene, &gl::testing::osmesaContext()};
  std::optional<GraphExecutor> ex;
  TimedRun(const Recipe& recipe, int frames, GlSync sync = GlSync::Auto)
      : graph(compileGraph(recipe, builtinPasses(), scene, FrameSettings{96, 72, scene.camera},
                           {"sm.visibility", "rt.visibility"})) {
    ex.emplace(graph, world, sync);
    ex->runFrame();
    ex->clearTimings();
    for (int f = 0; f < frames; ++f) ex->runFrame();
  }
};

TEST(ExecutorGlTiming, EveryGlNodeGetsItsQueryResultAfterTheFrame) {
  constexpr int kFrames = 3;
  const TimedRun run(shadowRecipe(), kFrames);
  const CompiledGraph& graph = run.graph;
  const GraphExecutor& ex = *run.ex;
  int glNodes = 0;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const GraphNode& node = graph.nodes[n];
    const NodeTiming& t = ex.timings()[n];
    SCOPED_TRACE(node.name);
    EXPECT_EQ(t.cpuMs.size(), std::size_t(kFrames));
    const bool gl = node.issuesGlWork();
    if (!gl) {
      EXPECT_TRUE(t.gpuMs.empty());
      continue;
    }
    ++glNodes;
    EXPECT_EQ(t.gpuMs.size(), std::size_t(kFrames));
    // A node's GL time lies within its frame, which is at most the sum of all nodes' CPU times
    // of that frame plus the query reads; a loose bound that a garbage value breaks.
    double frame = 0;
    for (const NodeTiming& other : ex.timings())
      frame += std::accumulate(other.cpuMs.begin(), other.cpuMs.end(), 0.0);
    for (double ms : t.gpuMs) {
      EXPECT_GE(ms, 0.0);
      EXPECT_LT(ms, frame + 1000.0);
    }
  }
  EXPECT_GE(glNodes, 3);  // gbuffer, sm and at least the readbacks of the outputs
}

// The exported timings (diptych render --timings): every figure is a summary over the measured
// frames; GL nodes and transfers carry their own GL time and, apart, the wait for earlier nodes'
// GL work; CPU nodes carry neither. Per frame, the nodes' CPU times and waits are disjoint
// intervals inside the frame's wall time, so their sum cannot exceed it (before this, the wait
// sat inside the CPU time of the first node that synchronised).
TEST(ExecutorGlTiming, ExportKeepsEachNodesGlWaitApartAndSummarisesEveryFigure) {
  constexpr int kFrames = 4;
  const TimedRun run(shadowRecipe(), kFrames);
  const CompiledGraph& graph = run.graph;
  const GraphExecutor& ex = *run.ex;
  ASSERT_EQ(ex.frameMs().size(), std::size_t(kFrames));
  const nlohmann::json j = graphToJson(graph, &ex.timings());
  ASSERT_EQ(j["schedule"].size(), graph.nodes.size());
  int waits = 0;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const GraphNode& node = graph.nodes[n];
    const nlohmann::json& t = j["schedule"][n]["timing"];
    SCOPED_TRACE(node.name);
    const bool gl = node.issuesGlWork();
    std::vector<std::string> figures = {"cpu_ms", "process_cpu_ms"};
    if (gl)
      figures.insert(figures.end(), {"gpu_ms", "gl_wait_ms", "gl_wait_cpu_ms", "gl_completion_ms",
                                     "gl_completion_cpu_ms"});
    for (const std::string& f : figures) {
      ASSERT_TRUE(t.contains(f)) << f;
      EXPECT_EQ(t[f]["samples"], kFrames) << f;
      EXPECT_GE(t[f]["min"].get<double>(), 0.0) << f;
      EXPECT_LE(t[f]["min"].get<double>(), t[f]["median"].get<double>()) << f;
      EXPECT_LE(t[f]["median"].get<double>(), t[f]["max"].get<double>()) << f;
    }
    EXPECT_EQ(t.contains("gpu_ms"), gl);
    EXPECT_EQ(t.contains("gl_wait_ms"), gl);
    EXPECT_EQ(t.contains("gl_wait_cpu_ms"), gl);
    EXPECT_EQ(t.contains("gl_completion_cpu_ms"), gl);
    EXPECT_FALSE(t.contains("counters") && t["counters"].contains("process_cpu_ms"));
    waits += gl;
  }
  EXPECT_GE(waits, 3);
  for (int f = 0; f < kFrames; ++f) {
    double inside = 0;
    for (const NodeTiming& t : ex.timings())
      inside += t.cpuMs[f] + (t.glWaitMs.empty() ? 0.0 : t.glWaitMs[f]);
    EXPECT_LE(inside, ex.frameMs()[f]) << "frame " << f;
  }
}

// A GL node's work completes after the node returns; the wait for it, taken before the next GL
// node or at the frame's end, is charged to the node that issued the work (gl_completion_*), so
// per node process_cpu_ms + gl_completion_cpu_ms is its whole CPU cost. Each wait is one
// interval: the next GL node's gl_wait of a frame is the same figure as the previous GL node's
// completion, and the last GL node's completion (frame end) is inside the frame.
TEST(ExecutorGlTiming, TheWaitForANodesGlWorkIsChargedToThatNode) {
  constexpr int kFrames = 3;
  const TimedRun run(shadowRecipe(), kFrames);
  const CompiledGraph& graph = run.graph;
  const GraphExecutor& ex = *run.ex;
  std::vector<std::size_t> glNodes;
  for (std::size_t n = 0; n < graph.nodes.size(); ++n) {
    const GraphNode& node = graph.nodes[n];
    const NodeTiming& t = ex.timings()[n];
    if (node.issuesGlWork()) {
      glNodes.push_back(n);
      EXPECT_EQ(t.glCompletionMs.size(), std::size_t(kFrames)) << node.name;
      EXPECT_EQ(t.glCompletionCpuMs.size(), std::size_t(kFrames)) << node.name;
    } else {
      EXPECT_TRUE(t.glCompletionMs.empty()) << node.name << ": CPU nodes issue no GL work";
    }
  }
  ASSERT_GE(glNodes.size(), 3u);
  for (int f = 0; f < kFrames; ++f) {
    SCOPED_TRACE("frame " + std::to_string(f));
    EXPECT_EQ(ex.timings()[glNodes.front()].glWaitMs[f], 0.0)
        << "the previous frame's GL work completed inside that frame";
    for (std::size_t k = 1; k < glNodes.size(); ++k) {
      const NodeTiming& before = ex.timings()[glNodes[k - 1]];
      const NodeTiming& after = ex.timings()[glNodes[k]];
      SCOPED_TRACE(graph.nodes[glNodes[k]].name);
      if (graph.nodes[glNodes[k - 1]].kind == NodeKind::Readback) {
        // A readback's work is done when it returns; the executor takes its (empty) completion
        // at once, so the next GL node has nothing to wait for.
        EXPECT_EQ(after.glWaitMs[f], 0.0);
        continue;
      }
      EXPECT_EQ(before.glCompletionMs[f], after.glWaitMs[f]);
      EXPECT_EQ(before.glCompletionCpuMs[f], after.glWaitCpuMs[f]);
    }
    double inside = 0;
    for (const NodeTiming& t : ex.timings())
      inside += t.cpuMs[f] + (t.glCompletionMs.empty() ? 0.0 : t.glCompletionMs[f]);
    EXPECT_LE(inside, ex.frameMs()[f]);
  }
}

// GL work is submitted without waiting for it, so the compiler issues a GL pass before the CPU
// passes that do not depend on it (here listed after them), reads back first what those CPU
// passes need (the executor waits for all earlier GL work before a transfer), and the CPU passes
// then run while the GL pass's work is pending: the export names them, the timings measure it.
TEST(ExecutorGlTiming, CpuPassesRunBesideTheGlWorkOfAPassIssuedBeforeThem) {
  Recipe recipe = shadowRecipe();
  std::swap(recipe.passes[1], recipe.passes[2]);  // rt_shadows (CPU) listed before shadow_map
  constexpr int kFrames = 3;
  const TimedRun run(recipe, kFrames);
  const CompiledGraph& graph = run.graph;
  const GraphExecutor& ex = *run.ex;
  std::vector<std::string> names;
  for (const GraphNode& n : graph.nodes) names.push_back(n.name);
  EXPECT_EQ(names, (std::vector<std::string>{"gbuffer", "readback:gbuffer.hits", "sm", "rt",
                                             "readback:sm.visibility"}));
  const nlohmann::json j = graphToJson(graph, &ex.timings());
  EXPECT_EQ(j["schedule"][2]["overlapped_by"], nlohmann::json::array({"rt"}));
  EXPECT_FALSE(j["schedule"][1].contains("overlapped_by"))
      << "a readback's work is done when it returns";
  ASSERT_EQ(ex.timings()[2].glOverlapMs.size(), std::size_t(kFrames));
  for (int f = 0; f < kFrames; ++f) {
    EXPECT_GE(ex.timings()[2].glOverlapMs[f], ex.timings()[3].cpuMs[f])
        << "the wait for the shadow map's work starts after rt_shadows ran";
  }
}

// GlSync: on OSMesa (llvmpipe) Auto waits per node and says why; PerFrame waits only at the end
// of each frame (a GPU engine's pipelining: no gl_wait or completion per node, one frame wait)
// and computes the same signals.
TEST(ExecutorGlTiming, PerFrameSyncWaitsOnceAtTheFrameEndAndChangesNoSignal) {
  constexpr int kFrames = 2;
  const TimedRun perNode(shadowRecipe(), kFrames);
  EXPECT_EQ(perNode.ex->glSync(), GlSync::PerNode);
  EXPECT_NE(perNode.ex->glSyncReason().find("auto: software rasterizer llvmpipe"),
            std::string::npos)
      << perNode.ex->glSyncReason();
  EXPECT_TRUE(perNode.ex->frameGlWaitMs().empty());
  const TimedRun perFrame(shadowRecipe(), kFrames, GlSync::PerFrame);
  EXPECT_EQ(perFrame.ex->glSyncReason(), "frame (asked)");
  EXPECT_EQ(perFrame.ex->frameGlWaitMs().size(), std::size_t(kFrames));
  for (std::size_t n = 0; n < perFrame.graph.nodes.size(); ++n) {
    const NodeTiming& t = perFrame.ex->timings()[n];
    SCOPED_TRACE(perFrame.graph.nodes[n].name);
    EXPECT_TRUE(t.glWaitMs.empty());
    EXPECT_TRUE(t.glCompletionMs.empty());
    EXPECT_EQ(t.gpuMs.size(), perFrame.graph.nodes[n].issuesGlWork() ? std::size_t(kFrames) : 0u);
  }
  for (const char* signal : {"sm.visibility", "rt.visibility"})
    EXPECT_EQ(perFrame.ex->output(signal).words, perNode.ex->output(signal).words) << signal;
}
}  // namespace DIPTYCH_UNITY_ID
