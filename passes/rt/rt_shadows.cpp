#include "passes/rt/rt_shadows.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/shadow_rays.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"

namespace diptych {

ParamSchema RtShadowsPass::schema() {
  return {ParamSpec::integer("area_samples", 16, 1, 4096,
                             "stratified shadow rays per area light (1: its centre only)")};
}

void RtShadowsPass::setup(PassBuilder& b) {
  areaSamples_ = b.params().integer("area_samples");
  io_ = slotIo(b, "visibility");
}

void RtShadowsPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const CpuImage& hits = c.cpuRead(io_.hits);
  CpuImage& out = c.cpuWrite(io_.signal);
  const int w = hits.desc.width, h = hits.desc.height;
  const auto& lights = world.scene().lights;
  const RtScene& rt = world.rtScene();

  // The row-pointer writes below assume one float per texel, the frame's size, a layer a light.
  checkVisibilitySignal(out, w, h, lights.size(), "rt_shadows");
  const ExactHitBuffer& exact = exactHits(c, io_.hits);
  const std::size_t lightCount = lights.size();
  std::vector<shading::ShadingLight> shadingLights;
  for (const Light& light : lights) shadingLights.push_back(shading::toShadingLight(light));
  std::vector<char> mayNotReach;     // lightMayNotReach: only those are tested per receiver
  std::vector<std::size_t> raysPer;  // a receiver's rays toward each light
  std::size_t raysPerReceiver = 0;
  for (const Light& light : lights) {
    mayNotReach.push_back(lightMayNotReach(light));
    raysPer.push_back(light.castsShadows ? std::size_t(shadowRaysPerReceiver(light, areaSamples_))
                                         : 0);
    raysPerReceiver += raysPer.back();
  }
  const bool testReach =
      std::any_of(mayNotReach.begin(), mayNotReach.end(), [](char m) { return m; });
  std::atomic<std::size_t> covered{0}, traced{0};
  // One pass over the frame, row by row: each covered pixel's receiver built in place, its
  // shadow rays traced in coherent streams with its row's (traceShadowTile, as the Whitted
  // reference traces a tile's), the row's texels written once. Before, a counting pass, a
  // frame-sized receiver array, a stream per light over it, a fill of every layer and a scatter
  // per light: four more passes over the frame's memory.
  tbb::parallel_for(0, h, [&](int y) {
    // Per thread, reused row after row (the width's worth: no allocation per row).
    thread_local std::vector<ShadowReceiver> receivers;
    thread_local std::vector<std::uint32_t> seeds;  // pixel index, as the Whitted tracer's
    thread_local std::vector<int> column;
    thread_local std::vector<float> visibility;
    thread_local std::vector<std::uint8_t> lit;  // lightReaches, per receiver and light
    receivers.resize(std::size_t(w));
    seeds.resize(std::size_t(w));
    column.resize(std::size_t(w));
    visibility.resize(std::size_t(w) * lightCount);
    lit.resize(std::size_t(w) * lightCount);
    std::size_t n = 0, unlitRays = 0;
    const SurfaceHit* hit = exact.row(y);
    for (int x = 0; x < w; ++x) {
      if (hit[x].instance < 0) continue;
      receivers[n] = shadowReceiver(world.geometry(), hit[x]);
      // As the reference: no ray toward a light that sends this point nothing (the ceiling of
      // a Cornell box behind its one-sided light: 16 rays a pixel for a visibility that
      // multiplies zero). The signal says 1 there, what a raster lookup outside its map says.
      for (std::size_t l = 0; testReach && l < lightCount; ++l) {
        const bool reaches =
            !mayNotReach[l] || lightReaches(shadingLights[l], receivers[n].position);
        lit[n * lightCount + l] = reaches;
        unlitRays += reaches ? 0 : raysPer[l];
      }
      seeds[n] = std::uint32_t(y * w + x);
      column[n++] = x;
    }
    traceShadowTile(rt, lights, {receivers.data(), n}, areaSamples_, {seeds.data(), n}, visibility,
                    testReach ? std::span<const std::uint8_t>(lit.data(), n * lightCount)
                              : std::span<const std::uint8_t>());
    for (std::size_t l = 0; l < lightCount; ++l) {
      // Layer l is R32F: pixel x's texel is word x of the row; uncovered pixels are visible.
      std::uint32_t* row = out.row(y, int(l));
      std::fill_n(row, w, std::bit_cast<std::uint32_t>(1.f));
      for (std::size_t i = 0; i < n; ++i)
        row[column[i]] = std::bit_cast<std::uint32_t>(visibility[i * lightCount + l]);
    }
    for (int l = int(lightCount); l < out.desc.layers; ++l)  // layers beyond the lights: visible
      std::fill_n(out.row(y, l), w, std::bit_cast<std::uint32_t>(1.f));
    covered.fetch_add(n, std::memory_order_relaxed);
    traced.fetch_add(n * raysPerReceiver - unlitRays, std::memory_order_relaxed);
  });
  c.count("rays", double(traced.load()));
  c.count("receivers", double(covered.load()));
}

}  // namespace diptych
