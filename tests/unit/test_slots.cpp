#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "passes/registry.h"
#include "passes/slots.h"

using namespace diptych;

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
  r.passes = {{.name = "g", .type = "gbuffer", .place = "passes[0]"},
              {.name = "shade",
               .type = "shade",
               .inputs = {{"visibility", "g.visibility"}},
               .place = "passes[1]"}};
  r.outputs = {"shade.color"};
  applySlotOverride(r, parseSlotOverride("visibility=rt_shadows:area_samples=4"), builtinPasses());
  ASSERT_EQ(r.passes.size(), 3u);
  EXPECT_EQ(r.passes[1].name, "visibility");
  EXPECT_EQ(r.passes[1].inputs.at("visibility"), "g.visibility");
  EXPECT_EQ(r.passes[2].inputs.at("light_visibility"), "visibility.visibility");
}
