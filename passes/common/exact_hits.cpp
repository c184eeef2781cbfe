#include "passes/common/exact_hits.h"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "engine/graph/render_world.h"
#include "passes/common/hits_texel.h"

namespace diptych {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
  // Only what PinholeFrame reads: the pixel-centre rays the lift intersects.
  return a.position == b.position && a.target == b.target && a.up == b.up &&
         a.verticalFov == b.verticalFov;
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
  tbb::parallel_for(0, height_, [&](int y) {
    SurfaceHit* row = hits_.data() + std::size_t(y) * std::size_t(width_);
    for (int x = 0; x < width_; ++x) {
      const auto hit = exactTexel(hits, geometry, pinhole, x, y);
      row[x] = hit ? *hit : SurfaceHit{};  // instance -1: background
    }
  });
  camera_ = camera;
  ++builds_;
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
