#include "passes/rt/rt_distributed.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <numeric>
#include <span>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/graph/scene_needs.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/whitted.h"
#include "passes/rt/rt_whitted.h"
#include "passes/rt/sdf_steps.h"
#include "passes/rt/texture_supersample.h"

namespace diptych {
namespace {

// Primary rays per Embree stream call (RtScene::intersectRays): a row's samples are traced in
// tiles of this many, the most WhittedTracer::radianceTile shades at once.
constexpr std::size_t kPrimaryTile = WhittedTracer::kMaxTile;
constexpr std::uint32_t kTimeSalt = 0x54494d45u;  // "TIME": the time strata's own hashes

// A per-pixel random permutation of 0..n-1 (Fisher-Yates driven by pcgHash). Pairing pixel
// stratum s with lens stratum perm[s] keeps both sets stratified while decorrelating them, as
// Cook et al. prescribe for the separate dimensions of a distributed sample; pairing s with s
// would tie each lens position to one position in the pixel and show as structured noise.
void shuffle(std::vector<int>& perm, std::uint32_t seed) {
  std::iota(perm.begin(), perm.end(), 0);
  for (std::size_t i = perm.size(); i > 1; --i) {
    seed = pcgHash(seed);
    std::swap(perm[i - 1], perm[seed % i]);
  }
}

}  // namespace

ParamSchema RtDistributedPass::schema(int defaultSpp) {
  return {ParamSpec::integer("spp", defaultSpp, 1, 4096,
                             "samples per pixel, rounded to a square k x k stratified grid"),
          ParamSpec::integer("depth", 5, 1, 64, "maximum recursion depth (primary hit = 1)"),
          ParamSpec::integer("area_samples", 16, 1, 4096,
                             "stratified shadow rays per area light at each hit"),
          ParamSpec::choice("texture_lod", "level0", {"level0", "cone"},
                            "texture level at traced hits: level 0, or ray cones (RTG ch. 20)")};
}

void RtDistributedPass::setup(PassBuilder& b) {
  b.needs(SceneNeed::Geometry);
  spp_ = stratifiedSampleCount(b.params().integer("spp"));
  maxDepth_ = b.params().integer("depth");
  areaSamples_ = b.params().integer("area_samples");
  rayCones_ = b.params().string("texture_lod") == "cone";
  if (!thinLens_) textureSamples_ = b.params().integer("texture_samples");
  // Each sample would take its pixel's mean, which the samples already integrate: the texture
  // filtered twice, and a silhouette's colours bled onto the other side.
  if (textureSamples_ > 1 && spp_ > 1)
    b.params().fail("texture_samples", "texture_samples > 1 needs spp 1: with " +
                                           std::to_string(spp_) +
                                           " samples a pixel already integrates its texture");
  color_ = b.write("color", {Format::RGBA32F, b.frame().width, b.frame().height},
                   vec4(0.f, 0.f, 0.f, 1.f));
  sdfSteps_ = writeSdfSteps(b);
}

void RtDistributedPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const FrameSettings& frame = c.frame();
  Camera camera = frame.camera;
  if (!thinLens_) camera.aperture = 0.f;  // a pinhole: thinLensRay is then primaryRay exactly
  CpuImage& out = c.cpuWrite(color_);
  CpuImage* steps = sdfSteps_ != kNoResource ? &c.cpuWrite(sdfSteps_) : nullptr;
  const WhittedTracer tracer(world.scene(), world.geometry(), world.rtScene(),
                             {maxDepth_, areaSamples_, rayCones_});
  // Primary cones start at the eye with zero width and the pixel's spread (RTG eq. 20.30); with
  // a lens the cone's width at the lens is left out (the lens radius is far below the widths at
  // textured hits for the scenes' apertures).
  // With k x k samples per pixel each sample stands for one stratum: 1/k of the pixel's spread.
  const RayCone primaryCone{0.f, pixelSpreadAngle(camera, frame.height) / std::sqrt(float(spp_))};
  const RayCone* cone = rayCones_ ? &primaryCone : nullptr;
  const ThinLensFrame lensFrame(camera, frame.width, frame.height);
  const PinholeFrame& pinhole = lensFrame.pinhole();
  const bool lens = camera.aperture > 0.f;
  // Motion blur (Cook et al.'s time dimension): each sample at its own time in the shutter, a
  // per-pixel permutation of spp jittered strata of [0, 1), decorrelated from the pixel and lens
  // strata as those are from each other. Only where something moves: a static scene's rays
  // keep kFrameTime and its image stays bit for bit what it was; rt_whitted, like the raster
  // passes, shows the frame's instant.
  const bool shutter = thinLens_ && world.scene().hasMotion();
  // rt_whitted's texture_samples (rt_whitted.h): each pixel's texture signal, traced first.
  const bool textureSignal =
      textureSamples_ > 1 && sceneSatisfies(world.scene(), SceneNeed::TexturedMaterial);
  std::atomic<std::int64_t> textureRays = 0;
  // The primary ray of pixel x's sample s (its seed in `seed`), as below.
  const auto sampleRay = [&](int x, int y, int s, std::span<const int> lensStratum,
                             std::span<const int> timeStratum, std::uint32_t& seed) {
    const std::uint32_t pixel = std::uint32_t(y * frame.width + x);
    // The hashes only where they are read (pcgHash is out of line: an unused one still ran).
    const vec2 offset = spp_ == 1 ? vec2(0.5f) : stratifiedSample(s, spp_, pcgHash(pixel));
    const float px = float(x) + offset.x, py = float(y) + offset.y;
    seed = spp_ == 1 ? pixel : pcgHash(pixel * 4096u + std::uint32_t(s));
    // pinhole.ray == thinLensRay with no aperture; the lens's hash only with a lens ("LENS").
    Ray ray = !lens ? pinhole.ray(px, py)
                    : lensFrame.ray(px, py,
                                    stratifiedSample(lensStratum[std::size_t(s)], spp_,
                                                     pcgHash(pixel ^ 0x4c454e53u)));
    if (shutter)
      ray.time =
          (float(timeStratum[std::size_t(s)]) + unitFloat(pcgHash(seed ^ kTimeSalt))) / float(spp_);
    return ray;
  };
  // Without SDF objects a row's sample rays (neighbouring pixels, or one pixel's strata: all
  // coherent) are traced in tiles of 64 as Embree streams and shaded by radianceTile, whose
  // shadow rays go as one stream too; each pixel sums its samples in their order, so the image
  // is the ray-by-ray loop's below up to the rounding of Embree's packet kernels
  // (engine/rt/whitted_tile.cpp). With SDF objects that loop stays: its
  // beginSdfPixel / storeSdfPixel count each pixel's sphere-tracing steps.
  if (!steps) {
    const RtScene& rt = world.rtScene();
    tbb::parallel_for(0, frame.height, [&](int y) {
      std::vector<int> lensStratum(std::size_t(spp_), 0), timeStratum(std::size_t(spp_), 0);
      std::vector<vec3> sum(std::size_t(frame.width), vec3(0.f));
      std::vector<vec4> signal(textureSignal ? std::size_t(frame.width) : 0);
      std::vector<SecondarySignals> secondary(signal.size());
      if (textureSignal)
        textureRays += whittedTextureRow(world.scene(), world.geometry(), rt, pinhole,
                                         textureSamples_, y, signal, tracer, secondary);
      vec4 signalOf[kPrimaryTile];
      SecondarySignals secondaryOf[kPrimaryTile];
      Ray rays[kPrimaryTile];
      std::uint32_t seeds[kPrimaryTile];
      int pixelOf[kPrimaryTile];
      std::size_t filled = 0;
      // One sample through a pinhole at the frame's instant (the Whitted reference): sampleRay's
      // ray is the pixel centre's, whose directions the row computes at once (vectorised,
      // PinholeFrame::rowDirections, bit for bit ray()'s).
      std::vector<vec3> centres;
      if (spp_ == 1 && !lens && !shutter) {
        centres.resize(std::size_t(frame.width));
        pinhole.rowDirections(y, centres);
      }
      const auto flush = [&] {
        Hit hits[kPrimaryTile];
        const Hit* found[kPrimaryTile];
        CameraRays{rt, world.scene(), world.geometry()}.intersectRays(
            {rays, filled}, {hits, filled}, {found, filled}, tracer.wantsHitNormal());
        const RayCone* cones[kPrimaryTile];
        vec3 colors[kPrimaryTile];
        std::fill_n(cones, filled, cone);
        for (std::size_t i = 0; i < filled && textureSignal; ++i) {
          signalOf[i] = signal[std::size_t(pixelOf[i])];
          secondaryOf[i] = secondary[std::size_t(pixelOf[i])];
        }
        tracer.radianceTile({rays, filled}, {found, filled}, {seeds, filled}, 1,
                            {cones, cone ? filled : 0}, {colors, filled},
                            {signalOf, textureSignal ? filled : 0},
                            {secondaryOf, textureSignal ? filled : 0});
        for (std::size_t i = 0; i < filled; ++i) sum[std::size_t(pixelOf[i])] += colors[i];
        filled = 0;
      };
      for (int x = 0; x < frame.width; ++x) {
        const std::uint32_t pixel = std::uint32_t(y * frame.width + x);
        if (lens) shuffle(lensStratum, pcgHash(pixel ^ 0x4c454e53u));
        if (shutter) shuffle(timeStratum, pcgHash(pixel ^ kTimeSalt));
        for (int s = 0; s < spp_; ++s) {
          // In place (guaranteed copy elision): assigning the returned Ray reloaded its
          // just-stored floats as 16-byte loads, a store-forwarding stall per sample (perf
          // annotate: about half of this loop's own time).
          if (!centres.empty()) {
            seeds[filled] = pixel;  // sampleRay's seed for one sample
            ::new (static_cast<void*>(&rays[filled]))
                Ray{pinhole.position(), centres[std::size_t(x)]};
          } else {
            ::new (static_cast<void*>(&rays[filled]))
                Ray(sampleRay(x, y, s, lensStratum, timeStratum, seeds[filled]));
          }
          pixelOf[filled] = x;
          if (++filled == kPrimaryTile) flush();
        }
      }
      if (filled > 0) flush();
      for (int x = 0; x < frame.width; ++x) {
        const vec3 color = sum[std::size_t(x)] / float(spp_);
        for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, color[ch]);
        out.setF(x, y, 3, 1.f);
      }
    });
    c.count("rays", double(tracer.raysTraced() + textureRays.load()));
    c.count("samples", double(spp_) * frame.width * frame.height);
    return;
  }
  tbb::parallel_for(0, frame.height, [&](int y) {
    std::vector<int> lensStratum(std::size_t(spp_), 0), timeStratum(std::size_t(spp_), 0);
    for (int x = 0; x < frame.width; ++x) {
      const std::uint32_t pixel = std::uint32_t(y * frame.width + x);
      // The same pixel pattern and seeds as rt_whitted, so that the two differ only by the lens.
      // A pinhole (rt_whitted) never reads the lens sample: skip its shuffle and strata.
      if (lens) shuffle(lensStratum, pcgHash(pixel ^ 0x4c454e53u));  // "LENS"
      if (shutter) shuffle(timeStratum, pcgHash(pixel ^ kTimeSalt));
      beginSdfPixel();
      // Inside the pixel's step count, whose sum is RtScene::sdfStepStats (sdf_steps.h); ray by
      // ray, as this loop traces: the streams' signal up to Embree's packet rounding.
      const vec4 signal = textureSignal ? TextureSupersamplePass::singleRayPixel(
                                              world.scene(), world.geometry(), world.rtScene(),
                                              pinhole, textureSamples_, x, y)
                                        : vec4(-1.f);
      SecondarySignals secondary;
      if (textureSignal) {
        textureRays += std::int64_t(textureSamples_) * textureSamples_;
        // The secondary hits' footprint where the centre's own reach a colour texture (its
        // colours are singleRayPixel's, unused here).
        const Ray centre = pinhole.ray(float(x) + 0.5f, float(y) + 0.5f);
        Hit h;
        std::int64_t rays = 1;
        const FootprintTarget target =
            CameraRays{world.rtScene(), world.scene(), world.geometry()}.intersect(centre, h, false)
                ? texturedSecondariesAt(tracer, world.scene(), world.geometry(), world.rtScene(),
                                        centre, h, rays)
                : FootprintTarget{};
        secondary =
            secondaryFootprintPixel(tracer, world.scene(), world.geometry(), world.rtScene(),
                                    pinhole, textureSamples_, x, y, target, rays);
        textureRays += rays;
      }
      vec3 sum(0.f);
      for (int s = 0; s < spp_; ++s) {
        std::uint32_t seed;
        const Ray ray = sampleRay(x, y, s, lensStratum, timeStratum, seed);
        sum += tracer.radiance(ray, 1, seed, cone, nullptr, textureSignal ? &signal : nullptr,
                               textureSignal ? &secondary : nullptr);
      }
      storeSdfPixel(steps, x, y);
      const vec3 color = sum / float(spp_);
      for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, color[ch]);
      out.setF(x, y, 3, 1.f);
    }
  });
  c.count("rays", double(tracer.raysTraced() + textureRays.load()));
  c.count("samples", double(spp_) * frame.width * frame.height);
}

}  // namespace diptych
