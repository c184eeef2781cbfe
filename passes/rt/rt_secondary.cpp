#include "passes/rt/rt_secondary.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <bit>
#include <optional>
#include <vector>

#include "engine/core/check.h"
#include "engine/graph/render_world.h"
#include "engine/graph/scene_needs.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/whitted.h"
#include "engine/shading/shading.h"
#include "passes/common/exact_hits.h"
#include "passes/rt/sdf_steps.h"
#include "passes/rt/texture_supersample.h"

namespace diptych {

ParamSchema RtSecondaryPass::schema() {
  return {ParamSpec::integer("depth", 5, 2, 64,
                             "maximum recursion depth, the G-buffer point being depth 1 (lecture's "
                             "max)"),
          ParamSpec::integer("area_samples", 16, 1, 4096,
                             "stratified shadow rays per area light at each hit"),
          ParamSpec::choice("texture_lod", "level0", {"level0", "cone"},
                            "texture level at traced hits: level 0, or ray cones (RTG ch. 20)"),
          ParamSpec::integer("texture_samples", 1, 1, 64,
                             "N: the texture colour at the first textured hit along each "
                             "pixel's secondary ray averaged over the pixel's footprint, N x N "
                             "sub-pixel rays followed the same way (the Whitted reference's "
                             "texture_samples); 1: the hit's own lookup")};
}

void RtSecondaryPass::setup(PassBuilder& b) {
  maxDepth_ = b.params().integer("depth");
  areaSamples_ = b.params().integer("area_samples");
  rayCones_ = b.params().string("texture_lod") == "cone";
  textureSamples_ = b.params().integer("texture_samples");
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
  // The material decides first, per instance once: only its pixels pay for rebuilding the
  // surface point (a per-pixel lookup through instance, mesh and material cost more than the
  // test).
  std::vector<char> candidate(scene.instances.size());
  for (std::size_t i = 0; i < candidate.size(); ++i) {
    const Material& m = scene.material(scene.meshes[scene.instances[i].mesh].material);
    candidate[i] =
        reflection ? shading::materialHasReflection(m) : shading::materialHasTransmission(m);
  }
  DIPTYCH_CHECK(
      out.channels() == 4 && out.desc.width == frame.width && out.desc.height == frame.height,
      "rt_secondary: the signal is not RGBA32F of the frame's size");
  DIPTYCH_CHECK(exact.width() == frame.width && exact.height() == frame.height,
                "rt_secondary: the hits are not of the frame's size");
  // texture_samples (rt_secondary.h): the footprint of each candidate pixel's secondary hit.
  const bool footprint = textureSamples_ > 1 && sceneSatisfies(scene, SceneNeed::TexturedMaterial);
  std::atomic<std::int64_t> footprintRays = 0;
  tbb::parallel_for(0, frame.height, [&](int y) {
    // The row's footprint signals (stream path; empty without texture_samples).
    std::vector<SecondarySignals> signals;
    std::vector<vec4> colors;  // the camera hits' own: not looked up (-1)
    std::vector<FootprintTarget> targets;
    std::vector<std::uint8_t> traced;  // targets[x].kinds != 0
    const SurfaceHit* hit = exact.row(y);
    const auto isCandidate = [&](int x) {
      return hit[x].instance >= 0 && candidate[std::size_t(hit[x].instance)];
    };
    // The camera ray of pixel x: the row's directions computed at once (vectorised,
    // PinholeFrame::rowDirections) at its first candidate; rows without one compute none.
    std::vector<vec3> directions;
    const auto eyeRay = [&](int x) {
      if (directions.empty()) {
        directions.resize(std::size_t(frame.width));
        pinhole.rowDirections(y, directions);
      }
      return Ray{pinhole.position(), directions[std::size_t(x)]};
    };
    // Pixel x's surface point: the one kept for the frame's consumers (ExactHitBuffer::point;
    // rt_reflection makes it, rt_transmission and shade copy it), or made into `own`.
    const auto surfacePoint = [&](int x, const Ray& eye,
                                  std::optional<SurfacePoint>& own) -> const SurfacePoint& {
      if (const SurfacePoint* kept = exact.point(scene, world.geometry(), x, y, eye.direction))
        return *kept;
      return own.emplace(makeSurfacePoint(scene, world.geometry(), hit[x], eye.direction));
    };
    const std::uint8_t kind =
        reflection ? FootprintTarget::kReflected : FootprintTarget::kTransmitted;
    std::int64_t rowFootprintRays = 0;
    // The pixel's footprint is traced where its own secondary ray from point p reaches a colour
    // texture (through hits of its kind: texturedSecondaries).
    const auto texturedAt = [&](const SurfacePoint& p, const Ray& eye) {
      return texturedSecondaries(tracer, scene, world.geometry(), world.rtScene(), p, eye.direction,
                                 kind, rowFootprintRays);
    };
    if (footprint && !steps) {  // with SDF objects: pixel by pixel below
      signals.resize(std::size_t(frame.width));
      colors.resize(std::size_t(frame.width));
      targets.assign(std::size_t(frame.width), FootprintTarget{});
      traced.assign(std::size_t(frame.width), 0);
      for (int x = 0; x < frame.width; ++x) {
        if (!isCandidate(x)) continue;
        const Ray eye = eyeRay(x);
        std::optional<SurfacePoint> own;
        targets[std::size_t(x)] = texturedAt(surfacePoint(x, eye, own), eye);
        traced[std::size_t(x)] = targets[std::size_t(x)].kinds != 0;
      }
      const SecondaryFootprint rowFootprint{tracer, targets, signals, false};
      rowFootprintRays += supersampleTextureRow(scene, world.geometry(), world.rtScene(), pinhole,
                                                traced, textureSamples_, y, colors, &rowFootprint);
    }
    // The row's address once (per-texel setF recomputes the stride and the index).
    std::uint32_t* row = out.row(y);
    const auto store = [&](int x, const vec3& radiance) {
      std::uint32_t* texel = row + 4 * std::size_t(x);
      for (int ch = 0; ch < 3; ++ch) texel[ch] = std::bit_cast<std::uint32_t>(radiance[ch]);
      texel[3] = std::bit_cast<std::uint32_t>(1.f);
    };
    // The row's secondary rays, in tiles: traced as Embree streams level by level (neighbouring
    // pixels of a mirror or a glass leave in similar directions; WhittedTracer::tracedTile).
    // Results are those of tracer.reflected / transmitted up to the rounding of Embree's packet
    // kernels (engine/rt/whitted_tile.cpp). With SDF objects each
    // pixel's rays stay between beginSdfPixel and storeSdfPixel, which count their sphere-tracing
    // steps: one ray at a time there.
    constexpr std::size_t kTile = WhittedTracer::kMaxTile;
    WhittedTracer::SecondaryRay rays[kTile];
    int pixel[kTile];
    std::size_t filled = 0;
    const auto flush = [&] {
      vec3 radiance[kTile];
      tracer.tracedTile({rays, filled}, {radiance, filled});
      for (std::size_t i = 0; i < filled; ++i) store(pixel[i], radiance[i]);
      filled = 0;
    };
    for (int x = 0; x < frame.width; ++x) {
      vec3 radiance(0.f);
      if (steps) beginSdfPixel();  // else a thread-local call and four stores per pixel
      if (isCandidate(x)) {
        const Ray eye = eyeRay(x);
        std::optional<SurfacePoint> own;
        const SurfacePoint& p = surfacePoint(x, eye, own);
        // Per point, as Whitted decides (a texture may make this texel rough or not metal).
        if (reflection ? shading::hasReflection(p.resolved, false)
                       : shading::hasTransmission(p.resolved)) {
          const std::uint32_t seed = std::uint32_t(y * frame.width + x);
          // The G-buffer point is the lecture's depth 1; its secondary rays are depth 2. Its cone
          // (RTG eq. 20.30) has width spread * distance there.
          const RayCone cone{spread * glm::length(p.position - eye.origin), spread};
          const RayCone* c = rayCones_ ? &cone : nullptr;
          if (steps) {
            // The pixel's footprint inside its step count, as its rays below.
            const SecondarySignals s =
                footprint ? secondaryFootprintPixel(tracer, scene, world.geometry(),
                                                    world.rtScene(), pinhole, textureSamples_, x, y,
                                                    texturedAt(p, eye), rowFootprintRays)
                          : SecondarySignals{};
            radiance = reflection ? tracer.reflected(p, -eye.direction, 1, seed, c, &s)
                                  : tracer.transmitted(p, -eye.direction, 1, seed, c, &s);
          } else if (tracer.secondaryRay(p, -eye.direction, 1, seed, c, reflection, rays[filled])) {
            if (footprint)
              WhittedTracer::passSignal(signals[std::size_t(x)], reflection, rays[filled]);
            pixel[filled] = x;
            if (++filled == kTile) flush();
            continue;  // stored by flush
          }
        }
      }
      store(x, radiance);
      storeSdfPixel(steps, x, y);
    }
    if (filled > 0) flush();
    footprintRays += rowFootprintRays;
  });
  c.count("rays", double(tracer.raysTraced() + footprintRays.load()));
}

}  // namespace diptych
