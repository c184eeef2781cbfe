// The shadow-map lookup's 3x3 PCF by four textureGather (shaders/shadow_map_lookup.frag
// pcf3Gathered, ShadowMapGl::gatherPcf) gives the visibility of the nine-texelFetch loop bit for
// bit, for every bias mode that takes the gathered path, at a coarse and a fine map, on a point
// light (cube maps: the interior pass gathers, the edge pass keeps the loop). The frame must
// hold lit, shadowed and penumbra pixels, so that the comparison covers every count of lit taps.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/gl/shader.h"

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "passes/raster/shadow_map_gl.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

CpuImage visibility(const Scene& scene, bool gather, const std::string& bias, int resolution) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "sm",
       .type = "shadow_map",
       .params = {{"resolution", resolution}, {"bias", bias}, {"filter", "pcf"}, {"kernel", 3}},
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[1]"}};
  const CompiledGraph graph = compileGraph(
      recipe, builtinPasses(), scene, FrameSettings{160, 120, scene.camera}, {"sm.visibility"});
  RenderWorld world(scene, &gl::testing::osmesaContext());
  world.glCached<shadowmap::ShadowMapGl>().gatherPcf = gather;
  GraphExecutor ex(graph, world);
  ex.runFrame();
  return ex.output("sm.visibility");
}

TEST(ShadowLookup, GatheredPcfEqualsNineFetches) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  ASSERT_EQ(scene.lights[0].type, LightType::Point);  // a cube map: the interior pass gathers
  for (const char* bias : {"none", "constant", "slope", "normal_offset"})
    for (int resolution : {64, 1024}) {
      SCOPED_TRACE(std::string(bias) + " " + std::to_string(resolution));
      const CpuImage gathered = visibility(scene, true, bias, resolution);
      const CpuImage fetched = visibility(scene, false, bias, resolution);
      ASSERT_EQ(gathered.words.size(), fetched.words.size());
      int differ = 0, lit = 0, shadowed = 0, penumbra = 0;
      for (int y = 0; y < gathered.desc.height; ++y)
        for (int x = 0; x < gathered.desc.width; ++x) {
          const float v = gathered.f(x, y, 0);
          differ += v != fetched.f(x, y, 0) ? 1 : 0;
          lit += v == 1.f ? 1 : 0;
          shadowed += v == 0.f ? 1 : 0;
          penumbra += v > 0.f && v < 1.f ? 1 : 0;
        }
      EXPECT_EQ(differ, 0);
      EXPECT_GT(lit, 1000);
      EXPECT_GT(shadowed, 100);
      EXPECT_GT(penumbra, 20);
    }
}

// The comparison above would pass if the gathered path never ran. With a copy of the shaders
// whose gathered branch returns 0.25 (no count of nine taps gives it), most covered pixels read
// 0.25: the interior pass takes that branch.
TEST(ShadowLookup, TheGatheredPathIsTakenByTheInteriorPass) {
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  const std::filesystem::path probe =
      std::filesystem::temp_directory_path() / ("diptych-gather-probe-" + std::to_string(getpid()));
  std::filesystem::remove_all(probe);
  std::filesystem::copy(gl::shaderDirectory(), probe, std::filesystem::copy_options::recursive);
  std::ifstream in(probe / "shadow_map_lookup.frag");
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  std::string source = text.str();
  const std::string call = "return pcf3Gathered();";
  ASSERT_NE(source.find(call), std::string::npos);
  source.replace(source.find(call), call.size(), "return 0.25;");
  std::ofstream(probe / "shadow_map_lookup.frag") << source;
  ::setenv("DIPTYCH_SHADER_DIR", probe.c_str(), 1);
  const CpuImage probed = visibility(scene, true, "slope", 1024);
  ::unsetenv("DIPTYCH_SHADER_DIR");
  std::filesystem::remove_all(probe);
  int quarter = 0;
  for (int y = 0; y < probed.desc.height; ++y)
    for (int x = 0; x < probed.desc.width; ++x) quarter += probed.f(x, y, 0) == 0.25f ? 1 : 0;
  EXPECT_GT(quarter, 1000);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
