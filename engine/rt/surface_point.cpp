#include "engine/rt/surface_point.h"

#include <string>

#include "engine/core/error.h"
#include "engine/rt/ray_offset.h"
#include "engine/shading/texture_sampling.h"

namespace diptych {

shading::ShadingMaterial resolveMaterial(const Scene& scene, const Material& material, vec2 uv) {
  shading::ShadingMaterial m = shading::toShadingMaterial(material);
  const auto texture = [&](int index) -> const Texture* {
    return index >= 0 && index < int(scene.textures.size()) ? &scene.textures[index] : nullptr;
  };
  if (material.checker) {
    m.color = checkerColor(*material.checker, uv);
  } else if (const Texture* t = texture(material.colorTexture)) {
    const vec4 c = sampleTexture(*t, uv);
    m.color *= vec3(c.x, c.y, c.z);
    m.alpha *= c.w;
  }
  if (const Texture* t = texture(material.emissionTexture)) {
    const vec4 e = sampleTexture(*t, uv);
    m.emission *= vec3(e.x, e.y, e.z);
  }
  return m;
}

SurfacePoint makeSurfacePoint(const Scene& scene, const WorldGeometry& world, const SurfaceHit& hit,
                              const vec3& incoming) {
  if (hit.instance < 0 || hit.instance >= int(world.meshes.size()))
    throw Error("makeSurfacePoint: instance " + std::to_string(hit.instance) + " out of range");
  const WorldMesh& mesh = world.meshes[hit.instance];
  if (std::size_t(hit.primitive) >= mesh.indices.size() / 3)
    throw Error("makeSurfacePoint: primitive " + std::to_string(hit.primitive) +
                " out of range in instance " + std::to_string(hit.instance));

  SurfacePoint s;
  s.hit = hit;
  s.position = interpolatePosition(mesh, hit.primitive, hit.u, hit.v);
  const std::uint32_t* tri = &mesh.indices[3 * std::size_t(hit.primitive)];
  s.positionMagnitude =
      vertexMagnitude(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
  s.faceNormal = geometricNormal(mesh, hit.primitive);
  // The face is seen from the front when the ray travels against its normal.
  s.frontFacing = glm::dot(s.faceNormal, incoming) <= 0.f;
  s.geometricNormal = s.frontFacing ? s.faceNormal : -s.faceNormal;
  vec3 n = interpolateNormal(mesh, hit.primitive, hit.u, hit.v);
  if (!s.frontFacing) n = -n;
  s.shadingNormal = n;
  s.uv = interpolateUv(mesh, hit.primitive, hit.u, hit.v);
  s.material = mesh.material;
  s.resolved = resolveMaterial(scene, scene.material(mesh.material), s.uv);
  return s;
}

Ray spawnRay(const SurfacePoint& p, const vec3& direction) {
  const vec3 n =
      glm::dot(direction, p.geometricNormal) >= 0.f ? p.geometricNormal : -p.geometricNormal;
  return {offsetRayOrigin(p.position, n, p.positionMagnitude), direction};
}

}  // namespace diptych
