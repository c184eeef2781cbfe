#pragma once
// Decoding the G-buffer hits texel shared by every pass that reads gbuffer.hits:
// RGBA32UI = (instance + 1, primitive, floatBits(u), floatBits(v)); x == 0 is background.
#include <bit>
#include <optional>

#include "engine/graph/cpu_image.h"
#include "engine/rt/surface_point.h"

namespace diptych {

inline std::optional<SurfaceHit> hitsTexel(const CpuImage& hits, int x, int y) {
  const std::uint32_t id = hits.u(x, y, 0);
  if (id == 0) return std::nullopt;
  return SurfaceHit{int(id - 1), hits.u(x, y, 1), std::bit_cast<float>(hits.u(x, y, 2)),
                    std::bit_cast<float>(hits.u(x, y, 3))};
}

// The texel as the exact producers see it: a hit on the tessellation of an analytic instance
// (quadric or SDF) is moved onto the exact surface along the pixel-centre ray the G-buffer traced
// (liftToAnalytic), so rt_shadows, rt_reflection, rt_transmission and the CPU shade pass shade the
// point the Whitted reference finds; raster producers keep reading hitsTexel (the triangles).
// Those passes read it from the frame's exact-hit buffer (exact_hits.h), built once from this.
// `pinhole`: the camera frame at the hits image's size, built once per image by per-pixel loops
// (primaryRay would rebuild it for every lifted texel; the ray is the same bit for bit).
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const PinholeFrame& pinhole, int x, int y) {
  auto hit = hitsTexel(hits, x, y);
  if (hit && world.meshes.at(std::size_t(hit->instance)).analytic)
    hit = liftToAnalytic(world, *hit, pinhole.ray(x + 0.5f, y + 0.5f));
  return hit;
}
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const Camera& camera, int x, int y) {
  return exactTexel(hits, world, PinholeFrame(camera, hits.desc.width, hits.desc.height), x, y);
}

}  // namespace diptych
