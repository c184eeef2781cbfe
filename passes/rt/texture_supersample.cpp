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

SurfaceHit surfaceHit(const Hit& h) {
  return {h.instance, h.primitive, h.u, h.v, h.analytic};
}

const Material& materialOf(const Scene& scene, const WorldGeometry& geometry, const Hit& h) {
  return scene.material(geometry.meshes[std::size_t(h.instance)].material);
}

// Whether a point casts a ray of the kind, as WhittedTracer::shadeGiven decides: its material
// first (cheap), then the point's own resolved material (a texture may make it rough or not
// metal; `p` null: the material only).
bool casts(const Material& m, const SurfacePoint* p, bool reflection) {
  if (!(reflection ? shading::materialHasReflection(m) : shading::materialHasTransmission(m)))
    return false;
  return !p || (reflection ? shading::hasReflection(p->resolved, false)
                           : shading::hasTransmission(p->resolved));
}

// One link of a chain of rays of one kind: the ray that `point` (at `depth`, reached along
// `direction`) casts; false at the tracer's depth limit.
bool link(const WhittedTracer& tracer, const SurfacePoint& point, const vec3& direction, int depth,
          bool reflection, Ray& out) {
  WhittedTracer::SecondaryRay s;
  if (!tracer.secondaryRay(point, -direction, depth, 0u, nullptr, reflection, s)) return false;
  out = s.ray;
  return true;
}

// A link traced, one ray (counted in `rays`): its closest hit in h; false on a miss.
bool traceLink(const RtScene& rt, const Ray& ray, Hit& h, std::int64_t& rays) {
  ++rays;
  return rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), h, false);
}

// The next link of a chain: hit h of `ray` as a point that casts the kind again, and the ray it
// casts at `depth`, which replaces `ray`. false where it casts none (or at the depth limit).
bool advance(const WhittedTracer& tracer, const Scene& scene, const WorldGeometry& geometry,
             const Hit& h, bool reflection, int depth, Ray& ray) {
  const Material& m = materialOf(scene, geometry, h);
  if (!casts(m, nullptr, reflection)) return false;
  const SurfacePoint next = makeSurfacePoint(scene, geometry, surfaceHit(h), ray.direction);
  if (!casts(m, &next, reflection)) return false;
  const vec3 arriving = ray.direction;
  return link(tracer, next, arriving, depth, reflection, ray);
}

// The ray of one kind that camera point p casts, followed through `hops` hits that cast that
// kind again: the ray that leaves the last of them. false where the chain breaks (a miss, a hit
// that casts no such ray, the depth limit).
bool followChain(const WhittedTracer& tracer, const Scene& scene, const WorldGeometry& geometry,
                 const RtScene& rt, const SurfacePoint& p, const vec3& direction, bool reflection,
                 int hops, std::int64_t& rays, Ray& out) {
  if (!link(tracer, p, direction, 1, reflection, out)) return false;
  for (int hop = 1; hop <= hops; ++hop) {
    Hit h;
    if (!traceLink(rt, out, h, rays) ||
        !advance(tracer, scene, geometry, h, reflection, 1 + hop, out))
      return false;
  }
  return true;
}

// SecondaryFootprint's rays: each sub-pixel hit's chain followed to its target's last link, those
// links queued per camera stream and traced in streams of kStreamRays, their hits' colours summed
// into the pixel's mean of their kind.
class SecondaryRays {
 public:
  SecondaryRays(const Scene& scene, const WorldGeometry& geometry, const RtScene& rt,
                const SecondaryFootprint& footprint, std::size_t pixels)
      : scene_(scene), geometry_(geometry), rt_(rt), footprint_(footprint), means_(2 * pixels) {}
  // The secondary rays of sub-pixel ray `ray`'s hit h, for pixel i of the row.
  void cast(const Ray& ray, const Hit& h, std::size_t i) {
    const FootprintTarget& target = footprint_.targets[i];
    if (target.kinds == 0) return;
    const Material& m = materialOf(scene_, geometry_, h);
    const bool reflective = (target.kinds & FootprintTarget::kReflected) && casts(m, nullptr, true);
    const bool transmissive =
        (target.kinds & FootprintTarget::kTransmitted) && casts(m, nullptr, false);
    if (!reflective && !transmissive) return;
    const SurfacePoint p = makeSurfacePoint(scene_, geometry_, surfaceHit(h), ray.direction);
    for (const bool reflection : {true, false}) {
      const int k = reflection ? 0 : 1;
      Ray last;
      if ((reflection ? reflective : transmissive) && casts(m, &p, reflection) &&
          followChain(footprint_.tracer, scene_, geometry_, rt_, p, ray.direction, reflection,
                      target.hops[k], traced_, last))
        queue(last, 2 * i + std::size_t(k));
    }
  }
  // Traces what is queued.
  void flush() {
    if (filled_ == 0) return;
    Hit hits[kTile];
    const Hit* found[kTile];
    rt_.intersectRays({rays_, filled_}, {hits, filled_}, {found, filled_}, false);
    traced_ += std::int64_t(filled_);
    for (std::size_t k = 0; k < filled_; ++k) {
      if (!found[k]) continue;
      Mean& mean = means_[owner_[k]];
      mean.sum += resolvedColorAt(scene_, geometry_, surfaceHit(*found[k]));
      ++mean.count;
    }
    filled_ = 0;
  }
  // Pixel i's signals, once every ray is flushed, with its target's hops.
  SecondarySignals signals(std::size_t i) const {
    const FootprintTarget& target = footprint_.targets[i];
    return {means_[2 * i].value(), means_[2 * i + 1].value(), target.hops[0], target.hops[1]};
  }
  std::int64_t traced() const { return traced_; }

 private:
  static constexpr std::size_t kTile = RtScene::kStreamRays;
  void queue(const Ray& ray, std::size_t owner) {
    rays_[filled_] = ray;
    owner_[filled_] = owner;
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

FootprintTarget texturedSecondaries(const WhittedTracer& tracer, const Scene& scene,
                                    const WorldGeometry& geometry, const RtScene& rt,
                                    const SurfacePoint& p, const vec3& direction,
                                    std::uint8_t wanted, std::int64_t& rays) {
  FootprintTarget out;
  for (const bool reflection : {true, false}) {
    const std::uint8_t kind =
        reflection ? FootprintTarget::kReflected : FootprintTarget::kTransmitted;
    if (!(wanted & kind) || !casts(scene.material(p.material), &p, reflection)) continue;
    // Along the chain until a hit reads a colour texture, or the chain breaks.
    Ray ray;
    if (!link(tracer, p, direction, 1, reflection, ray)) continue;
    for (int hop = 0;; ++hop) {
      Hit h;
      if (!traceLink(rt, ray, h, rays)) break;
      if (readsColorTexture(scene, materialOf(scene, geometry, h))) {
        out.kinds |= kind;
        out.hops[reflection ? 0 : 1] = std::uint8_t(hop);
        break;
      }
      if (!advance(tracer, scene, geometry, h, reflection, 2 + hop, ray)) break;
    }
  }
  return out;
}

FootprintTarget texturedSecondariesAt(const WhittedTracer& tracer, const Scene& scene,
                                      const WorldGeometry& geometry, const RtScene& rt,
                                      const Ray& ray, const Hit& h, std::int64_t& rays) {
  const Material& m = materialOf(scene, geometry, h);
  if (!casts(m, nullptr, true) && !casts(m, nullptr, false)) return {};
  const SurfacePoint p = makeSurfacePoint(scene, geometry, surfaceHit(h), ray.direction);
  return texturedSecondaries(tracer, scene, geometry, rt, p, ray.direction,
                             FootprintTarget::kReflected | FootprintTarget::kTransmitted, rays);
}

SecondarySignals secondaryFootprintPixel(const WhittedTracer& tracer, const Scene& scene,
                                         const WorldGeometry& geometry, const RtScene& rt,
                                         const PinholeFrame& pinhole, int n, int x, int y,
                                         const FootprintTarget& target, std::int64_t& rays) {
  SecondarySignals out;
  if (target.kinds == 0) return out;
  vec4 colour;  // the camera hits' own signal: not asked for here
  const std::uint8_t traced = 1;
  const SecondaryFootprint footprint{tracer, {&target, 1}, {&out, 1}, false};
  rays += supersampleTextureRow(scene, geometry, rt, pinhole, {&traced, 1}, n, y, {&colour, 1},
                                &footprint, x);
  return out;
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
          sum += resolvedColorAt(scene, geometry, surfaceHit(*h));
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
