// The shipped recipes: the JSON hybrid recipe and the C++ default are the same graph, and every
// recipe in samples/graphs parses and names only registered pass types.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine/graph/recipe.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

using namespace diptych;

TEST(Recipes, JsonHybridRecipeMatchesTheBuiltInOne) {
  const Recipe json = loadRecipe(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs/hybrid.json");
  const Recipe cpp = defaultHybridRecipe();
  ASSERT_EQ(json.passes.size(), cpp.passes.size());
  for (std::size_t i = 0; i < cpp.passes.size(); ++i) {
    EXPECT_EQ(json.passes[i].name, cpp.passes[i].name);
    EXPECT_EQ(json.passes[i].type, cpp.passes[i].type);
    EXPECT_EQ(json.passes[i].inputs, cpp.passes[i].inputs);
    EXPECT_EQ(json.passes[i].params, cpp.passes[i].params);
  }
  EXPECT_EQ(json.outputs, cpp.outputs);
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
