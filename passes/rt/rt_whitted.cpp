#include "passes/rt/rt_whitted.h"

#include <tbb/parallel_for.h>

#include "engine/graph/render_world.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/whitted.h"

namespace diptych {

void RtWhittedPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  maxDepth_ = b.params().integer("depth", 5, 1, 64);
  areaSamples_ = b.params().integer("area_samples", 16, 1, 4096);
  spp_ = stratifiedSampleCount(b.params().integer("spp", 1, 1, 4096));
  color_ = b.write("color", {Format::RGBA32F, b.frame().width, b.frame().height},
                   vec4(0.f, 0.f, 0.f, 1.f));
}

void RtWhittedPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const FrameSettings& frame = c.frame();
  Surface& out = c.cpuWrite(color_);
  const WhittedTracer tracer(world.scene(), world.geometry(), world.rtScene(),
                             {maxDepth_, areaSamples_});
  tbb::parallel_for(0, frame.height, [&](int y) {
    for (int x = 0; x < frame.width; ++x) {
      const std::uint32_t pixel = std::uint32_t(y * frame.width + x);
      vec3 sum(0.f);
      for (int s = 0; s < spp_; ++s) {
        // Pixel centre for one sample; otherwise a jittered stratum of the pixel. The seed of
        // the pixel-centre ray is the pixel index, as in the hybrid passes.
        const vec2 offset = spp_ == 1 ? vec2(0.5f) : stratifiedSample(s, spp_, pcgHash(pixel));
        const Ray ray =
            primaryRay(frame.camera, frame.width, frame.height, x + offset.x, y + offset.y);
        sum +=
            tracer.radiance(ray, 1, spp_ == 1 ? pixel : pcgHash(pixel * 4096u + std::uint32_t(s)));
      }
      const vec3 color = sum / float(spp_);
      for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, color[ch]);
      out.setF(x, y, 3, 1.f);
    }
  });
  c.count("rays", double(tracer.raysTraced()));
}

}  // namespace diptych
