#pragma once
// One exact-hit buffer per frame (issue 14): the G-buffer's hits texels decoded and, on analytic
// instances, lifted onto the exact surface (liftToAnalytic) once, then read by every exact
// consumer of the frame (rt_shadows, rt_reflection, rt_transmission, the CPU shade pass)
// instead of each lifting every texel again (up to five double-precision intersections per
// analytic pixel before, one per consumer).
//
// Where the G-buffer is a visibility buffer (passes/raster/gbuffer.h), (u, v) are those of the
// pixel ray through the named triangle, computed on the CPU in this build (exactTexel).
//
// Owner: the RenderWorld (RenderWorld::cpuCached), one buffer per world. It is a cache, not a
// graph resource, so the GL G-buffer and the slot contracts are untouched. Passes key it on the
// graph resource they read (exactHits(PassContext&, ResourceId)): a resource version is written
// once per frame (in-place writes make a new version), so the frame serial and the version name
// its texels, with no look at them. Other callers (tests, tools) pass an image: it is rebuilt
// unless it was built from an equal image (a compare of the texels) and the same camera. Either
// way a stale buffer cannot be read. Memory: 20 B (the hits) a pixel, plus 16 B (the texels) for
// the image path, held for the world's lifetime (6 to 11 MB at 640x480).
#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "engine/graph/cpu_image.h"
#include "engine/graph/pass.h"
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
  // Row y's hits (width() of them; instance -1: background), for per-pixel loops that would
  // otherwise copy each hit into an optional.
  const SurfaceHit* row(int y) const { return hits_.data() + std::size_t(y) * std::size_t(width_); }
  int width() const { return width_; }
  int height() const { return height_; }
  // How many times this buffer was (re)built: once per frame and hits resource, or per distinct
  // hits image and camera.
  int builds() const { return builds_; }

 private:
  friend const ExactHitBuffer& exactHits(RenderWorld&, const CpuImage&, const Camera&);
  friend const ExactHitBuffer& exactHits(PassContext&, ResourceId);
  bool builtFrom(const CpuImage& hits, const Camera& camera) const;
  void build(RenderWorld& world, const CpuImage& hits, const Camera& camera);

  int width_ = 0, height_ = 0, builds_ = 0;
  std::uint64_t frame_ = ~std::uint64_t(0);  // RenderWorld::frameSerial() it was built in
  ResourceId resource_ = kNoResource;        // the graph resource it was built from, if any
  std::vector<SurfaceHit> hits_;             // instance -1: background
  std::vector<std::uint32_t> source_;        // image path: the texels it was built from
  std::optional<Camera> camera_;             // the camera whose pixel rays lifted them
  std::mutex mutex_;
};

// The frame's exact hits for the gbuffer.hits resource `hits` that the calling pass reads, seen
// by the frame's camera: built on the first call of a frame (RenderWorld::frameSerial) for that
// resource, shared by the later calls of that frame. Passes run one at a time, so the reference
// stays valid for the caller's execute().
const ExactHitBuffer& exactHits(PassContext& context, ResourceId hits);

// The same for an image outside a frame graph's passes: rebuilt unless the last build was from
// this path with equal texels and the same camera.
const ExactHitBuffer& exactHits(RenderWorld& world, const CpuImage& hits, const Camera& camera);

}  // namespace diptych
