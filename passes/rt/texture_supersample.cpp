#include "passes/rt/texture_supersample.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/graph/scene_needs.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/shading.h"
#include "passes/common/hits_texel.h"

namespace diptych {
namespace {

// Sub-pixel coordinate of stratum i of n along an axis of pixel x: stratum centres are
// deterministic, so N = 1 is exactly the pixel centre.
float stratum(int x, int i, int n) {
  return float(x) + (float(i) + 0.5f) / float(n);
}

// A mean colour and coverage being summed.
struct Mean {
  vec4 sum{0.f};
  int count = 0;
  vec4 value() const { return count > 0 ? sum / float(count) : vec4(-1.f); }
};

// SecondaryFootprint's rays: queued per camera stream, traced in streams of kStreamRays, their
// hits' colours summed into the pixel's mean of their kind.
class SecondaryRays {
 public:
  SecondaryRays(const Scene& scene, const WorldGeometry& geometry, const RtScene& rt,
                const SecondaryFootprint& footprint, std::size_t pixels)
      : scene_(scene), geometry_(geometry), rt_(rt), footprint_(footprint), means_(2 * pixels) {}
  // The secondary rays of sub-pixel ray `ray`'s hit h, for pixel i of the row.
  void cast(const Ray& ray, const Hit& h, std::size_t i) {
    const std::uint8_t kinds = footprint_.kinds[i];
    if (kinds == 0) return;
    const Material& m = scene_.material(geometry_.meshes[std::size_t(h.instance)].material);
    const bool reflective =
        (kinds & SecondaryFootprint::kReflected) && shading::materialHasReflection(m);
    const bool transmissive =
        (kinds & SecondaryFootprint::kTransmitted) && shading::materialHasTransmission(m);
    if (!reflective && !transmissive) return;
    const SurfacePoint p =
        makeSurfacePoint(scene_, geometry_, {h.instance, h.primitive, h.u, h.v, h.analytic},
                         ray.direction);
    // Per point, as the tracer decides (a texture may make this texel rough or not metal).
    if (reflective && shading::hasReflection(p.resolved, false)) queue(p, ray, true, i);
    if (transmissive && shading::hasTransmission(p.resolved)) queue(p, ray, false, i);
  }
  // Traces what is queued.
  void flush() {
    if (filled_ == 0) return;
    Hit hits[kTile];
    const Hit* found[kTile];
    rt_.intersectRays({rays_, filled_}, {hits, filled_}, {found, filled_}, false);
    traced_ += std::int64_t(filled_);
    for (std::size_t k = 0; k < filled_; ++k) {
      const Hit* h = found[k];
      if (!h) continue;
      Mean& mean = means_[owner_[k]];
      mean.sum +=
          resolvedColorAt(scene_, geometry_, {h->instance, h->primitive, h->u, h->v, h->analytic});
      ++mean.count;
    }
    filled_ = 0;
  }
  // Pixel i's signals, once every ray is flushed.
  SecondarySignals signals(std::size_t i) const {
    return {means_[2 * i].value(), means_[2 * i + 1].value()};
  }
  std::int64_t traced() const { return traced_; }

 private:
  static constexpr std::size_t kTile = RtScene::kStreamRays;
  void queue(const SurfacePoint& p, const Ray& ray, bool reflection, std::size_t i) {
    WhittedTracer::SecondaryRay s;
    if (!footprint_.tracer.secondaryRay(p, -ray.direction, 1, 0u, nullptr, reflection, s)) return;
    rays_[filled_] = s.ray;
    owner_[filled_] = 2 * i + (reflection ? 0 : 1);
    if (++filled_ == kTile) flush();
  }
  const Scene& scene_;
  const WorldGeometry& geometry_;
  const RtScene& rt_;
  const SecondaryFootprint& footprint_;
  std::vector<Mean> means_;  // pixel i's: [2 i] reflected, [2 i + 1] transmitted
  Ray rays_[kTile];
  std::size_t owner_[kTile];
  std::size_t filled_ = 0;
  std::int64_t traced_ = 0;
};

}  // namespace

std::uint8_t texturedSecondaries(const WhittedTracer& tracer, const Scene& scene,
                                 const WorldGeometry& geometry, const RtScene& rt,
                                 const SurfacePoint& p, const vec3& direction,
                                 std::uint8_t wanted, std::int64_t& rays) {
  std::uint8_t out = 0;
  for (const bool reflection : {true, false}) {
    const std::uint8_t kind =
        reflection ? SecondaryFootprint::kReflected : SecondaryFootprint::kTransmitted;
    if (!(wanted & kind)) continue;
    // As WhittedTracer::shadeGiven decides whether the point casts the ray.
    if (reflection ? !shading::hasReflection(p.resolved, false)
                   : !shading::hasTransmission(p.resolved))
      continue;
    WhittedTracer::SecondaryRay s;
    if (!tracer.secondaryRay(p, -direction, 1, 0u, nullptr, reflection, s)) continue;
    Hit h;
    ++rays;
    if (rt.intersect(s.ray, 0.f, std::numeric_limits<float>::infinity(), h, false) &&
        readsColorTexture(scene, scene.material(geometry.meshes[std::size_t(h.instance)].material)))
      out |= kind;
  }
  return out;
}

SecondarySignals secondaryFootprintPixel(const WhittedTracer& tracer, const Scene& scene,
                                         const WorldGeometry& geometry, const RtScene& rt,
                                         const PinholeFrame& pinhole, int n, int x, int y,
                                         std::uint8_t kinds, std::int64_t& rays) {
  SecondarySignals out;
  if (kinds == 0) return out;
  vec4 colour;  // the camera hits' own signal: not asked for here
  const SecondaryFootprint footprint{tracer, {&kinds, 1}, {&out, 1}, false};
  rays += supersampleTextureRow(scene, geometry, rt, pinhole, {&kinds, 1}, n, y, {&colour, 1},
                                &footprint, x);
  return out;
}

std::uint8_t texturedSecondariesAt(const WhittedTracer& tracer, const Scene& scene,
                                   const WorldGeometry& geometry, const RtScene& rt,
                                   const Ray& ray, const Hit& h, std::int64_t& rays) {
  const Material& m = scene.material(geometry.meshes[std::size_t(h.instance)].material);
  if (!shading::materialHasReflection(m) && !shading::materialHasTransmission(m)) return 0;
  const SurfacePoint p = makeSurfacePoint(
      scene, geometry, {h.instance, h.primitive, h.u, h.v, h.analytic}, ray.direction);
  return texturedSecondaries(tracer, scene, geometry, rt, p, ray.direction,
                             SecondaryFootprint::kReflected | SecondaryFootprint::kTransmitted,
                             rays);
}

ParamSchema TextureSupersamplePass::schema() {
  return {ParamSpec::integer("samples", kDefaultSamples, 1, 64,
                             "N: N x N stratified sub-pixel rays per pixel (1: the pixel centre)")};
}

void TextureSupersamplePass::setup(PassBuilder& b) {
  samples_ = b.params().integer("samples");
  io_ = slotIo(b, "texture_filtering");
}

void TextureSupersamplePass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const FrameSettings& frame = c.frame();
  const CpuImage& hits = c.cpuRead(io_.hits);
  CpuImage& out = c.cpuWrite(io_.signal);
  // Fetched once, outside the loop (the first call builds the BVH).
  const RtScene& rt = world.rtScene();
  // The camera frames once per image (PinholeFrame::ray == primaryRay bit for bit).
  const PinholeFrame pinhole(frame.camera, frame.width, frame.height);
  std::atomic<std::int64_t> rays = 0;
  tbb::parallel_for(0, frame.height, [&](int y) {
    // Per thread, reused row after row.
    thread_local std::vector<vec4> row;
    thread_local std::vector<std::uint8_t> covered;
    row.resize(std::size_t(frame.width));
    covered.resize(std::size_t(frame.width));
    // Coverage only: lifting a texel onto its analytic shape never changes whether it is one.
    for (int x = 0; x < frame.width; ++x) covered[std::size_t(x)] = hits.u(x, y, 0) != 0u;
    rays += supersampleTextureRow(world.scene(), world.geometry(), rt, pinhole, covered, samples_,
                                  y, row);
    for (int x = 0; x < frame.width; ++x)
      for (int ch = 0; ch < 4; ++ch) out.setF(x, y, ch, row[std::size_t(x)][ch]);
  });
  // The rays traced: N^2 per covered pixel; the uncovered ones trace none.
  c.count("rays", double(rays));
}

std::int64_t supersampleTextureRow(const Scene& scene, const WorldGeometry& geometry,
                                   const RtScene& rt, const PinholeFrame& pinhole,
                                   std::span<const std::uint8_t> covered, int n, int y,
                                   std::span<vec4> out, const SecondaryFootprint* secondary,
                                   int x0) {
  // The row's sub-pixel rays, pixel by pixel in stratum order, go to Embree in coherent streams
  // of kStreamRays (RtScene::intersectRays, as rt_distributed's primary rays): one traversal
  // setup per packet of neighbouring rays instead of one rtcIntersect1 per ray. Each pixel sums
  // its hits in stratum order, so the signal is singleRayPixel's up to the rounding of Embree's
  // packet kernels (docs/ray-tracing.md, "Coherent rays as Embree streams"). Scratch lives on this
  // stack frame: nothing is allocated per pixel or per ray.
  constexpr std::size_t kTile = RtScene::kStreamRays;
  Ray rays[kTile];
  int pixelOf[kTile];
  Hit tileHits[kTile];
  const Hit* found[kTile];
  std::size_t filled = 0;
  std::int64_t traced = 0;
  std::optional<SecondaryRays> footprint;
  if (secondary) footprint.emplace(scene, geometry, rt, *secondary, out.size());
  const bool colours = !secondary || secondary->cameraColours;
  // The pixel whose rays are being summed; its rays may straddle two streams.
  int pixel = -1, count = 0;
  vec4 sum(0.f);
  const auto finish = [&] {
    if (pixel < 0) return;
    out[std::size_t(pixel)] = count > 0 ? sum / float(count) : vec4(-1.f);
  };
  const auto flush = [&] {
    CameraRays{rt, scene, geometry}.intersectRays({rays, filled}, {tileHits, filled},
                                                  {found, filled}, false);
    traced += std::int64_t(filled);
    for (std::size_t i = 0; i < filled; ++i) {
      if (pixelOf[i] != pixel) {
        finish();
        pixel = pixelOf[i];
        count = 0;
        sum = vec4(0.f);
      }
      if (const Hit* h = found[i]) {
        if (colours) {
          sum += resolvedColorAt(scene, geometry,
                                 {h->instance, h->primitive, h->u, h->v, h->analytic});
          ++count;
        }
        if (footprint) footprint->cast(rays[i], *h, std::size_t(pixelOf[i]));
      }
    }
    filled = 0;
  };
  for (int x = 0; x < int(out.size()); ++x) {
    if (!covered.empty() && !covered[std::size_t(x)]) {
      out[std::size_t(x)] = vec4(-1.f);
      continue;
    }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        rays[filled] = pinhole.ray(stratum(x0 + x, i, n), stratum(y, j, n));
        pixelOf[filled] = x;
        if (++filled == kTile) flush();
      }
  }
  if (filled > 0) flush();
  finish();
  if (footprint) {
    footprint->flush();
    for (std::size_t x = 0; x < out.size(); ++x) secondary->out[x] = footprint->signals(x);
    traced += footprint->traced();
  }
  return traced;
}

vec4 TextureSupersamplePass::singleRayPixel(const Scene& scene, const WorldGeometry& geometry,
                                            const RtScene& rt, const PinholeFrame& pinhole, int n,
                                            int x, int y) {
  vec4 sum(0.f);
  int count = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Ray ray = pinhole.ray(stratum(x, i, n), stratum(y, j, n));
      Hit hit;
      if (!CameraRays{rt, scene, geometry}.intersect(ray, hit, false)) continue;
      const SurfacePoint p = makeSurfacePoint(
          scene, geometry, {hit.instance, hit.primitive, hit.u, hit.v, hit.analytic},
          ray.direction);
      sum += vec4(p.resolved.color, p.resolved.alpha);
      ++count;
    }
  return count > 0 ? sum / float(count) : vec4(-1.f);
}

}  // namespace diptych
