#include "engine/rt/surface_point.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/rt/ray_offset.h"
#include "engine/scene/analytic_hit.h"
#include "engine/scene/analytic_tangents.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/shading/bump.h"
#include "engine/shading/texture_sampling.h"

namespace diptych {

namespace {

const Texture* textureAt(const Scene& scene, int index) {
  return index >= 0 && index < int(scene.textures.size()) ? &scene.textures[index] : nullptr;
}

// A material's colour and alpha at a point, and the texel they came from.
struct ColourAlpha {
  vec3 color{1.f};  // C
  float alpha = 1.f;
  vec3 texel{1.f};     // the colour texture's rgb, or the checker's colour; 1 without either
  vec3 gltfBase{1.f};  // the glTF base colour: baseColorFactor x the colour texture's rgb, or
                       // the checker's colour (set where re-mapped)
};

// The colour/alpha rule, written once for resolveMaterial and resolvedColorAlpha: C = colour x
// texel (a checker's colour replaces it, and the colour texture with it), alpha x texel.a; where
// the material is re-mapped per texel (remapsPerTexel) and `mr` is its metallic-roughness texel
// (1 without that texture), C becomes the glTF diffuse colour of the base colour at this texel
// (baseColorFactor x texel, or the checker's colour; gltfDiffuseColor, the loader's mapping:
// engine/scene/gltf_pbr.h).
// sample(texture) reads a texture at the point, at the caller's level. Inline: it runs per hit.
template <class Sample>
inline ColourAlpha colourAlpha(const Scene& scene, const Material& material, vec2 uv,
                               const vec4* mr, const Sample& sample) {
  ColourAlpha c{.color = material.color, .alpha = material.alpha};
  vec3 textured(1.f);  // the colour texture's rgb; 1 under a checker, as the glTF base colour
  if (material.checker) {
    c.color = c.texel = checkerColor(*material.checker, uv);
  } else if (const Texture* t = textureAt(scene, material.colorTexture)) {
    const vec4 texel = sample(*t);
    textured = c.texel = vec3(texel.x, texel.y, texel.z);
    c.color *= c.texel;
    c.alpha *= texel.w;
  }
  if (mr) {
    // A checker replaces the base colour, as resolveMaterial's baseColor (the glTF model's).
    c.gltfBase = material.checker ? c.texel : vec3(material.baseColorFactor) * textured;
    c.color = gltfDiffuseColor(c.gltfBase, material.metallicFactor * mr->z);
  }
  return c;
}

// The mapped coefficients into m; C is left to the caller (colourAlpha computes the same value).
void setLecture(shading::ShadingMaterial& m, const LectureCoefficients& k) {
  m.kd = k.kd;
  m.ks = k.ks;
  m.exponent = k.exponent;
  m.specularColor = k.specularColor;
  m.kps = k.kps;
  m.mirrorColor = k.mirrorColor;
  m.kt = k.kt;
  m.transmitColor = k.transmitColor;
}

}  // namespace

shading::ShadingMaterial resolveMaterial(const Scene& scene, const Material& material, vec2 uv,
                                         float uvLod) {
  shading::ShadingMaterial m = shading::toShadingMaterial(material);
  // Level 0 by the texture's magnification filter unless a footprint is given (ray cones):
  // then lambda = uvLod + 0.5 log2(w h) (RTG ch. 20, eq. 20.23's texture size term).
  const auto sampleTexture = [&](const Texture& t) {
    if (!std::isfinite(uvLod)) return diptych::sampleTexture(t, uv);
    const float size = float(t.image.width) * float(t.image.height);
    return sampleTextureLod(t, uv, uvLod + 0.5f * std::log2(std::max(size, 1.f)));
  };
  const Texture* metallicRoughness = textureAt(scene, material.metallicRoughnessTexture);
  const vec4 mr = metallicRoughness ? sampleTexture(*metallicRoughness) : vec4(1.f);
  const bool remap = remapsPerTexel(material);
  const ColourAlpha c = colourAlpha(scene, material, uv, remap ? &mr : nullptr, sampleTexture);
  m.color = c.color;
  m.alpha = c.alpha;
  m.baseColor = material.checker ? c.texel : m.baseColor * c.texel;
  if (const Texture* t = textureAt(scene, material.emissionTexture)) {
    const vec4 e = sampleTexture(*t);
    m.emission *= vec3(e.x, e.y, e.z);
  }
  if (remap) {
    // Sampled, not averaged: the glTF inputs at this texel through the same mapping the loader
    // used for the constants (engine/scene/gltf_pbr.h); C is colourAlpha's, the same value.
    setLecture(
        m, gltfPbrToLecture(c.gltfBase, material.metallicFactor * mr.z,
                            material.roughnessFactor * mr.y, material.transmissionFactor, m.ior));
    m.metallic = glm::clamp(material.metallicFactor * mr.z, 0.f, 1.f);  // the glTF model's inputs
    m.roughness = glm::clamp(material.roughnessFactor * mr.y, 0.f, 1.f);
  }
  if (const Texture* t = textureAt(scene, material.occlusionTexture)) {
    // glTF: occlusion darkens indirect light only; the lecture's ambient k_a is that term.
    const float ao = sampleTexture(*t).x;
    m.ka *= 1.f + material.occlusionStrength * (ao - 1.f);
  }
  // KHR_materials_iridescence: strength times the texture's R; thickness mix(min, max, G).
  if (const Texture* t = textureAt(scene, material.iridescenceTexture))
    m.iridescence *= sampleTexture(*t).x;
  if (const Texture* t = textureAt(scene, material.iridescenceThicknessTexture))
    m.iridescenceThickness = glm::mix(material.iridescenceThicknessMinimum,
                                      material.iridescenceThicknessMaximum, sampleTexture(*t).y);
  return m;
}

vec4 resolvedColorAlpha(const Scene& scene, const Material& material, vec2 uv) {
  // resolveMaterial's colour rule at level 0, without its other coefficients (the lecture mapping
  // per hit): C, or the base colour for the glTF model and for re-mapped materials.
  const Texture* metallicRoughness = textureAt(scene, material.metallicRoughnessTexture);
  const vec4 mr = metallicRoughness ? sampleTexture(*metallicRoughness, uv) : vec4(1.f);
  const bool remap = remapsPerTexel(material);
  const ColourAlpha c = colourAlpha(scene, material, uv, remap ? &mr : nullptr,
                                    [&](const Texture& t) { return sampleTexture(t, uv); });
  if (material.model != ShadingModel::Gltf && !remap) return vec4(c.color, c.alpha);
  // resolveMaterial's baseColor: what the glTF model reads (textureSignalColor), and what a
  // re-mapped material's coefficients are mapped from (withBaseColorSignal).
  return vec4(material.checker ? c.texel : vec3(material.baseColorFactor) * c.texel, c.alpha);
}

shading::ShadingMaterial withBaseColorSignal(shading::ShadingMaterial m, vec3 base, float alpha) {
  const LectureCoefficients k =
      gltfPbrToLecture(base, m.metallic, m.roughness, m.transmission, m.ior);
  setLecture(m, k);
  m.color = k.color;
  m.baseColor = base;
  m.alpha = alpha;
  return m;
}

void applyTextureSignal(SurfacePoint& p, const Scene& scene, const vec4& signal) {
  if (signal.w < 0.f) return;
  if (p.resolved.model != shading::SHADING_MODEL_GLTF && remapsPerTexel(scene.material(p.material)))
    p.resolved = withBaseColorSignal(p.resolved, vec3(signal), signal.w);
  else
    p.resolved = shading::withTextureSignal(p.resolved, vec3(signal), signal.w);
}

vec3 normalMapped(const Texture& map, float scale, const vec3& n, const vec4& tangent, vec2 uv) {
  const vec3 nn = glm::length(n) > 0.f ? glm::normalize(n) : n;
  // Gram-Schmidt: interpolated t and n are no longer orthogonal inside a triangle.
  vec3 t = vec3(tangent) - nn * glm::dot(nn, vec3(tangent));
  const float len = glm::length(t);
  if (!(len > 0.f) || !std::isfinite(len)) return n;
  t /= len;
  const vec3 b = glm::cross(nn, t) * (tangent.w < 0.f ? -1.f : 1.f);
  // glTF 3.9.3: n_ts = (2 texel - 1) * (scale, scale, 1), normalised.
  const vec4 texel = sampleTexture(map, uv);
  const vec3 ts =
      vec3((2.f * texel.x - 1.f) * scale, (2.f * texel.y - 1.f) * scale, 2.f * texel.z - 1.f);
  const vec3 mapped = ts.x * t + ts.y * b + ts.z * nn;
  const float mlen = glm::length(mapped);
  return mlen > 0.f && std::isfinite(mlen) ? mapped / mlen : n;
}

namespace {

// The point's fields in one aggregate initialisation, for triangles and analytic parts alike:
// the material is resolved straight into the result, not zero-filled, built apart and copied
// (the struct is ~250 bytes; issue 14's profile). n is the shading normal on the front side: the
// back sees the same surface. resolvedFrom is scene.material(material).
SurfacePoint assemble(const Scene& scene, const SurfaceHit& hit, const vec3& position,
                      const vec3& magnitude, const vec3& faceNormal, const vec3& n, bool front,
                      vec2 uv, int material, const Material& resolvedFrom) {
  // The back side by a product with -1 (exactly the negation): `front ? n : -n` spilled n and
  // read its y, z back as one 8-byte load across two stores, a store-forwarding stall per point
  // (perf annotate: a quarter of makeSurfacePoint's own time on the spheres).
  const float side = front ? 1.f : -1.f;
  return SurfacePoint{.hit = hit,
                      .position = position,
                      .positionMagnitude = magnitude,
                      .faceNormal = faceNormal,
                      .geometricNormal = side * faceNormal,
                      .shadingNormal = side * n,
                      .frontFacing = front,
                      .uv = uv,
                      .material = material,
                      .resolved = resolveMaterial(scene, resolvedFrom, uv)};
}

// SDF objects: the point is the tracer's (within the tolerance of the surface, outside it);
// the offset scale is the object's box, as for quadrics. uv: (0, 0), as the polygonisation's.
SurfacePoint makeSdfPoint(const Scene& scene, const WorldMesh& mesh, const SurfaceHit& hit,
                          const vec3& incoming) {
  const AnalyticInstance& a = *mesh.analytic;
  const dvec3 p(hit.u, hit.v, std::bit_cast<float>(hit.primitive));
  const vec3 faceNormal = sdfNormal(a, p);
  const bool front = glm::dot(faceNormal, incoming) <= 0.f;
  return assemble(scene, hit, toWorldPoint(a, p), a.magnitude, faceNormal, faceNormal, front,
                  vec2(0.f), mesh.material, scene.material(mesh.material));
}

// The exact surface: position and normal rebuilt from the hit record in double and rounded once
// (a sphere's from its octahedral normal, without trigonometry; its texture uv only when the
// material reads one). The offset scale is the shape's world box (as vertexMagnitude is a
// triangle's): the rounding of the point is at the scale of the shape's coordinates.
SurfacePoint makeAnalyticPoint(const Scene& scene, const WorldMesh& mesh, const SurfaceHit& hit,
                               const vec3& incoming) {
  if (mesh.analytic && mesh.analytic->sdf) return makeSdfPoint(scene, mesh, hit, incoming);
  if (!mesh.analytic || int(hit.primitive) >= partCount(mesh.analytic->shape))
    throw Error("makeSurfacePoint: instance " + std::to_string(hit.instance) +
                " has no analytic part " + std::to_string(hit.primitive));
  const AnalyticInstance& a = *mesh.analytic;
  const int part = int(hit.primitive);
  const vec2 record(hit.u, hit.v);
  vec3 position, faceNormal;
  analyticHitPointAndNormal(a, part, record, position, faceNormal);
  const bool front = glm::dot(faceNormal, incoming) <= 0.f;
  const Material& material = scene.material(mesh.material);
  const vec2 uv = materialReadsUv(material) ? analyticHitUv(a, part, record) : vec2(0.f);
  // Exact: the gradient is the shading normal, unless a normal or bump map perturbs it; t_u and
  // t_v come from the shape's own parameterisation (analyticTangents).
  if (!material.bump && material.normalTexture < 0)
    return assemble(scene, hit, position, a.magnitude, faceNormal, faceNormal, front, uv,
                    mesh.material, material);
  vec3 n = faceNormal, tu, tv;
  analyticTangents(a, part, uv, tu, tv);
  if (material.normalTexture >= 0 && material.normalTexture < int(scene.textures.size())) {
    // The frame computeVertexTangents would give: T along dp/du, B = -dp/dv (glTF's v).
    const float w = glm::dot(glm::cross(n, tu), -tv) < 0.f ? -1.f : 1.f;
    n = normalMapped(scene.textures[material.normalTexture], material.normalScale, n, vec4(tu, w),
                     uv);
  }
  if (material.bump) n = bumpMapNormal(scene, *material.bump, uv, tu, tv, n);
  return assemble(scene, hit, position, a.magnitude, faceNormal, n, front, uv, mesh.material,
                  material);
}

}  // namespace

SurfaceHit liftToAnalytic(const WorldGeometry& world, const SurfaceHit& hit, const Ray& primary) {
  if (hit.analytic || hit.instance < 0 || hit.instance >= int(world.meshes.size())) return hit;
  const WorldMesh& mesh = world.meshes[std::size_t(hit.instance)];
  if (!mesh.analytic) return hit;
  const auto exact = intersectAnalytic(*mesh.analytic, primary.origin, primary.direction, 0.f,
                                       std::numeric_limits<float>::infinity());
  if (!exact) return hit;
  if (mesh.analytic->sdf)
    return {hit.instance, std::bit_cast<std::uint32_t>(float(exact->point.z)), exact->record.x,
            exact->record.y, true};
  return {hit.instance, std::uint32_t(exact->part), exact->record.x, exact->record.y, true};
}

SurfacePoint makeSurfacePoint(const Scene& scene, const WorldGeometry& world, const SurfaceHit& hit,
                              const vec3& incoming) {
  if (hit.instance < 0 || hit.instance >= int(world.meshes.size()))
    throw Error("makeSurfacePoint: instance " + std::to_string(hit.instance) + " out of range");
  const WorldMesh& mesh = world.meshes[hit.instance];
  if (hit.analytic) return makeAnalyticPoint(scene, mesh, hit, incoming);
  if (std::size_t(hit.primitive) >= mesh.indices.size() / 3)
    throw Error("makeSurfacePoint: primitive " + std::to_string(hit.primitive) +
                " out of range in instance " + std::to_string(hit.instance));
  if (!std::isfinite(hit.u) || !std::isfinite(hit.v))  // a visibility texel not resolved
    throw Error("makeSurfacePoint: (u, v) not finite in instance " + std::to_string(hit.instance));

  const vec3 position = interpolatePosition(mesh, hit.primitive, hit.u, hit.v);
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(hit.primitive)];
  const vec3 faceNormal = geometricNormal(mesh, hit.primitive);
  // The face is seen from the front when the ray travels against its normal.
  const bool front = glm::dot(faceNormal, incoming) <= 0.f;
  vec3 n = interpolateNormal(mesh, hit.primitive, hit.u, hit.v);
  const vec2 uv = interpolateUv(mesh, hit.primitive, hit.u, hit.v);
  const Material& material = scene.material(mesh.material);
  if (material.normalTexture >= 0 && material.normalTexture < int(scene.textures.size()) &&
      !mesh.tangents.empty())
    n = normalMapped(scene.textures[material.normalTexture], material.normalScale, n,
                     interpolateTangent(mesh, hit.primitive, hit.u, hit.v), uv);
  if (material.bump && !mesh.uvs.empty()) {  // the lecture's bump mapping (engine/shading/bump.h)
    const SurfaceTangents t =
        triangleTangents(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]],
                         mesh.uvs[tri[0]], mesh.uvs[tri[1]], mesh.uvs[tri[2]]);
    n = bumpMapNormal(scene, *material.bump, uv, t.tu, t.tv, n);
  }
  return assemble(
      scene, hit, position,
      vertexMagnitude(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]),
      faceNormal, n, front, uv, mesh.material, material);
}

vec4 resolvedColorAt(const Scene& scene, const WorldGeometry& world, const SurfaceHit& hit) {
  // makeSurfacePoint's checks and its uv and material, per kind of hit.
  if (hit.instance < 0 || hit.instance >= int(world.meshes.size()))
    throw Error("resolvedColorAt: instance " + std::to_string(hit.instance) + " out of range");
  const WorldMesh& mesh = world.meshes[hit.instance];
  const Material& material = scene.material(mesh.material);
  if (hit.analytic) {
    const AnalyticInstance* a = mesh.analytic ? &*mesh.analytic : nullptr;
    if (a && a->sdf) return resolvedColorAlpha(scene, material, vec2(0.f));
    if (!a || int(hit.primitive) >= partCount(a->shape))
      throw Error("resolvedColorAt: instance " + std::to_string(hit.instance) +
                  " has no analytic part " + std::to_string(hit.primitive));
    const vec2 uv = materialReadsUv(material)
                        ? analyticHitUv(*a, int(hit.primitive), vec2(hit.u, hit.v))
                        : vec2(0.f);
    return resolvedColorAlpha(scene, material, uv);
  }
  if (std::size_t(hit.primitive) >= mesh.indices.size() / 3)
    throw Error("resolvedColorAt: primitive " + std::to_string(hit.primitive) +
                " out of range in instance " + std::to_string(hit.instance));
  if (!std::isfinite(hit.u) || !std::isfinite(hit.v))
    throw Error("resolvedColorAt: (u, v) not finite in instance " + std::to_string(hit.instance));
  return resolvedColorAlpha(scene, material, interpolateUv(mesh, hit.primitive, hit.u, hit.v));
}

Ray spawnRay(const SurfacePoint& p, const vec3& direction) {
  const vec3 n =
      glm::dot(direction, p.geometricNormal) >= 0.f ? p.geometricNormal : -p.geometricNormal;
  return {offsetRayOrigin(p.position, n, p.positionMagnitude), direction, p.time};
}

void atShutterTime(SurfacePoint& p, const WorldGeometry& world, float time) {
  p.time = time;
  const vec3& motion = world.meshes[std::size_t(p.hit.instance)].motion;
  if (time == kFrameTime || motion == vec3(0.f)) return;
  p.position += (time - kFrameTime) * motion;
  // Embree rounds its interpolated translation at the scale of the motion at any time, not of
  // the displacement (review of session 25: a 0.05-unit triangle moving 1000 units missed the
  // offset near t = 0.5), so the offset covers half the motion, the largest translation.
  p.positionMagnitude += 0.5f * glm::abs(motion);
}

}  // namespace diptych
