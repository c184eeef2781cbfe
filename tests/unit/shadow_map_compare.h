#pragma once
// Test support for the shadow_map pass: run gbuffer + rt_shadows + shadow_map side by side on
// the same pixels and classify the shadow map against the exact ray-traced visibility.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/graph/executor.h"
#include "engine/graph/frame_graph.h"
#include "engine/graph/render_world.h"
#include "gl_test_context.h"
#include "passes/registry.h"

namespace diptych::testing {

struct ShadowComparison {
  int width = 0, height = 0, layers = 0;
  std::vector<float> map, exact;        // [layer][y][x]
  std::vector<std::uint32_t> instance;  // per pixel: instance + 1, 0 = background
  // Classification of `instance` pixels outside the 2-pixel band around the exact boundary.
  std::size_t considered = 0, exactLit = 0, falseShadow = 0, falseLit = 0, band = 0;
  std::size_t fractional = 0;  // considered + band pixels with a map value strictly in (0, 1)
  bool finiteInUnitRange = true;
  double misclassified() const {
    return considered ? double(falseShadow + falseLit) / double(considered) : 0.0;
  }
  double falseShadowOfLit() const {
    return exactLit ? double(falseShadow) / double(exactLit) : 0.0;
  }
};

// `params`: the shadow_map pass parameters. Classifies light `layer` on pixels of `instance`.
inline ShadowComparison compareShadows(const Scene& scene, const nlohmann::json& params,
                                       int instance, int width = 320, int height = 240,
                                       int layer = 0) {
  Recipe recipe;
  recipe.passes = {
      {.name = "gbuffer", .type = "gbuffer", .place = "passes[0]"},
      {.name = "rt",
       .type = "rt_shadows",
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[1]"},
      {.name = "sm",
       .type = "shadow_map",
       .params = params,
       .inputs = {{"hits", "gbuffer.hits"}},
       .place = "passes[2]"},
  };
  const CompiledGraph graph =
      compileGraph(recipe, builtinPasses(), scene, FrameSettings{width, height, scene.camera},
                   {"sm.visibility", "rt.visibility", "gbuffer.hits"});
  gl::testing::osmesaContext();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  GraphExecutor ex(graph, world);
  ex.runFrame();
  const CpuImage& sm = ex.output("sm.visibility");
  const CpuImage& rt = ex.output("rt.visibility");
  const CpuImage& gb = ex.output("gbuffer.hits");

  ShadowComparison c;
  c.width = width;
  c.height = height;
  c.layers = sm.desc.layers;
  for (int l = 0; l < c.layers; ++l)
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const float v = sm.f(x, y, 0, l);
        c.finiteInUnitRange = c.finiteInUnitRange && std::isfinite(v) && v >= 0.f && v <= 1.f;
        c.map.push_back(v);
        c.exact.push_back(rt.f(x, y, 0, l));
      }
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) c.instance.push_back(gb.words[gb.index(x, y, 0, 0)]);

  const std::size_t base = std::size_t(layer) * width * height;
  const auto exactAt = [&](int x, int y) { return c.exact[base + std::size_t(y) * width + x]; };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (c.instance[std::size_t(y) * width + x] != std::uint32_t(instance + 1)) continue;
      const float e = exactAt(x, y), m = c.map[base + std::size_t(y) * width + x];
      if (m > 0.f && m < 1.f) ++c.fractional;
      bool inBand = false;  // within 2 px (Chebyshev) of a pixel with different exact visibility
      for (int dy = -2; dy <= 2 && !inBand; ++dy)
        for (int dx = -2; dx <= 2 && !inBand; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= width || yy >= height) continue;
          inBand = exactAt(xx, yy) != e;
        }
      if (inBand) {
        ++c.band;
        continue;
      }
      ++c.considered;
      const bool lit = e >= 0.5f, mapLit = m >= 0.5f;
      if (lit) ++c.exactLit;
      if (lit && !mapLit) ++c.falseShadow;
      if (!lit && mapLit) ++c.falseLit;
    }
  }
  return c;
}

}  // namespace diptych::testing
