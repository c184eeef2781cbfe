#include "passes/rt/rt_whitted.h"

#include <algorithm>
#include <vector>

#include "engine/rt/camera_rays.h"
#include "engine/rt/whitted.h"
#include "passes/rt/texture_supersample.h"

namespace diptych {

ParamSchema RtWhittedPass::schema() {
  ParamSchema s = RtDistributedPass::schema(1);
  s.push_back(ParamSpec::integer(
      "texture_samples", 1, 1, 64,
      "N: each pixel's texture colour averaged over N x N sub-pixel rays (texture_supersample's "
      "signal: the texture_filtering slot's exact answer); 1: the pixel centre's lookup"));
  return s;
}

std::int64_t whittedTextureRow(const Scene& scene, const WorldGeometry& geometry, const RtScene& rt,
                               const PinholeFrame& pinhole, int n, int y, std::span<vec4> out,
                               const WhittedTracer& tracer, std::span<SecondarySignals> secondary) {
  // Coverage as the reference sees it: a pixel whose centre ray misses shows the environment, so
  // its footprint is not traced (a plane to the horizon leaves much of the frame sky).
  // And the secondary rays that reach a colour texture, whose footprint is traced too.
  constexpr std::size_t kTile = WhittedTracer::kMaxTile;
  thread_local std::vector<std::uint8_t> covered;  // per thread, reused row after row
  thread_local std::vector<FootprintTarget> targets;
  covered.resize(out.size());
  targets.assign(out.size(), FootprintTarget{});
  std::int64_t traced = std::int64_t(out.size());
  const CameraRays camera{rt, scene, geometry};
  for (std::size_t x0 = 0; x0 < out.size(); x0 += kTile) {
    const std::size_t count = std::min(kTile, out.size() - x0);
    Ray rays[kTile];
    Hit hits[kTile];
    const Hit* found[kTile];
    for (std::size_t i = 0; i < count; ++i)
      rays[i] = pinhole.ray(float(x0 + i) + 0.5f, float(y) + 0.5f);
    camera.intersectRays({rays, count}, {hits, count}, {found, count}, false);
    for (std::size_t i = 0; i < count; ++i) {
      covered[x0 + i] = found[i] != nullptr;
      if (const Hit* h = found[i])
        targets[x0 + i] = texturedSecondariesAt(tracer, scene, geometry, rt, rays[i], *h, traced);
    }
  }
  const SecondaryFootprint footprint{tracer, targets, secondary};
  return traced +
         supersampleTextureRow(scene, geometry, rt, pinhole, covered, n, y, out, &footprint);
}

}  // namespace diptych
