// The shadow_map producer of the light-visibility slot, measured against exact shadow rays
// (rt_shadows) on the same pixels: misclassified plane pixels outside a 2-pixel band around
// the exact shadow boundary.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "engine/scene/load.h"
#include "shadow_map_compare.h"

using namespace diptych;
using diptych::testing::compareShadows;
using nlohmann::json;

namespace {

const Scene& shadowSphere() {
  static const Scene scene =
      loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/shadow-sphere.json");
  return scene;
}
constexpr int kPlane = 0;  // the plane is objects[0] of shadow-sphere.json

}  // namespace

TEST(ShadowMapMeasure, Table) {
  for (int res : {256, 1024, 4096})
    for (const char* bias : {"none", "constant", "slope", "normal_offset", "receiver_plane", "adaptive"}) {
      const auto c = compareShadows(shadowSphere(), {{"resolution", res}, {"bias", bias}}, kPlane);
      std::printf("%5d %-15s considered %zu lit %zu falseShadow %zu falseLit %zu  mis %.4f%%  fs/lit %.4f%%\n",
                  res, bias, c.considered, c.exactLit, c.falseShadow, c.falseLit,
                  100 * c.misclassified(), 100 * c.falseShadowOfLit());
    }
}
TEST(ShadowMapMeasure, Where) {
  for (int res : {256, 1024}) {
    const auto c = compareShadows(shadowSphere(), {{"resolution", res}, {"bias", "none"}}, kPlane);
    int n = 0;
    for (int y = 0; y < c.height; ++y) {
      std::string row;
      for (int x = 0; x < c.width; x += 2) {
        const std::size_t i = std::size_t(y) * c.width + x;
        row += c.instance[i] != 1 ? ' ' : (c.exact[i] == 1 && c.map[i] < 0.5f) ? 'X' : c.exact[i] == 0 ? '#' : '.';
      }
      if (y % 4 == 0) std::printf("%s\n", row.c_str());
      (void)n;
    }
  }
}
