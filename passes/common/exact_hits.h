#pragma once
// One exact-hit buffer per frame (issue 14): the G-buffer's hits texels decoded and, on analytic
// instances, lifted onto the exact surface (liftToAnalytic) once, then read by every exact
// consumer of the frame (rt_shadows, rt_reflection, rt_transmission, the CPU shade pass)
// instead of each lifting every texel again (up to five double-precision intersections per
// analytic pixel before, one per consumer).
//
// Owner: the RenderWorld (RenderWorld::cpuCached), one buffer per world. It is a cache, not a
// graph resource, so the GL G-buffer and the slot contracts are untouched: exactHits() rebuilds
// it whenever the hits texels or the camera differ from the ones it was built from (a full
// compare of the texels: one memcmp of 16 B a pixel per consumer, no lift), so a stale buffer
// cannot be read, whatever order passes, frames or tests call it in. Memory: 16 B (the texels)
// plus 20 B (the hits) a pixel, held for the world's lifetime (11 MB at 640x480).
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "engine/graph/cpu_image.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/scene.h"

namespace diptych {

class RenderWorld;

class ExactHitBuffer {
 public:
  // Pixel (x, y) as exactTexel() (passes/common/hits_texel.h) returns it, bit for bit.
  std::optional<SurfaceHit> at(int x, int y) const {
    const SurfaceHit& h = hits_[std::size_t(y) * std::size_t(width_) + std::size_t(x)];
    return h.instance < 0 ? std::nullopt : std::optional<SurfaceHit>(h);
  }
  int width() const { return width_; }
  int height() const { return height_; }
  // How many times this buffer was (re)built: once per distinct hits image and camera.
  int builds() const { return builds_; }

 private:
  friend const ExactHitBuffer& exactHits(RenderWorld&, const CpuImage&, const Camera&);
  bool builtFrom(const CpuImage& hits, const Camera& camera) const;
  void build(RenderWorld& world, const CpuImage& hits, const Camera& camera);

  int width_ = 0, height_ = 0, builds_ = 0;
  std::uint64_t frame_ = ~std::uint64_t(0);  // RenderWorld::frameSerial() it was built in
  std::vector<SurfaceHit> hits_;             // instance -1: background
  std::vector<std::uint32_t> source_;        // the hits texels it was built from
  std::optional<Camera> camera_;             // and the camera whose pixel rays lifted them
  std::mutex mutex_;
};

// The frame's exact hits for `hits` (a gbuffer.hits image) seen by `camera`: built on the first
// call of a frame (RenderWorld::frameSerial) or for other hits or another camera, shared by the
// later calls of that frame. Passes run one at a time, so the reference stays
// valid for the caller's execute().
const ExactHitBuffer& exactHits(RenderWorld& world, const CpuImage& hits, const Camera& camera);

}  // namespace diptych
