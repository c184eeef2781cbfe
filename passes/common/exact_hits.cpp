#include "passes/common/exact_hits.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/shading/shading.h"
#include "passes/common/hits_texel.h"

namespace diptych {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
  // Only what PinholeFrame reads: the pixel-centre rays the lift intersects.
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.verticalFov == b.verticalFov;
}

// exactTexel() of the RGBA32UI texel t (its four words) at pixel (x, y), bit for bit (test
// ExactHits.EqualsLiftingEachTexel), in fewer steps: the words read in place from the row, and
// on an analytic instance the lift tried first, since its hit replaces the triangle point's
// (u, v) altogether: alongRay then runs only where the lift misses (a silhouette texel).
// cache: the row's last triangle (alongRay; all of a row's rays leave the camera's position).
// direction: the pixel-centre ray's (PinholeFrame::rowDirections, == ray()'s bit for bit).
// traced: whose RtScene traces an impostor texel's ray where it misses its sphere (built on that
// first need only).
SurfaceHit liftedTexel(const std::uint32_t* t, const WorldGeometry& world, RenderWorld& traced,
                       const PinholeFrame& pinhole, const vec3& direction, AlongRayCache& cache) {
  if (t[0] == 0u) return SurfaceHit{};  // instance -1: background
  SurfaceHit hit{int(t[0] - 1u), t[1], std::bit_cast<float>(t[2]), std::bit_cast<float>(t[3])};
  const WorldMesh& mesh = texelMesh(world, hit);  // throws for a forged instance
  const bool computed = !std::isnan(hit.u);
  if (computed && !mesh.analytic) return hit;
  const Ray ray{pinhole.position(), direction};
  if (!computed && hit.primitive == kImpostorPrimitive) {  // a sphere's impostor: no triangle
    const SurfaceHit lifted = liftedImpostor(world, hit, ray);
    return lifted.analytic ? lifted : tracedTexel(traced.rtScene(), ray);
  }
  // A forged primitive is an error whether or not the lift would hit (alongRay's check).
  if (mesh.analytic && hit.primitive < mesh.indices.size() / 3) {
    const SurfaceHit lifted = liftToAnalytic(world, hit, ray);
    if (lifted.analytic) return lifted;
  }
  return computed ? hit : alongRay(mesh, hit, ray, &cache);
}

}  // namespace

bool ExactHitBuffer::builtFrom(const CpuImage& hits, const Camera& camera) const {
  return resource_ == kNoResource && camera_ && sameCamera(*camera_, camera) &&
         width_ == hits.desc.width && height_ == hits.desc.height && source_ == hits.words;
}

void ExactHitBuffer::build(RenderWorld& world, const CpuImage& hits, const Camera& camera) {
  // Forget the keys first: a build that throws (a forged texel, hits_texel.h) leaves hits_
  // half written, which no later call may take for a finished build.
  camera_.reset();
  frame_ = ~std::uint64_t(0);
  resource_ = kNoResource;
  width_ = hits.desc.width;
  height_ = hits.desc.height;
  // Every element is written below: resize keeps last frame's storage (no fill, no page faults).
  hits_.resize(std::size_t(width_) * std::size_t(height_));
  const PinholeFrame pinhole(camera, width_, height_);
  const WorldGeometry& geometry = world.geometry();
  const bool rgba = hits.channels() == 4;
  // The instances whose pixels several consumers make a SurfacePoint of (point()): rt_reflection's
  // and rt_transmission's candidates (rt_secondary.cpp's test), all of which shade makes too.
  const Scene& scene = world.scene();
  std::vector<char> shared(scene.instances.size());
  for (std::size_t i = 0; i < shared.size(); ++i) {
    const Material& m = scene.material(scene.meshes[scene.instances[i].mesh].material);
    shared[i] = shading::materialHasReflection(m) || shading::materialHasTransmission(m);
  }
  sharedIndex_.resize(hits_.size());
  rowShared_.resize(std::size_t(height_));
  tbb::parallel_for(0, height_, [&](int y) {
    SurfaceHit* row = hits_.data() + std::size_t(y) * std::size_t(width_);
    if (rgba) {
      const std::uint32_t* texel = hits.row(y);
      AlongRayCache cache;
      // The row's pixel-centre directions at once (vectorised), also where no texel needs one.
      thread_local std::vector<vec3> directions;
      directions.resize(std::size_t(width_));
      pinhole.rowDirections(y, directions);
      for (int x = 0; x < width_; ++x, texel += 4)
        row[x] = liftedTexel(texel, geometry, world, pinhole, directions[std::size_t(x)], cache);
    } else {
      for (int x = 0; x < width_; ++x) {
        const auto hit = exactTexel(hits, geometry, pinhole, x, y, &world.rtScene());
        row[x] = hit ? *hit : SurfaceHit{};  // instance -1: background
      }
    }
    std::int32_t* index = sharedIndex_.data() + std::size_t(y) * std::size_t(width_);
    std::int32_t count = 0;
    for (int x = 0; x < width_; ++x)
      index[x] = row[x].instance >= 0 && shared[std::size_t(row[x].instance)] ? count++ : -1;
    rowShared_[std::size_t(y)] = count;
  });
  // Rows' counts to their first point's index, rows past the budget left out.
  constexpr std::size_t kMaxPoints = kMaxSharedBytes / sizeof(SurfacePoint);
  std::size_t points = 0;
  for (std::int32_t& first : rowShared_) {
    const std::size_t count = std::size_t(first);
    first = points + count <= kMaxPoints ? std::int32_t(points) : -1;
    if (first >= 0) points += count;
  }
  // Every point is constructed before it is read (point()): resize keeps last frame's storage.
  points_.resize(points);
  made_.assign(points, 0);
  camera_ = camera;
  ++builds_;
}

std::ptrdiff_t ExactHitBuffer::sharedSlot(int x, int y) const {
  const std::int32_t first = rowShared_[std::size_t(y)];
  const std::int32_t index = sharedIndex_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
  return first < 0 || index < 0 ? -1 : std::ptrdiff_t(first) + index;
}

const SurfacePoint* ExactHitBuffer::point(const Scene& scene, const WorldGeometry& geometry, int x,
                                          int y, const vec3& incoming) const {
  const std::ptrdiff_t i = sharedSlot(x, y);
  if (i < 0) return nullptr;
  std::atomic_ref<std::uint8_t> state(made_[std::size_t(i)]);
  std::uint8_t expected = 0;
  if (!state.compare_exchange_strong(expected, 1, std::memory_order_acquire))
    return expected == 2 ? &points_[std::size_t(i)] : nullptr;  // 1: another thread makes it
  // Trivially destructible (surface_point.h): the slot's old value needs no destructor. A throw
  // (a forged hit) leaves it "being made", so later callers make their own and throw too.
  const SurfaceHit& hit = hits_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
  ::new (&points_[std::size_t(i)]) SurfacePoint(makeSurfacePoint(scene, geometry, hit, incoming));
  state.store(2, std::memory_order_release);
  return &points_[std::size_t(i)];
}

const SurfacePoint* ExactHitBuffer::keptPoint(int x, int y) const {
  const std::ptrdiff_t i = sharedSlot(x, y);
  if (i < 0) return nullptr;
  const std::atomic_ref<std::uint8_t> state(made_[std::size_t(i)]);
  return state.load(std::memory_order_acquire) == 2 ? &points_[std::size_t(i)] : nullptr;
}

const ExactHitBuffer& exactHits(PassContext& context, ResourceId hits) {
  RenderWorld& world = context.world();
  ExactHitBuffer& buffer = world.cpuCached<ExactHitBuffer>();
  const std::lock_guard lock(buffer.mutex_);
  // Once per frame: kept across frames, a still camera's timed frames would never pay the lift.
  // One graph runs per frame serial, and a resource version is written once in it.
  if (buffer.frame_ != world.frameSerial() || buffer.resource_ != hits) {
    buffer.build(world, context.cpuRead(hits), context.frame().camera);
    buffer.frame_ = world.frameSerial();
    buffer.resource_ = hits;
    buffer.source_.clear();
  }
  return buffer;
}

const ExactHitBuffer& exactHits(RenderWorld& world, const CpuImage& hits, const Camera& camera) {
  ExactHitBuffer& buffer = world.cpuCached<ExactHitBuffer>();
  const std::lock_guard lock(buffer.mutex_);
  if (buffer.frame_ != world.frameSerial() || !buffer.builtFrom(hits, camera)) {
    buffer.build(world, hits, camera);
    buffer.frame_ = world.frameSerial();
    buffer.resource_ = kNoResource;
    buffer.source_ = hits.words;
  }
  return buffer;
}

}  // namespace diptych
