#pragma once
// The shading point of a ray hit: exact position from the same arrays Embree traced, normals,
// uv, and the material with its textures and checker resolved at the point.
#include <cstdint>
#include <limits>
#include <type_traits>

#include "engine/scene/camera_math.h"
#include "engine/scene/world_geometry.h"
#include "engine/shading/shading.h"

namespace diptych {

// What identifies a point on the world geometry: Embree's hit, or a visibility-buffer texel.
// On an instance's analytic shape (WorldMesh::analytic, Embree user geometry) `analytic` is
// true, `primitive` is the shape's part and (u, v) its hit record (engine/scene/analytic_hit.h:
// a sphere's octahedral normal, other parts' uv), from which the point is rebuilt exactly. On an
// SDF object (no parameters) (u, v) are the object-space hit point's x and y and `primitive`
// holds the bits of its z.
struct SurfaceHit {
  int instance = -1;
  std::uint32_t primitive = 0;
  float u = 0.f, v = 0.f;  // Embree barycentrics, or the shape's uv
  bool analytic = false;
};

struct SurfacePoint {
  SurfaceHit hit;
  vec3 position{0.f};           // interpolatePosition(): bit-identical to what Embree intersected
  vec3 positionMagnitude{0.f};  // max |vertex coordinate| per axis, for offsetRayOrigin()
  vec3 faceNormal{0.f};         // unit geometric normal of the CCW front face (unflipped)
  vec3 geometricNormal{0.f};    // faceNormal flipped to face the incoming ray
  vec3 shadingNormal{0.f};      // interpolated vertex normal, on the same side as geometricNormal
  bool frontFacing = true;      // the ray arrived on the front (CCW) side
  vec2 uv{0.f};  // analytic sphere: (0, 0) unless materialReadsUv (engine/scene/analytic_hit.h)
  int material = -1;                    // index into Scene::materials (-1: default)
  shading::ShadingMaterial resolved{};  // C with texture/checker, M_E with its texture
  float time = kFrameTime;              // the shutter time of the ray that found it (atShutterTime)
};

// Hot loops construct points in place in raw or reused storage (placement new, never destroyed:
// passes/cpu/shade.cpp, engine/rt/whitted_tile.cpp), which is valid only while this holds.
static_assert(std::is_trivially_destructible_v<SurfacePoint>);

// incoming: direction of the ray that found the hit (from the eye toward the surface); only its
// sign relative to the face matters. A zero vector counts as arriving on the front.
// Throws Error for an instance or primitive out of range.
SurfacePoint makeSurfacePoint(const Scene& scene, const WorldGeometry& world, const SurfaceHit& hit,
                              const vec3& incoming);

// The texture_filtering signal of makeSurfacePoint(scene, world, hit, ...).resolved, bit for bit
// (tested): textureSignalColor (shading.glsl: C, or the glTF model's base colour) and alpha, and
// nothing else: no position, normals, normal or bump map, emission or occlusion texture. The
// texture_filtering slot's exact producer reads only these (passes/rt/texture_supersample.cpp).
// Throws Error as makeSurfacePoint does.
vec4 resolvedColorAt(const Scene& scene, const WorldGeometry& world, const SurfaceHit& hit);

// p (made by makeSurfacePoint, at kFrameTime) as a ray at shutter time `time` found it: a moving
// instance's point displaced by (time - kFrameTime) * WorldMesh::motion, the translation Embree
// applied to that ray (rt_scene_instancing.h), its offset magnitude grown by half the motion so
// that offsetRayOrigin covers the rounding of Embree's translation and of the sum; p.time =
// time, which spawnRay and the shadow receivers pass on. Normals are unchanged: the motion is a
// translation.
void atShutterTime(SurfacePoint& p, const WorldGeometry& world, float time);

// A raster (G-buffer) hit on the tessellation of an analytic instance, moved onto the exact
// surface: the closest hit of `primary` (the pixel's ray, the one the G-buffer intersected)
// with that instance's shape, computed by the very function Embree's callback calls, so the
// hybrid's exact producers shade the point the Whitted reference finds. Any other hit, or a ray
// that misses the shape (impossible for an inscribed tessellation but for rounding), is
// returned unchanged.
SurfaceHit liftToAnalytic(const WorldGeometry& world, const SurfaceHit& hit, const Ray& primary);

// A secondary ray leaving p along the unit `direction`: its origin is offset (offsetRayOrigin,
// engine/rt/ray_offset.h) along the geometric normal on the side the direction points to, so
// reflected rays leave from the front and transmitted rays from the back. It keeps p's time.
Ray spawnRay(const SurfacePoint& p, const vec3& direction);

// The material's parameters at uv: C = color * colorTexture (or the checker, which replaces C),
// alpha = alpha * colorTexture.a, M_E = emission * emissionTexture.
// glTF materials re-mapped per texel (remapsPerTexel: a metallicRoughnessTexture, or under the
// lecture's model a colour texture or a checker on a partly metal or transmissive material) take
// the lecture coefficients of the texel's base colour, metallic and roughness; an occlusionTexture
// scales k_a (the lecture's ambient, glTF's indirect light); the iridescence textures scale the
// film's strength (R) and place its thickness (G). uvLod: log2 of the footprint in uv units
// (engine/rt/ray_cone.h); -infinity (the default) reads level 0 with each texture's magnification
// filter.
shading::ShadingMaterial resolveMaterial(const Scene& scene, const Material& material, vec2 uv,
                                         float uvLod = -std::numeric_limits<float>::infinity());

// The texture_filtering signal's colour (textureSignalColor) and alpha of
// resolveMaterial(scene, material, uv) at level 0 (uvLod -infinity), by the same colour/alpha
// rule (one function for both), without the other coefficients. The colour is C for the
// lecture's model, the base colour for glTF's and for lecture-model materials re-mapped per texel
// (remapsPerTexel), whose coefficients shade maps from it (withBaseColorSignal).
vec4 resolvedColorAlpha(const Scene& scene, const Material& material, vec2 uv);

// A lecture-model material re-mapped per texel (remapsPerTexel) with the signal's base colour
// and coverage in place of its own lookup's: gltfPbrToLecture of that colour and the point's
// metallic and roughness, as resolveMaterial maps its own texel. GL: gl_shade.frag.
shading::ShadingMaterial withBaseColorSignal(shading::ShadingMaterial m, vec3 base, float alpha);

// The texture_filtering slot's signal (colour and coverage; alpha < 0: none, p keeps its own
// level-0 lookup) in place of p's own lookup: the colour the material's model reads
// (shading.glsl withTextureSignal), or on lecture-model materials re-mapped per texel the base
// colour their coefficients are mapped from (withBaseColorSignal; docs/textures.md). CPU shade
// and the Whitted reference's texture_samples apply it alike; GL: gl_shade.frag.
void applyTextureSignal(SurfacePoint& p, const Scene& scene, const vec4& signal);

// A tangent-space normal map applied at uv: n' = normalize(T x + B y + N z) with (x, y, z) =
// (2 texel - 1) * (scale, scale, 1), T Gram-Schmidt-orthogonalised against n and
// B = w cross(N, T) (glTF 2.0, 3.9.3 and 3.7.2.1). n is the interpolated normal on the side the
// front (CCW) side; a degenerate frame returns n unchanged.
vec3 normalMapped(const Texture& map, float scale, const vec3& n, const vec4& tangent, vec2 uv);

}  // namespace diptych
