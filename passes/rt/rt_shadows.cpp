#include "passes/rt/rt_shadows.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <bit>

#include "engine/core/check.h"
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
  rowCount_.assign(std::size_t(h) + 1, 0);
  tbb::parallel_for(0, h, [&](int y) {
    const std::uint32_t* row = hits.row(y);
    const std::size_t stride = std::size_t(hits.channels());
    int count = 0;
    for (int x = 0; x < w; ++x) count += row[std::size_t(x) * stride] != 0u ? 1 : 0;
    rowCount_[std::size_t(y) + 1] = count;
  });
  for (int y = 0; y < h; ++y) rowCount_[y + 1] += rowCount_[y];
  const std::size_t n = std::size_t(rowCount_[h]);
  pixelOf_.resize(n);  // pixel index: also the area-light sample seed
  receivers_.resize(n);
  const ExactHitBuffer& exact = exactHits(c, io_.hits);
  tbb::parallel_for(0, h, [&](int y) {
    std::size_t i = std::size_t(rowCount_[y]);
    for (int x = 0; x < w; ++x) {
      const auto hit = exact.at(x, y);
      if (!hit) continue;
      receivers_[i] = shadowReceiver(world.geometry(), *hit);
      pixelOf_[i++] = std::uint32_t(y * w + x);
    }
  });
  const std::vector<float> visibility =
      traceShadowRays(rt, lights, receivers_, areaSamples_, pixelOf_);
  out.fill(vec4(1.f));
  // The row-pointer writes below assume one float per texel, the frame's size, a layer a light.
  DIPTYCH_CHECK(out.channels() == 1 && out.desc.width == w && out.desc.height == h &&
                    out.desc.layers >= int(lights.size()),
                "rt_shadows: visibility is not R32F of the frame's size with a layer per light");
  for (std::size_t l = 0; l < lights.size(); ++l) {
    // Layer l is R32F: pixel p's texel is word p of the layer.
    std::uint32_t* layer = out.row(0, int(l));
    const float* v = visibility.data() + l * n;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i < r.end(); ++i)
                          layer[pixelOf_[i]] = std::bit_cast<std::uint32_t>(v[i]);
                      });
  }
  std::size_t active = 0;
  for (const Light& light : lights)
    active += light.castsShadows ? n * std::size_t(shadowRaysPerReceiver(light, areaSamples_)) : 0;
  c.count("rays", double(active));
}

}  // namespace diptych
