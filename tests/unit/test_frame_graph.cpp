// Frame-graph compiler and executor tests with real CPU passes defined here.
#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/graph/executor.h"
#include "engine/graph/export.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

// Writes a constant image; parameter "value".
class ConstantPass : public Pass {
 public:
  static ParamSchema schema() { return {ParamSpec::number("value", 1.0, -1e9, 1e9, "the value")}; }
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    value_ = float(b.params().number("value"));
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(-7.f));
  }
  void execute(PassContext& c) override { c.cpuWrite(out_).fill(vec4(value_)); }

 private:
  float value_ = 1.f;
  ResourceId out_ = kNoResource;
};

// out = a + b (b optional).
class AddPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    a_ = b.read("a", Format::R32F);
    b_ = b.readOptional("b", Format::R32F);
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.f));
  }
  void execute(PassContext& c) override {
    const CpuImage& a = c.cpuRead(a_);
    CpuImage& out = c.cpuWrite(out_);
    for (int y = 0; y < out.desc.height; ++y)
      for (int x = 0; x < out.desc.width; ++x)
        out.setF(x, y, 0, a.f(x, y, 0) + (b_ == kNoResource ? 0.f : c.cpuRead(b_).f(x, y, 0)));
  }

 private:
  ResourceId a_ = kNoResource, b_ = kNoResource, out_ = kNoResource;
};

// Needs a transmissive material; doubles its input in place (a versioned write).
class NeedsGlassPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    b.needs(SceneNeed::TransmissiveMaterial);
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.25f));
  }
  void execute(PassContext& c) override { c.cpuWrite(out_).fill(vec4(100.f)); }

 private:
  ResourceId out_ = kNoResource;
};

class ScalePass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override { out_ = b.modify("in", "out", Format::R32F); }
  void execute(PassContext& c) override {
    for (auto& w : c.cpuWrite(out_).words)
      w = std::bit_cast<std::uint32_t>(2.f * std::bit_cast<float>(w));
  }

 private:
  ResourceId out_ = kNoResource;
};

// Reads a resource it never declared: the executor must refuse.
class SneakyPass : public Pass {
 public:
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& b) override {
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.f));
  }
  void execute(PassContext& c) override { c.cpuRead(ResourceId(0)); }

 private:
  ResourceId out_ = kNoResource;
};

// A GL-domain producer, used only to check transfer insertion at compile time.
class FakeGlProducer : public Pass {
 public:
  Domain domain() const override { return Domain::Gl; }
  void setup(PassBuilder& b) override {
    out_ = b.write("out", {Format::R32F, b.frame().width, b.frame().height}, vec4(0.f));
  }
  void execute(PassContext&) override {}

 private:
  ResourceId out_ = kNoResource;
};

PassRegistry testRegistry() {
  PassRegistry r;
  r.add<ConstantPass>({.name = "constant", .summary = "constant image"});
  r.add<AddPass>({.name = "add", .summary = "a + b"});
  r.add<NeedsGlassPass>({.name = "needs_glass", .summary = "culled without glass"});
  r.add<ScalePass>({.name = "scale", .summary = "in-place doubling"});
  r.add<SneakyPass>({.name = "sneaky", .summary = "undeclared access"});
  r.add<FakeGlProducer>({.name = "gl_producer", .summary = "gl domain"});
  return r;
}

Recipe recipe(const std::string& json) {
  return parseRecipe(nlohmann::json::parse(json), "test.json");
}

Scene sceneWithTriangle(float kt) {
  Scene s;
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.indices = {0, 1, 2};
  m.material = 0;
  s.meshes.push_back(m);
  s.instances.push_back({"tri", 0, mat4(1.f)});
  Material mat;
  mat.kt = kt;
  s.materials.push_back(mat);
  return s;
}

FrameSettings smallFrame() {
  return {.width = 4, .height = 3};
}

std::string errorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(FrameGraph, ExecutesInDependencyOrderAndProducesOutput) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [
      {"name": "sum", "type": "add", "inputs": {"a": "one.out", "b": "two.out"}},
      {"name": "one", "type": "constant", "params": {"value": 1}},
      {"name": "two", "type": "constant", "params": {"value": 2}}],
    "outputs": ["sum.out"]})"),
                              testRegistry(), scene, smallFrame());
  ASSERT_EQ(g.nodes.size(), 3u);
  EXPECT_EQ(g.nodes.back().name, "sum");
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  EXPECT_FLOAT_EQ(ex.output("sum.out").f(3, 2, 0), 3.f);
  EXPECT_EQ(ex.timings().size(), g.nodes.size());
  EXPECT_EQ(ex.timings()[0].cpuMs.size(), 1u);
}

TEST(FrameGraph, CullsPassesNoOutputNeedsWithReason) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [
      {"name": "one", "type": "constant"}, {"name": "unused", "type": "constant"}],
    "outputs": ["one.out"]})"),
                              testRegistry(), scene, smallFrame());
  EXPECT_FALSE(g.passes[PassIndex(0)].culled);
  EXPECT_TRUE(g.passes[PassIndex(1)].culled);
  EXPECT_EQ(g.passes[PassIndex(1)].cullReason, "output not requested");
  EXPECT_EQ(g.nodes.size(), 1u);
}

TEST(FrameGraph, SceneDrivenCullingFeedsConsumersTheDefault) {
  const char* json = R"({"passes": [
      {"name": "glass", "type": "needs_glass"},
      {"name": "sum", "type": "add", "inputs": {"a": "glass.out"}}],
    "outputs": ["sum.out"]})";
  const Scene noGlass = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(json), testRegistry(), noGlass, smallFrame());
  EXPECT_TRUE(g.passes[PassIndex(0)].culled);
  EXPECT_EQ(g.passes[PassIndex(0)].cullReason, "scene has no transmissive materials");
  ASSERT_EQ(g.nodes.size(), 2u);
  EXPECT_EQ(g.nodes[0].kind, NodeKind::Default);
  RenderWorld world(noGlass);
  GraphExecutor ex(g, world);
  ex.runFrame();
  EXPECT_FLOAT_EQ(ex.output("sum.out").f(0, 0, 0), 0.25f);  // the declared fallback

  const Scene glass = sceneWithTriangle(0.9f);
  const auto g2 = compileGraph(recipe(json), testRegistry(), glass, smallFrame());
  EXPECT_FALSE(g2.passes[PassIndex(0)].culled);
  RenderWorld world2(glass);
  GraphExecutor ex2(g2, world2);
  ex2.runFrame();
  EXPECT_FLOAT_EQ(ex2.output("sum.out").f(0, 0, 0), 100.f);
}

TEST(FrameGraph, CycleIsAnErrorNamingThePasses) {
  const Scene scene = sceneWithTriangle(0.f);
  const std::string e = errorOf([&] {
    compileGraph(recipe(R"({"passes": [
        {"name": "a", "type": "add", "inputs": {"a": "b.out"}},
        {"name": "b", "type": "add", "inputs": {"a": "a.out"}}], "outputs": ["a.out"]})"),
                 testRegistry(), scene, smallFrame());
  });
  EXPECT_NE(e.find("test.json"), std::string::npos) << e;
  EXPECT_NE(e.find("cycle"), std::string::npos) << e;
  EXPECT_NE(e.find("a -> b -> a"), std::string::npos) << e;
}

TEST(FrameGraph, ReadOfNeverWrittenResourceNamesPassAndResource) {
  const Scene scene = sceneWithTriangle(0.f);
  const std::string e = errorOf([&] {
    compileGraph(recipe(R"({"passes": [{"name": "one", "type": "constant"},
        {"name": "sum", "type": "add", "inputs": {"a": "one.missing"}}], "outputs": ["sum.out"]})"),
                 testRegistry(), scene, smallFrame());
  });
  EXPECT_NE(e.find("passes[1].inputs.a"), std::string::npos) << e;
  EXPECT_NE(e.find("'one.missing', which is never written"), std::string::npos) << e;
  EXPECT_NE(e.find("one.out"), std::string::npos) << e;  // says what is written instead
}

TEST(FrameGraph, RecipeDefectsAreNamedErrors) {
  const Scene scene = sceneWithTriangle(0.f);
  auto compile = [&](const std::string& json) {
    return errorOf([&] { compileGraph(recipe(json), testRegistry(), scene, smallFrame()); });
  };
  EXPECT_NE(compile(R"({"passes": [{"type": "nope"}], "outputs": ["nope.out"]})")
                .find("unknown pass type 'nope'"),
            std::string::npos);
  EXPECT_NE(
      compile(
          R"({"passes": [{"type": "constant", "params": {"valeu": 1}}], "outputs": ["constant.out"]})")
          .find("passes[0].params.valeu: unknown parameter"),
      std::string::npos);
  EXPECT_NE(
      compile(
          R"({"passes": [{"type": "constant", "params": {"value": "x"}}], "outputs": ["constant.out"]})")
          .find("expected a number"),
      std::string::npos);
  EXPECT_NE(compile(R"({"passes": [{"type": "add"}], "outputs": ["add.out"]})")
                .find("input 'a' is not connected"),
            std::string::npos);
  EXPECT_NE(
      compile(
          R"({"passes": [{"type": "constant"}, {"type": "add", "inputs": {"a": "constant.out", "zzz": "constant.out"}}], "outputs": ["add.out"]})")
          .find("'zzz' is not an input"),
      std::string::npos);
  EXPECT_NE(compile(R"({"passes": [{"type": "constant"}], "outputs": ["constant.nothing"]})")
                .find("output 'constant.nothing' is never written"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              parseRecipe(nlohmann::json::parse(R"({"passes": [], "outputs": []})"), "r.json");
            }).find("r.json: passes"),
            std::string::npos);
  EXPECT_NE(
      errorOf([] { loadRecipe("/nonexistent/recipe.json"); }).find("/nonexistent/recipe.json"),
      std::string::npos);
}

TEST(FrameGraph, UndeclaredAccessAtExecuteIsAnError) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [{"name": "one", "type": "constant"},
      {"name": "s", "type": "sneaky"}, {"name": "sum", "type": "add", "inputs": {"a": "one.out", "b": "s.out"}}],
    "outputs": ["sum.out"]})"),
                              testRegistry(), scene, smallFrame());
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  const std::string e = errorOf([&] { ex.runFrame(); });
  EXPECT_NE(e.find("pass 's' read resource 'one.out' without declaring it"), std::string::npos)
      << e;
}

TEST(FrameGraph, LifetimesAllowPoolReuse) {
  // chain: c1 -> a1 -> a2 -> a3; c1.out dies after a1, so a2 can reuse its slot.
  const Scene scene = sceneWithTriangle(0.f);
  const auto g =
      compileGraph(recipe(R"({"passes": [{"name": "c1", "type": "constant", "params": {"value": 1}},
      {"name": "a1", "type": "add", "inputs": {"a": "c1.out"}},
      {"name": "a2", "type": "add", "inputs": {"a": "a1.out"}},
      {"name": "a3", "type": "add", "inputs": {"a": "a2.out", "b": "a2.out"}}],
    "outputs": ["a3.out"]})"),
                   testRegistry(), scene, smallFrame());
  EXPECT_EQ(g.storages.size(), 4u);
  EXPECT_LT(g.pool.size(), g.storages.size());
  EXPECT_LT(g.bytesWithReuse(), g.bytesWithoutReuse());
  // No two storages sharing a slot have overlapping lifetimes.
  for (std::size_t i = 0; i < g.storages.size(); ++i)
    for (std::size_t j = i + 1; j < g.storages.size(); ++j)
      if (g.storages[i].poolSlot == g.storages[j].poolSlot) {
        EXPECT_TRUE(g.storages[i].lastNode < g.storages[j].firstNode ||
                    g.storages[j].lastNode < g.storages[i].firstNode);
      }
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  EXPECT_FLOAT_EQ(ex.output("a3.out").f(1, 1, 0), 2.f);  // reuse did not clobber live data
}

TEST(FrameGraph, InPlaceModifyCreatesANewVersionOnTheSameStorage) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g =
      compileGraph(recipe(R"({"passes": [{"name": "c", "type": "constant", "params": {"value": 3}},
      {"name": "twice", "type": "scale", "inputs": {"in": "c.out"}}], "outputs": ["twice.out"]})"),
                   testRegistry(), scene, smallFrame());
  const ResourceId in = *g.findResource("c.out"), out = *g.findResource("twice.out");
  EXPECT_EQ(g.resources[out].version, 1);
  EXPECT_EQ(g.storageOf.at({in, Domain::Cpu}), g.storageOf.at({out, Domain::Cpu}));
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  EXPECT_FLOAT_EQ(ex.output("twice.out").f(0, 0, 0), 6.f);
}

TEST(FrameGraph, CrossDomainEdgesGetTransferNodes) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [{"name": "raster", "type": "gl_producer"},
      {"name": "sum", "type": "add", "inputs": {"a": "raster.out"}}], "outputs": ["sum.out", "raster.out"]})"),
                              testRegistry(), scene, smallFrame());
  int readbacks = 0;
  for (const GraphNode& n : g.nodes) readbacks += n.kind == NodeKind::Readback;
  EXPECT_EQ(readbacks, 1);  // one readback serves both the CPU pass and the output
  EXPECT_EQ(g.nodes[1].name, "readback:raster.out");
  EXPECT_TRUE(g.usesGl());
  RenderWorld world(scene);
  EXPECT_THROW(GraphExecutor(g, world), Error);  // GL work needs a context
}

// An optional input whose producer the scene culls leaves the frame: no default fill is
// scheduled, the consumer does not read it (it sees kNoResource, so b = 0 here, not the
// fallback 0.25), and the export names what was left out and why.
TEST(FrameGraph, OptionalInputOfASceneCulledProducerLeavesTheFrame) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [{"name": "glass", "type": "needs_glass"},
      {"name": "one", "type": "constant"}, {"name": "sum", "type": "add", "inputs": {"a": "one.out", "b": "glass.out"}}],
    "outputs": ["sum.out"]})"),
                              testRegistry(), scene, smallFrame());
  for (const GraphNode& n : g.nodes) {
    EXPECT_NE(n.name, "default:glass.out");
    EXPECT_NE(n.name, "glass");
  }
  ASSERT_EQ(g.nodes.size(), 2u);  // one, sum
  const GraphPass& sum = g.passes[PassIndex(2)];
  ASSERT_EQ(sum.reads.size(), 1u);
  EXPECT_EQ(g.resources[sum.reads[0]].name, "one.out");
  ASSERT_EQ(sum.inputsLeftOut.size(), 1u);
  EXPECT_EQ(sum.inputsLeftOut[0], "b <- glass.out (scene has no transmissive materials)");
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  EXPECT_EQ(ex.output("sum.out").f(0, 0, 0), 1.f);
  const nlohmann::json j = graphToJson(g, nullptr);
  EXPECT_EQ(j["passes"][2]["inputs_left_out"][0], sum.inputsLeftOut[0]);
}

TEST(FrameGraph, ExportsDotAndJsonWithCullReasonsMemoryAndTimings) {
  const Scene scene = sceneWithTriangle(0.f);
  const auto g = compileGraph(recipe(R"({"passes": [{"name": "glass", "type": "needs_glass"},
      {"name": "one", "type": "constant"}, {"name": "sum", "type": "add", "inputs": {"a": "glass.out", "b": "one.out"}}],
    "outputs": ["sum.out"]})"),
                              testRegistry(), scene, smallFrame());
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  ex.runFrame();
  const nlohmann::json j = graphToJson(g, &ex.timings());
  ASSERT_EQ(j["culled"].size(), 1u);
  EXPECT_EQ(j["culled"][0]["pass"], "glass");
  EXPECT_EQ(j["culled"][0]["reason"], "scene has no transmissive materials");
  EXPECT_EQ(j["schedule"].size(), g.nodes.size());
  EXPECT_EQ(j["schedule"][1]["kind"], "default");  // just before its first reader
  EXPECT_EQ(j["schedule"][1]["name"], "default:glass.out");
  EXPECT_EQ(j["schedule"].back()["timing"]["cpu_ms"]["samples"], 2);
  // Every node reports the CPU time of all the process's threads over it (benchmarks.md).
  // A median over the measured frames like every other figure, not a counter of the last frame.
  for (const auto& node : j["schedule"]) {
    EXPECT_FALSE(node["timing"].contains("counters") &&
                 node["timing"]["counters"].contains("process_cpu_ms"));
    const auto& p = node["timing"]["process_cpu_ms"];
    EXPECT_EQ(p["samples"], 2) << node["name"];
    EXPECT_GE(p["min"].get<double>(), 0.0) << node["name"];
    EXPECT_LE(p["min"].get<double>(), p["median"].get<double>()) << node["name"];
    EXPECT_LE(p["median"].get<double>(), p["max"].get<double>()) << node["name"];
    EXPECT_FALSE(node["timing"].contains("gl_wait_ms")) << "CPU nodes never wait for the GL";
  }
  EXPECT_GT(j["memory"]["bytes_without_reuse"].get<std::size_t>(), 0u);
  EXPECT_EQ(j["edges"].size(), 2u);
  const std::string dot = graphToDot(g, &ex.timings());
  EXPECT_NE(dot.find("digraph frame"), std::string::npos);
  EXPECT_NE(dot.find("culled: scene has no transmissive materials"), std::string::npos);
  EXPECT_NE(dot.find("\"one\" -> \"sum\""), std::string::npos);
  EXPECT_NE(dot.find(" ms"), std::string::npos);
}
}  // namespace DIPTYCH_UNITY_ID
