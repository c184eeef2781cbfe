// The shipped recipes: the built-in default is samples/graphs/hybrid.json with each slot on its
// exact producer, and every recipe in samples/graphs parses and names only registered types.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "engine/graph/recipe.h"
#include "passes/registry.h"
#include "passes/slots.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

TEST(Recipes, TheBuiltInRecipeIsHybridJsonWithEverySlotOnItsExactProducer) {
  const Recipe json = loadRecipe(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs/hybrid.json");
  const Recipe builtIn = defaultHybridRecipe();
  EXPECT_NE(builtIn.file.find("hybrid.json"), std::string::npos) << builtIn.file;
  ASSERT_EQ(json.passes.size(), builtIn.passes.size());
  for (std::size_t i = 0; i < builtIn.passes.size(); ++i) {
    EXPECT_EQ(json.passes[i].type, builtIn.passes[i].type);
    EXPECT_EQ(json.passes[i].inputs, builtIn.passes[i].inputs);
  }
  const auto shade = std::find_if(builtIn.passes.begin(), builtIn.passes.end(),
                                  [](const RecipePass& p) { return p.type == "shade"; });
  ASSERT_NE(shade, builtIn.passes.end());
  for (const TechniqueSlot& slot : techniqueSlots()) {
    ASSERT_TRUE(shade->inputs.count(slot.shadeInput)) << slot.name;
    const std::string source = shade->inputs.at(slot.shadeInput);
    const std::string producer = source.substr(0, source.find('.'));
    EXPECT_EQ(source, producer + "." + slot.signal);
    const auto pass = std::find_if(builtIn.passes.begin(), builtIn.passes.end(),
                                   [&](const RecipePass& p) { return p.name == producer; });
    ASSERT_NE(pass, builtIn.passes.end());
    EXPECT_EQ(pass->type, slot.exact) << slot.name;
  }
}

TEST(Recipes, EverySampleRecipeUsesRegisteredPassTypes) {
  int count = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs")) {
    if (entry.path().extension() != ".json") continue;
    const Recipe recipe = loadRecipe(entry.path());
    for (const RecipePass& pass : recipe.passes)
      EXPECT_NE(builtinPasses().find(pass.type), nullptr) << entry.path() << ": " << pass.type;
    ++count;
  }
  EXPECT_GE(count, 1);
}

}  // namespace DIPTYCH_UNITY_ID
