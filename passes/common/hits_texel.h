#pragma once
// Decoding the G-buffer hits texel shared by every pass that reads gbuffer.hits:
// RGBA32UI = (instance + 1, primitive, floatBits(u), floatBits(v)); x == 0 is background.
// (u, v) are NaN in a frame whose G-buffer is a visibility buffer (passes/raster/gbuffer.h):
// hitsTexel then names the triangle only; exactTexel and triangleTexel compute them.
#include <bit>
#include <cmath>
#include <limits>
#include <optional>

#include <string>

#include "engine/core/error.h"
#include "engine/graph/cpu_image.h"
#include "engine/rt/ray_triangle.h"
#include "engine/rt/rt_scene.h"
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
// triangle's plane (as the GLSL does).
// `cache`, when given, keeps the last triangle's RayTriangleSetup for the next call with the
// same triangle and ray origin (a row of pixel rays crossing one triangle): the result is the
// same bit for bit.
struct AlongRayCache {
  const WorldMesh* mesh = nullptr;
  std::uint32_t primitive = 0;
  vec3 origin{0.f};
  RayTriangleSetup setup;
};
inline SurfaceHit alongRay(const WorldMesh& mesh, SurfaceHit hit, const Ray& ray,
                           AlongRayCache* cache = nullptr) {
  if (hit.primitive >= mesh.indices.size() / 3)
    throw Error("G-buffer hits texel: primitive " + std::to_string(hit.primitive) +
                " out of range in instance " + std::to_string(hit.instance));
  AlongRayCache local;
  AlongRayCache& c = cache ? *cache : local;
  if (c.mesh != &mesh || c.primitive != hit.primitive || c.origin != ray.origin) {
    const std::uint32_t* i = &mesh.indices[3 * std::size_t(hit.primitive)];
    c = {&mesh, hit.primitive, ray.origin,
         rayTriangleSetup(ray.origin, mesh.positions[i[0]], mesh.positions[i[1]],
                          mesh.positions[i[2]])};
  }
  vec2 uv;
  if (!rayTriangleBarycentrics(c.setup, ray.direction, uv)) uv = vec2(1.f / 3.f);
  // Built from registers into the caller's slot: hit.u, hit.v stored and the whole hit then
  // copied reloaded them as one 16-byte load, a store-forwarding stall per texel (perf annotate:
  // half of this function's time in the exact-hit buffer's build).
  return SurfaceHit{hit.instance, hit.primitive, uv.x, uv.y, hit.analytic};
}

// The texel's mesh; a texel naming no instance of `world` (a G-buffer of another scene, a
// corrupt texture) is an Error, as in shadowReceiver, not an out-of-range read.
inline const WorldMesh& texelMesh(const WorldGeometry& world, const SurfaceHit& hit) {
  if (hit.instance < 0 || std::size_t(hit.instance) >= world.meshes.size())
    throw Error("G-buffer hits texel: instance " + std::to_string(hit.instance) + " out of range");
  return world.meshes[std::size_t(hit.instance)];
}

// The texel's point on the rasterized triangle (no analytic lift): its own (u, v), or where the
// G-buffer left them NaN (a visibility buffer), those of the pixel-centre ray (alongRay).
inline std::optional<SurfaceHit> triangleTexel(const CpuImage& hits, const WorldGeometry& world,
                                               const PinholeFrame& pinhole, int x, int y) {
  auto hit = hitsTexel(hits, x, y);
  if (hit && std::isnan(hit->u))
    hit = alongRay(texelMesh(world, *hit), *hit, pinhole.ray(x + 0.5f, y + 0.5f));
  return hit;
}

// An impostor texel (kImpostorPrimitive, engine/scene/world_geometry.h) names the sphere, not a
// triangle: it is lifted the same way (liftToAnalytic along the pixel's ray). Where the exact
// sphere is missed after all (the impostor's test is conservative: a sliver of a pixel at the
// silhouette) the result is not analytic, and the pixel's ray is to be traced instead
// (tracedTexel), which finds what lies behind.
inline SurfaceHit liftedImpostor(const WorldGeometry& world, const SurfaceHit& texel,
                                 const Ray& ray) {
  const WorldMesh& mesh = texelMesh(world, texel);
  if (!mesh.analytic || mesh.analytic->sdf)
    throw Error("G-buffer hits texel: instance " + std::to_string(texel.instance) +
                " has no analytic surface, but the texel names no triangle");
  return liftToAnalytic(world, {texel.instance, 0u, 0.f, 0.f, false}, ray);
}
// The closest hit of a pixel's ray (instance -1: none), for the impostor texels that missed.
inline SurfaceHit tracedTexel(const RtScene& rt, const Ray& ray) {
  Hit h;
  if (!rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity(), h, false))
    return SurfaceHit{};
  return SurfaceHit{h.instance, h.primitive, h.u, h.v, h.analytic};
}
// The texel as the exact producers see it: the triangle point (triangleTexel: in a visibility
// buffer, (u, v) of the pixel-centre ray, primaryRay bit for bit, through the named triangle,
// computed here in C++), and a hit on the tessellation of an analytic instance (quadric or SDF)
// moved onto the exact surface along that ray (liftToAnalytic), so rt_shadows, rt_reflection,
// rt_transmission and the CPU shade pass shade the point the Whitted reference finds; raster
// producers keep reading the GL texel. Those passes read it from the frame's exact-hit buffer
// (exact_hits.h), built once from this. `pinhole`: the camera frame at the hits image's size,
// built once per image by per-pixel loops (primaryRay would rebuild it for every texel; the ray
// is the same bit for bit).
// `rt`: where impostor texels (above) that miss their sphere are traced; without it such a
// texel is an Error.
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const PinholeFrame& pinhole, int x, int y,
                                            const RtScene* rt = nullptr) {
  auto hit = hitsTexel(hits, x, y);
  if (!hit) return hit;
  const WorldMesh& mesh = texelMesh(world, *hit);
  const bool computed = !std::isnan(hit->u);
  if (computed && !mesh.analytic) return hit;
  const Ray ray = pinhole.ray(x + 0.5f, y + 0.5f);
  if (!computed && hit->primitive == kImpostorPrimitive) {
    const SurfaceHit lifted = liftedImpostor(world, *hit, ray);
    if (lifted.analytic) return lifted;
    if (!rt)
      throw Error("G-buffer hits texel: the impostor of instance " + std::to_string(hit->instance) +
                  " at pixel " + std::to_string(x) + "," + std::to_string(y) +
                  " missed its sphere, and no ray-traced scene was given to trace the pixel");
    const SurfaceHit traced = tracedTexel(*rt, ray);
    return traced.instance < 0 ? std::nullopt : std::optional<SurfaceHit>(traced);
  }
  if (!computed) hit = alongRay(mesh, *hit, ray);
  if (mesh.analytic) hit = liftToAnalytic(world, *hit, ray);
  return hit;
}
inline std::optional<SurfaceHit> exactTexel(const CpuImage& hits, const WorldGeometry& world,
                                            const Camera& camera, int x, int y,
                                            const RtScene* rt = nullptr) {
  return exactTexel(hits, world, PinholeFrame(camera, hits.desc.width, hits.desc.height), x, y, rt);
}

}  // namespace diptych
