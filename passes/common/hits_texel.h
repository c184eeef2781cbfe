#pragma once
// Decoding the G-buffer hits texel shared by every pass that reads gbuffer.hits:
// RGBA32UI = (instance + 1, primitive, floatBits(u), floatBits(v)); x == 0 is background.
// (u, v) are 0 in a frame whose G-buffer is a visibility buffer (passes/raster/gbuffer.h):
// hitsTexel then names the triangle only; exactTexel computes (u, v) whatever the G-buffer wrote.
#include <bit>
#include <optional>

#include "engine/graph/cpu_image.h"
#include "engine/rt/ray_triangle.h"
#include "engine/rt/surface_point.h"

namespace diptych {

inline std::optional<SurfaceHit> hitsTexel(const CpuImage& hits, int x, int y) {
  const std::uint32_t id = hits.u(x, y, 0);
  if (id == 0) return std::nullopt;
  return SurfaceHit{int(id - 1), hits.u(x, y, 1), std::bit_cast<float>(hits.u(x, y, 2)),
                    std::bit_cast<float>(hits.u(x, y, 3))};
}

// The hit's triangle intersected with `ray`: (u, v) by rayTriangleBarycentrics
// (engine/rt/ray_triangle.h, the C++ twin of the G-buffer's GLSL), the centroid for a ray in the
// triangle's plane (as the GLSL does). The texel's own (u, v) are not read.
inline SurfaceHit alongRay(const WorldMesh& mesh, SurfaceHit hit, const Ray& ray) {
  const std::uint32_t* i = &mesh.indices[3 * std::size_t(hit.primitive)];
  vec2 uv;
  if (!rayTriangleBarycentrics(ray.origin, ray.direction, mesh.positions[i[0]],
                               mesh.positions[i[1]], mesh.positions[i[2]], uv))
    uv = vec2(1.f / 3.f);
  hit.u = uv.x;
  hit.v = uv.y;
  return hit;
}

// The texel's point on the rasterized triangle (no analytic lift), with (u, v) computed as
// exactTexel does: what hitsTexel gave before the visibility buffer, for tools that want the
// tessellation's point whatever the G-buffer wrote.
inline std::optional<SurfaceHit> triangleTexel(const CpuImage& hits, const WorldGeometry& world,
                                               const PinholeFrame& pinhole, int x, int y) {
  auto hit = hitsTexel(hits, x, y);
  if (hit)
    hit = alongRay(world.meshes.at(std::size_t(hit->instance)), *hit,
                   pinhole.ray(x + 0.5f, y + 0.5f));
  return hit;
}

// The texel as the exact producers see it: only (instance, primitive) are read; (u, v) are those
// of the pixel-centre ray (the ray the Whitted reference traces, primaryRay bit for bit) through
// that triangle, computed here in C++ (alongRay), so the CPU passes see the same hits whether the
// G-buffer wrote (u, v) or is a visibility buffer (gbuffer.h), and on any GL driver. A hit on the
// tessellation of an analytic instance (quadric or SDF) is then moved onto the exact surface
// along that ray (liftToAnalytic), so rt_shadows, rt_reflection, rt_transmission and the CPU
// shade pass shade the point the Whitted reference finds; raster producers keep reading the
// GL texel. Those passes read it from the frame's exact-hit buffer (exact_hits.h), built once
// from this. `pinhole`: the camera frame at the hits image's size, built once per image by
// per-pixel loops (primaryRay would rebuild it for every texel; the ray is the same bit for bit).
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const PinholeFrame& pinhole, int x, int y) {
  auto hit = hitsTexel(hits, x, y);
  if (!hit) return hit;
  const Ray ray = pinhole.ray(x + 0.5f, y + 0.5f);
  const WorldMesh& mesh = world.meshes.at(std::size_t(hit->instance));
  hit = alongRay(mesh, *hit, ray);
  if (mesh.analytic) hit = liftToAnalytic(world, *hit, ray);
  return hit;
}
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const Camera& camera, int x, int y) {
  return exactTexel(hits, world, PinholeFrame(camera, hits.desc.width, hits.desc.height), x, y);
}

}  // namespace diptych
