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
//
// It also keeps the surface points that more than one consumer makes: a pixel whose material
// has reflection or transmission is made a SurfacePoint by rt_reflection, rt_transmission and
// shade alike (makeSurfacePoint, ~540 instructions a pixel, where the Whitted reference makes
// it once), so the frame's first consumer keeps it (point()) and the later ones copy it
// (keptPoint()). Memory: 4 B a pixel plus sizeof(SurfacePoint) (248 B) a shared pixel, at most
// kMaxSharedBytes (rows beyond it are not kept: their consumers make their own).
#include <cstddef>
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
  // Pixel (x, y)'s surface point seen along `incoming`, its camera ray's direction (as every
  // consumer passes it: makeSurfacePoint(scene, geometry, *at(x, y), incoming) bit for bit),
  // made on the frame's first call and kept for the later ones; nullptr where the pixel is not
  // shared (its material has neither reflection nor transmission, or beyond kMaxSharedBytes) or
  // is being made by another thread: the caller makes its own then. Callers never write a point
  // twice concurrently (a pass's rows go to one thread each; passes run one at a time), but a
  // flag per point makes a race harmless all the same.
  const SurfacePoint* point(const Scene& scene, const WorldGeometry& geometry, int x, int y,
                            const vec3& incoming) const;
  // The point a consumer of this frame kept for pixel (x, y) (point()), or nullptr: for the
  // frame's last consumer (shade), which has nobody to keep it for.
  const SurfacePoint* keptPoint(int x, int y) const;
  static constexpr std::size_t kMaxSharedBytes = std::size_t(256) << 20;

  // How many times this buffer was (re)built: once per frame and hits resource, or per distinct
  // hits image and camera.
  int builds() const { return builds_; }

 private:
  friend const ExactHitBuffer& exactHits(RenderWorld&, const CpuImage&, const Camera&);
  friend const ExactHitBuffer& exactHits(PassContext&, ResourceId);
  bool builtFrom(const CpuImage& hits, const Camera& camera) const;
  std::ptrdiff_t sharedSlot(int x, int y) const;  // index into points_, or -1
  void build(RenderWorld& world, const CpuImage& hits, const Camera& camera);

  int width_ = 0, height_ = 0, builds_ = 0;
  std::uint64_t frame_ = ~std::uint64_t(0);  // RenderWorld::frameSerial() it was built in
  ResourceId resource_ = kNoResource;        // the graph resource it was built from, if any
  std::vector<SurfaceHit> hits_;             // instance -1: background
  std::vector<std::uint32_t> source_;        // image path: the texels it was built from
  std::optional<Camera> camera_;             // the camera whose pixel rays lifted them
  // point(): per pixel, its index in its row's shared points (-1: none); per row, the index of
  // its first in points_ (-1: the row is beyond kMaxSharedBytes); per point, 0 (not made),
  // 1 (being made) or 2 (made), read and written through std::atomic_ref.
  std::vector<std::int32_t> sharedIndex_, rowShared_;
  mutable std::vector<SurfacePoint> points_;
  mutable std::vector<std::uint8_t> made_;
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
