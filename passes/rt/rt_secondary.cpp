#include "passes/rt/rt_secondary.h"

#include <tbb/parallel_for.h>

#include <optional>

#include "engine/graph/render_world.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/whitted.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"
#include "passes/rt/sdf_steps.h"

namespace diptych {

ParamSchema RtSecondaryPass::schema() {
  return {ParamSpec::integer("depth", 5, 2, 64,
                             "maximum recursion depth, the G-buffer point being depth 1 (lecture's "
                             "max)"),
          ParamSpec::integer("area_samples", 16, 1, 4096,
                             "stratified shadow rays per area light at each hit"),
          ParamSpec::choice("texture_lod", "level0", {"level0", "cone"},
                            "texture level at traced hits: level 0, or ray cones (RTG ch. 20)")};
}

void RtSecondaryPass::setup(PassBuilder& b) {
  maxDepth_ = b.params().integer("depth");
  areaSamples_ = b.params().integer("area_samples");
  rayCones_ = b.params().string("texture_lod") == "cone";
  io_ = slotIo(b, kind_ == Kind::Reflection ? "reflection" : "transmission");
  sdfSteps_ = writeSdfSteps(b);
}

void RtSecondaryPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const FrameSettings& frame = c.frame();
  CpuImage& out = c.cpuWrite(io_.signal);
  CpuImage* steps = sdfSteps_ != kNoResource ? &c.cpuWrite(sdfSteps_) : nullptr;
  const WhittedTracer tracer(scene, world.geometry(), world.rtScene(),
                             {maxDepth_, areaSamples_, rayCones_});
  const float spread = pixelSpreadAngle(frame.camera, frame.height);
  const bool reflection = kind_ == Kind::Reflection;

  const PinholeFrame pinhole(frame.camera, frame.width, frame.height);
  const ExactHitBuffer& exact = exactHits(c, io_.hits);
  tbb::parallel_for(0, frame.height, [&](int y) {
    for (int x = 0; x < frame.width; ++x) {
      vec3 radiance(0.f);
      beginSdfPixel();
      // The material decides first: only its pixels pay for rebuilding the surface point.
      const auto hit = exact.at(x, y);
      const Material* m =
          hit ? &scene.material(
                    scene.meshes[scene.instances.at(std::size_t(hit->instance)).mesh].material)
              : nullptr;
      if (m && (reflection ? shading::materialHasReflection(*m)
                           : shading::materialHasTransmission(*m))) {
        const Ray eye = pinhole.ray(x + 0.5f, y + 0.5f);
        const std::optional<SurfacePoint> sp =
            hit ? std::optional(makeSurfacePoint(scene, world.geometry(), *hit, eye.direction))
                : std::nullopt;
        // Per point, as Whitted decides (a texture may make this texel rough or not metal).
        if (sp && (reflection ? shading::hasReflection(sp->resolved, false)
                              : shading::hasTransmission(sp->resolved))) {
          const SurfacePoint& p = *sp;
          const std::uint32_t seed = std::uint32_t(y * frame.width + x);
          // The G-buffer point is the lecture's depth 1; its secondary rays are depth 2. Its cone
          // (RTG eq. 20.30) has width spread * distance there.
          const RayCone cone{spread * glm::length(p.position - eye.origin), spread};
          const RayCone* c = rayCones_ ? &cone : nullptr;
          radiance = reflection ? tracer.reflected(p, -eye.direction, 1, seed, c)
                                : tracer.transmitted(p, -eye.direction, 1, seed, c);
        }
      }
      for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, radiance[ch]);
      out.setF(x, y, 3, 1.f);
      storeSdfPixel(steps, x, y);
    }
  });
  c.count("rays", double(tracer.raysTraced()));
}

}  // namespace diptych
