#include "engine/gl/shading_buffers.h"

#include "engine/gl/loader.h"
#include "engine/rt/shading.h"

namespace diptych::gl {
namespace {

// std430 layout of scene_shading.glsl's GpuMaterial: eight vec4.
void packMaterial(const Material& m, std::vector<float>& out) {
  const shading::ShadingMaterial s = shading::toShadingMaterial(m);
  const bool checker = m.checker.has_value();
  const Checker c = checker ? *m.checker : Checker{};
  const float values[32] = {s.color.x,
                            s.color.y,
                            s.color.z,
                            s.ka,
                            s.kd,
                            s.ks,
                            s.exponent,
                            s.kps,
                            s.specularColor.x,
                            s.specularColor.y,
                            s.specularColor.z,
                            s.ior,
                            s.mirrorColor.x,
                            s.mirrorColor.y,
                            s.mirrorColor.z,
                            s.kt,
                            s.transmitColor.x,
                            s.transmitColor.y,
                            s.transmitColor.z,
                            s.alpha,
                            s.emission.x,
                            s.emission.y,
                            s.emission.z,
                            checker ? 1.f : 0.f,
                            c.colorA.x,
                            c.colorA.y,
                            c.colorA.z,
                            c.scale,
                            c.colorB.x,
                            c.colorB.y,
                            c.colorB.z,
                            m.alphaCutoff};
  out.insert(out.end(), std::begin(values), std::end(values));
}

void packLight(const Light& l, std::vector<float>& out) {
  const shading::ShadingLight s = shading::toShadingLight(l);
  const float values[20] = {float(s.type), s.range,       s.cosInner,    s.cosOuter,
                            s.color.x,     s.color.y,     s.color.z,     s.intensity,
                            s.position.x,  s.position.y,  s.position.z,  s.area,
                            s.direction.x, s.direction.y, s.direction.z, l.castsShadows ? 1.f : 0.f,
                            l.edgeU.x,     l.edgeU.y,     l.edgeU.z,     l.radius};
  out.insert(out.end(), std::begin(values), std::end(values));
}

Buffer makeBuffer(const void* data, std::size_t bytes) {
  // A zero-sized SSBO cannot be bound; keep one dummy element so shaders always see a buffer.
  static const float dummy[4] = {0, 0, 0, 0};
  return bytes ? Buffer::create(bytes, data) : Buffer::create(sizeof(dummy), dummy);
}

}  // namespace

void GlShadingBuffers::bindStorage() const {
  materials.bindBase(GL_SHADER_STORAGE_BUFFER, kSceneMaterialsBinding);
  instances.bindBase(GL_SHADER_STORAGE_BUFFER, kSceneInstancesBinding);
  lights.bindBase(GL_SHADER_STORAGE_BUFFER, kSceneLightsBinding);
}

GlShadingBuffers uploadShading(const Scene& scene, const GlSceneBuffers& geometry) {
  std::vector<float> materials;
  packMaterial(scene.material(-1), materials);
  for (const Material& m : scene.materials) packMaterial(m, materials);
  std::vector<std::int32_t> instances(2 * scene.instances.size(), 0);
  for (const GlMeshRange& range : geometry.meshes) {
    instances[2 * std::size_t(range.instance)] = range.material + 1;
    instances[2 * std::size_t(range.instance) + 1] = std::int32_t(range.firstTriangle);
  }
  std::vector<float> lights;
  for (const Light& l : scene.lights) packLight(l, lights);

  GlShadingBuffers out;
  out.materials = makeBuffer(materials.data(), materials.size() * sizeof(float));
  out.instances = makeBuffer(instances.data(), instances.size() * sizeof(std::int32_t));
  out.lights = makeBuffer(lights.data(), lights.size() * sizeof(float));
  out.materialCount = int(scene.materials.size() + 1);
  out.instanceCount = int(scene.instances.size());
  out.lightCount = int(scene.lights.size());
  return out;
}

}  // namespace diptych::gl
