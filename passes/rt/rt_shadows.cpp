#include "passes/rt/rt_shadows.h"

#include <tbb/parallel_for.h>

#include "engine/graph/render_world.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/shadow_rays.h"
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

  // Receivers for covered pixels only, built in parallel per row, then compacted in order.
  std::vector<int> rowCount(h + 1, 0);
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) rowCount[y + 1] += hits.u(x, y, 0) != 0u ? 1 : 0;
  });
  for (int y = 0; y < h; ++y) rowCount[y + 1] += rowCount[y];
  const std::size_t n = std::size_t(rowCount[h]);
  std::vector<std::uint32_t> pixelOf(n);  // pixel index: also the area-light sample seed
  std::vector<ShadowReceiver> receivers(n);
  const ExactHitBuffer& exact = exactHits(world, hits, c.frame().camera);
  tbb::parallel_for(0, h, [&](int y) {
    std::size_t i = std::size_t(rowCount[y]);
    for (int x = 0; x < w; ++x) {
      const auto hit = exact.at(x, y);
      if (!hit) continue;
      receivers[i] = shadowReceiver(world.geometry(), *hit);
      pixelOf[i++] = std::uint32_t(y * w + x);
    }
  });
  const std::vector<float> visibility =
      traceShadowRays(rt, lights, receivers, areaSamples_, pixelOf);
  out.fill(vec4(1.f));
  for (std::size_t l = 0; l < lights.size(); ++l) {
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
      out.setF(int(pixelOf[i] % w), int(pixelOf[i] / w), 0, visibility[l * n + i], int(l));
    });
  }
  std::size_t active = 0;
  for (const Light& light : lights)
    active += light.castsShadows ? n * std::size_t(shadowRaysPerReceiver(light, areaSamples_)) : 0;
  c.count("rays", double(active));
}

}  // namespace diptych
