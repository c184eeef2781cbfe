#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "engine/core/error.h"
#include "engine/graph/frame_graph.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "passes/slots.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
// The resource feeding shade's input for `slot`.
std::string slotSignalOf(const Recipe& r, const TechniqueSlot& slot) {
  for (const RecipePass& p : r.passes)
    if (p.type == "shade") return p.inputs.at(slot.shadeInput);
  return "";
}

TEST(Slots, ParsesTypeAndTypedParameters) {
  const SlotOverride o = parseSlotOverride("reflection=rt_reflection:depth=3,fast=true,mode=pcf5");
  EXPECT_EQ(o.slot, "reflection");
  EXPECT_EQ(o.type, "rt_reflection");
  EXPECT_EQ(o.params["depth"], 3.0);
  EXPECT_EQ(o.params["fast"], true);
  EXPECT_EQ(o.params["mode"], "pcf5");
  EXPECT_TRUE(parseSlotOverride("transmission=rt_transmission").params.empty());
}

TEST(Slots, MalformedOverridesAreNamedErrors) {
  for (const char* bad :
       {"reflection", "=rt_reflection", "reflection=", "reflection=rt_reflection:depth",
        "reflection=rt_reflection:=3", "reflection=rt_reflection:a=1,,b=2"}) {
    try {
      parseSlotOverride(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--slot"), std::string::npos) << e.what();
    }
  }
}

TEST(Slots, OverrideReplacesTheProducerFeedingShade) {
  Recipe r = defaultHybridRecipe();
  applySlotOverride(r, parseSlotOverride("reflection=rt_reflection:depth=2"), builtinPasses());
  const auto it = std::find_if(r.passes.begin(), r.passes.end(),
                               [](const RecipePass& p) { return p.name == "reflection"; });
  ASSERT_NE(it, r.passes.end());
  EXPECT_EQ(it->params["depth"], 2.0);
  EXPECT_THROW(applySlotOverride(r, parseSlotOverride("reflection=warp"), builtinPasses()),
               InputError);
  EXPECT_THROW(applySlotOverride(r, parseSlotOverride("sound=rt_reflection"), builtinPasses()),
               InputError);
}

TEST(Slots, OverrideAddsAProducerWhenTheRecipeHasNone) {
  Recipe r;
  r.passes = {
      {.name = "g", .type = "gbuffer", .place = "passes[0]"},
      {.name = "shade", .type = "shade", .inputs = {{"hits", "g.hits"}}, .place = "passes[1]"}};
  r.outputs = {"shade.color"};
  applySlotOverride(r, parseSlotOverride("visibility=rt_shadows:area_samples=4"), builtinPasses());
  ASSERT_EQ(r.passes.size(), 3u);
  EXPECT_EQ(r.passes[1].name, "visibility");
  EXPECT_EQ(r.passes[1].inputs.at("hits"), "g.hits");
  EXPECT_EQ(r.passes[2].inputs.at("light_visibility"), "visibility.visibility");
}

// The crash found by reading: shade's slot input names a pass the recipe lacks.
TEST(Slots, OverrideOfAShadeInputFromAMissingPassIsANamedError) {
  Recipe r = defaultHybridRecipe();
  r.passes.erase(r.passes.begin() + 1);  // "shadows", still read by shade.light_visibility
  try {
    applySlotOverride(r, parseSlotOverride("visibility=shadow_map"), builtinPasses());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("no pass named 'shadows'"), std::string::npos) << e.what();
    EXPECT_NE(e.place().find("light_visibility"), std::string::npos) << e.what();
  }
}

// Every registered producer, swapped into the hybrid recipe through its slot, compiles: its
// setup reads exactly the parameters its schema declares, and writes the slot's signal.
TEST(Slots, EveryRegisteredProducerCompilesInItsSlot) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  const FrameSettings frame{32, 24, scene.camera};
  int producers = 0;
  for (const TechniqueSlot& slot : techniqueSlots()) {
    for (const PassTypeInfo* type : builtinPasses().producersOf(slot.name)) {
      Recipe r = defaultHybridRecipe();
      applySlotOverride(r, parseSlotOverride(slot.name + "=" + type->name), builtinPasses());
      const std::string signal = slotSignalOf(r, slot);
      const CompiledGraph g = compileGraph(r, builtinPasses(), scene, frame, {signal});
      const GraphResource& res = g.resources[*g.findResource(signal)];
      EXPECT_EQ(res.desc.format, slot.format) << type->name;
      EXPECT_EQ(res.desc.layers, slot.layerPerLight ? int(scene.lights.size()) : 1) << type->name;
      ++producers;
    }
  }
  EXPECT_EQ(producers, int(builtinPasses().all().size()) - 5);  // all but gbuffer, shade, 3 refs
}

TEST(Slots, SchemaDefaultsAndRangesComeFromTheRegistry) {
  const PassTypeInfo* sm = builtinPasses().find("shadow_map");
  ASSERT_NE(sm, nullptr);
  EXPECT_EQ(sm->slot, "visibility");
  const auto bias = std::find_if(sm->params.begin(), sm->params.end(),
                                 [](const ParamSpec& p) { return p.name == "bias"; });
  ASSERT_NE(bias, sm->params.end());
  EXPECT_EQ(bias->fallback, "slope");
  EXPECT_EQ(bias->choices.size(), 6u);
  // A recipe value outside the schema's range is refused with the range.
  Recipe r = defaultHybridRecipe();
  applySlotOverride(r, parseSlotOverride("visibility=shadow_map:resolution=8"), builtinPasses());
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  try {
    compileGraph(r, builtinPasses(), scene, {32, 24, scene.camera});
    ADD_FAILURE() << "accepted resolution=8";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("params.resolution: value 8"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("[16.0, 16384.0]"), std::string::npos) << e.what();
  }
}
}  // namespace DIPTYCH_UNITY_ID
