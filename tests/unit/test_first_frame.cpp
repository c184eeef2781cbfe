// A run's first frame against a steady one (GraphExecutor::MeasuredRun, issue 9: one-time costs
// are reported apart, never inside a frame). A first frame pays for work that no one records as
// one-time (a GL driver compiling a program at its first draw, first-touch pages); the executor
// tells that remainder apart from the one-time work the world did record, per node. Passes
// defined here do a known amount of each on their first execute (sleeps, so that the lower
// bounds asserted hold on a loaded machine; nothing asserts how fast anything runs).
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "engine/core/timing.h"
#include "engine/graph/executor.h"
#include "engine/graph/export.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/recipe.h"
#include "engine/graph/render_world.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr double kRecordedMs = 60, kUnrecordedMs = 200;

// On its first execute: kRecordedMs of work recorded as one-time, kUnrecordedMs not recorded.
class FirstUsePass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.f));
  }
  void execute(PassContext& c) override {
    if (!used_) {
      const Stopwatch clock;
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(kRecordedMs));
      c.world().addOneTime("first-use table", clock.milliseconds());
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(kUnrecordedMs));
      used_ = true;
    }
    c.cpuWrite(out_).fill(vec4(1.f));
  }

 private:
  bool used_ = false;
  ResourceId out_ = kNoResource;
};

// The same work every frame.
class SteadyPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    in_ = b.read("in", Format::R32F);
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.f));
  }
  void execute(PassContext& c) override { c.cpuWrite(out_).fill(vec4(c.cpuRead(in_).f(0, 0, 0))); }

 private:
  ResourceId in_ = kNoResource, out_ = kNoResource;
};

CompiledGraph graph(const Scene& scene) {
  PassRegistry r;
  r.add<FirstUsePass>({.name = "first_use", .summary = "one-time work on first execute"});
  r.add<SteadyPass>({.name = "steady", .summary = "the same work every frame"});
  const Recipe recipe = parseRecipe(nlohmann::json::parse(R"({"passes": [
      {"name": "a", "type": "first_use"},
      {"name": "b", "type": "steady", "inputs": {"in": "a.out"}}],
      "outputs": ["b.out"]})"),
                                    "first_frame.json");
  return compileGraph(recipe, r, scene, FrameSettings{.width = 8, .height = 4});
}

std::size_t nodeNamed(const CompiledGraph& g, const std::string& name) {
  for (std::size_t n = 0; n < g.nodes.size(); ++n)
    if (g.nodes[n].name == name) return n;
  ADD_FAILURE() << "no node " << name;
  return 0;
}

TEST(FirstFrame, UnrecordedFirstUseWorkIsToldApartFromRecordedOneTimeWork) {
  const Scene scene;
  RenderWorld world(scene);
  const CompiledGraph g = graph(scene);
  GraphExecutor ex(g, world);
  const GraphExecutor::MeasuredRun run = ex.runMeasured(1, 3);
  const std::size_t a = nodeNamed(g, "a"), b = nodeNamed(g, "b");
  ASSERT_EQ(run.firstUseMs.size(), g.nodes.size());

  // The recorded part is the world's one-time entry, found in the first frame...
  ASSERT_EQ(run.oneTimeMs.count("first-use table"), 1u);
  EXPECT_GE(run.oneTimeMs.at("first-use table"), kRecordedMs);
  EXPECT_DOUBLE_EQ(run.firstFrameOneTimeMs, run.oneTimeMs.at("first-use table"));
  // ...and the unrecorded part is the remainder, charged to the node that did it and to no
  // other: its first-use time holds the unrecorded sleep but not the recorded one.
  EXPECT_GE(run.firstUseMs[a], kUnrecordedMs);
  EXPECT_LT(run.firstUseMs[a], run.firstFrameMs - run.firstFrameOneTimeMs);
  EXPECT_LT(run.firstUseMs[b], kUnrecordedMs / 2) << "b did the same work in every frame";
  EXPECT_GE(run.firstFrameUnrecordedMs(), kUnrecordedMs);
  EXPECT_GE(run.firstFrameMs, kRecordedMs + kUnrecordedMs);
  EXPECT_LT(run.steadyFrameMs, run.firstFrameMs);

  // Reported per node, the steady node left out.
  const nlohmann::json j = firstFrameJson(g, run);
  EXPECT_DOUBLE_EQ(j.at("unrecorded_ms").get<double>(), run.firstFrameUnrecordedMs());
  EXPECT_TRUE(j.at("first_use_ms").contains("a"));
  EXPECT_FALSE(j.at("first_use_ms").contains("b"));
  EXPECT_NE(firstFrameLine(g, run).find("(by node: a "), std::string::npos)
      << firstFrameLine(g, run);

  // Each node's one-time work, per frame: all of it in a's first frame.
  GraphExecutor again(g, world);
  again.runFrame();
  for (const NodeTiming& t : again.timings()) EXPECT_EQ(t.oneTimeMs, std::vector<double>{0.0});
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
