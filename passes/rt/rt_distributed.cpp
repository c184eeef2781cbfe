#include "passes/rt/rt_distributed.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/rt/light_sampling.h"
#include "engine/rt/ray_cone.h"
#include "engine/rt/whitted.h"
#include "passes/rt/sdf_steps.h"

namespace diptych {
namespace {

// Primary rays per Embree stream call: a row is traced in tiles of this many pixels (80 bytes
// each on the stack), the most WhittedTracer::radianceTile shades at once.
constexpr std::size_t kPrimaryTile = WhittedTracer::kMaxTile;

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
  const PinholeFrame pinhole(camera, frame.width, frame.height);
  const bool lens = camera.aperture > 0.f;
  // One pinhole ray through each pixel centre (rt_whitted): the rays of a row are coherent, so
  // they are traced as Embree streams and each hit is then shaded as radiance() would
  // (radianceAt). With SDF objects the per-pixel ray keeps its place between
  // beginSdfPixel and storeSdfPixel, which count its sphere-tracing steps.
  if (spp_ == 1 && !lens && !steps) {
    const RtScene& rt = world.rtScene();
    tbb::parallel_for(0, frame.height, [&](int y) {
      RTCRayHit tile[kPrimaryTile];  // RTC_ALIGN(16), as rtcIntersect1M requires
      for (int x0 = 0; x0 < frame.width; x0 += int(kPrimaryTile)) {
        const int n = std::min(int(kPrimaryTile), frame.width - x0);
        for (int i = 0; i < n; ++i) {
          const Ray ray = pinhole.ray(float(x0 + i) + 0.5f, float(y) + 0.5f);
          setEmbreeRay(tile[i].ray, ray.origin, ray.direction, 0.f,
                       std::numeric_limits<float>::infinity());
          tile[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
          tile[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        }
        rt.intersectTile({tile, std::size_t(n)}, true);
        Ray rays[kPrimaryTile];
        Hit hits[kPrimaryTile];
        const Hit* found[kPrimaryTile];
        std::uint32_t seeds[kPrimaryTile];
        vec3 colors[kPrimaryTile];
        const RayCone* cones[kPrimaryTile];
        for (int i = 0; i < n; ++i) {
          const RTCRay& r = tile[i].ray;
          rays[i] = {vec3(r.org_x, r.org_y, r.org_z), vec3(r.dir_x, r.dir_y, r.dir_z)};
          found[i] = rt.hitOf(tile[i], hits[i], tracer.wantsHitNormal()) ? &hits[i] : nullptr;
          seeds[i] = std::uint32_t(y * frame.width + x0 + i);
          cones[i] = cone;
        }
        // The tile's shadow rays and secondary rays go to Embree as streams too, level by level.
        const std::size_t m = std::size_t(n);
        tracer.radianceTile({rays, m}, {found, m}, {seeds, m}, 1, {cones, cone ? m : 0},
                            {colors, m});
        for (int i = 0; i < n; ++i) {
          for (int ch = 0; ch < 3; ++ch) out.setF(x0 + i, y, ch, colors[i][ch]);
          out.setF(x0 + i, y, 3, 1.f);
        }
      }
    });
    c.count("rays", double(tracer.raysTraced()));
    c.count("samples", double(frame.width) * frame.height);
    return;
  }
  tbb::parallel_for(0, frame.height, [&](int y) {
    std::vector<int> lensStratum(std::size_t(spp_), 0);
    for (int x = 0; x < frame.width; ++x) {
      const std::uint32_t pixel = std::uint32_t(y * frame.width + x);
      // The same pixel pattern and seeds as rt_whitted, so that the two differ only by the lens.
      const std::uint32_t pixelSeed = pcgHash(pixel);
      const std::uint32_t lensSeed = pcgHash(pixel ^ 0x4c454e53u);  // "LENS"
      // A pinhole (rt_whitted) never reads the lens sample: skip its shuffle and strata.
      if (lens) shuffle(lensStratum, lensSeed);
      beginSdfPixel();
      vec3 sum(0.f);
      for (int s = 0; s < spp_; ++s) {
        const vec2 offset = spp_ == 1 ? vec2(0.5f) : stratifiedSample(s, spp_, pixelSeed);
        const float px = float(x) + offset.x, py = float(y) + offset.y;
        const Ray ray =
            lens ? thinLensRay(camera, frame.width, frame.height, px, py,
                               stratifiedSample(lensStratum[std::size_t(s)], spp_, lensSeed))
                 : pinhole.ray(px, py);  // == thinLensRay with no aperture
        sum += tracer.radiance(ray, 1,
                               spp_ == 1 ? pixel : pcgHash(pixel * 4096u + std::uint32_t(s)), cone);
      }
      storeSdfPixel(steps, x, y);
      const vec3 color = sum / float(spp_);
      for (int ch = 0; ch < 3; ++ch) out.setF(x, y, ch, color[ch]);
      out.setF(x, y, 3, 1.f);
    }
  });
  c.count("rays", double(tracer.raysTraced()));
  c.count("samples", double(spp_) * frame.width * frame.height);
}

}  // namespace diptych
