#include "passes/rt/texture_supersample.h"

#include <tbb/parallel_for.h>

#include <limits>

#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "passes/common/hits_texel.h"

namespace diptych {

ParamSchema TextureSupersamplePass::schema() {
  return {ParamSpec::integer("samples", 4, 1, 64,
                             "N: N x N stratified sub-pixel rays per pixel (1: the pixel centre)")};
}

void TextureSupersamplePass::setup(PassBuilder& b) {
  samples_ = b.params().integer("samples");
  io_ = slotIo(b, "texture_filtering");
}

void TextureSupersamplePass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const FrameSettings& frame = c.frame();
  const CpuImage& hits = c.cpuRead(io_.hits);
  CpuImage& out = c.cpuWrite(io_.signal);
  const int n = samples_;
  // Fetched once, outside the loop (the first call builds the BVH).
  const RtScene& rt = world.rtScene();
  // The camera frames once per image (PinholeFrame::ray == primaryRay bit for bit).
  const PinholeFrame pinhole(frame.camera, frame.width, frame.height);
  tbb::parallel_for(0, frame.height, [&](int y) {
    for (int x = 0; x < frame.width; ++x) {
      vec4 albedo(-1.f);
      // Coverage only: lifting a texel onto its analytic shape never changes whether it is one.
      if (hits.u(x, y, 0) != 0u) {
        vec4 sum(0.f);
        int count = 0;
        for (int j = 0; j < n; ++j) {
          for (int i = 0; i < n; ++i) {
            // Stratum centres: deterministic, so N = 1 is exactly the pixel centre.
            const float sx = float(x) + (float(i) + 0.5f) / float(n);
            const float sy = float(y) + (float(j) + 0.5f) / float(n);
            const Ray ray = pinhole.ray(sx, sy);
            const auto hit = rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), false);
            if (!hit) continue;
            const SurfacePoint p = makeSurfacePoint(
                scene, world.geometry(),
                {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic}, ray.direction);
            sum += vec4(p.resolved.color, p.resolved.alpha);
            ++count;
          }
        }
        if (count > 0) albedo = sum / float(count);
      }
      for (int ch = 0; ch < 4; ++ch) out.setF(x, y, ch, albedo[ch]);
    }
  });
  c.count("rays", double(frame.width) * frame.height * n * n);
}

}  // namespace diptych
