#include "engine/gl/shading_buffers.h"

#include <algorithm>
#include <map>

#include "engine/core/check.h"
#include "engine/gl/bindings.h"
#include "engine/gl/loader.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/shading/shading.h"
#include "engine/shading/texture_sampling.h"

namespace diptych::gl {
namespace {

// The texture whose alpha multiplies the material's coverage (resolveMaterial: a checker
// replaces the colour texture, and an empty image samples as 1).
const diptych::Texture* coverageTexture(const Scene& scene, const Material& m) {
  if (m.checker || m.colorTexture < 0 || m.colorTexture >= int(scene.textures.size()))
    return nullptr;
  const diptych::Texture& t = scene.textures[std::size_t(m.colorTexture)];
  return t.image.empty() ? nullptr : &t;
}

float texelAlpha(const Image& image, int x, int y) {
  return image.channels >= 4 ? image.at(x, y, 3) : 1.f;  // as sampleTexture's texel()
}

bool isNearest(FilterMode f) {
  return f == FilterMode::Nearest || f == FilterMode::NearestMipmapNearest ||
         f == FilterMode::NearestMipmapLinear;
}

// The 9th vec4 of GpuMaterial: (layer or -1, width, height, flags) with flags = wrapS +
// 4 wrapT + 16 (bilinear) + 32 (alpha-masked). Small integers are exact in float.
struct AlphaLane {
  float layer = -1.f, width = 0.f, height = 0.f, flags = 0.f;
};

int wrapCode(WrapMode w) {
  switch (w) {
    case WrapMode::Repeat:
      return 0;
    case WrapMode::ClampToEdge:
      return 1;
    case WrapMode::MirroredRepeat:
      return 2;
  }
  return 0;
}

// scene_shading.glsl's GpuMaterial, a vec4 a texel (GPU_MATERIAL_TEXELS): nine vec4, then the glTF
// model's three, the four of the textures, the bump map's two and the iridescence's two.
// Which secondary signals some point of the material can have (shading::materialHas*, bounds
// over its textures), as bits of GpuMaterial.modelTransSpec.w: the GL producers' gate before
// rebuilding any surface (scene_shading.glsl sceneHitMay*), as rt_secondary.cpp decides first.
float materialGates(const Material& m) {
  return float((shading::materialHasReflection(m, false) ? 1 : 0) |
               (shading::materialHasReflection(m, true) ? 2 : 0) |
               (shading::materialHasTransmission(m) ? 4 : 0) | (remapsPerTexel(m) ? 8 : 0));
}

void packMaterial(const Material& m, const AlphaLane& lane, std::vector<float>& out) {
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
  out.insert(out.end(), {lane.layer, lane.width, lane.height, lane.flags});
  out.insert(out.end(), {s.baseColor.x, s.baseColor.y, s.baseColor.z, s.metallic,            //
                         s.specularTint.x, s.specularTint.y, s.specularTint.z, s.roughness,  //
                         float(s.model), s.transmission, s.specularWeight, materialGates(m)});
  // --- textures (scene_shading.glsl's GpuMaterial.texColorEmitMrAo .. texRoughness) ---
  // Texture indices as float (-1: none; exact for indices below 2^24), and the glTF inputs that
  // resolveMaterial re-maps per texel with gltfPbrToLecture.
  const float colour = m.checker ? -1.f : float(m.colorTexture);
  // KHR_materials_volume on the raster side: Beer-Lambert over thicknessFactor (docs/materials.md).
  const vec3 thick = m.thickness > 0.f ? shading::volumeTransmittance(
                                             m.attenuationColor, m.attenuationDistance, m.thickness)
                                       : vec3(1.f);
  out.insert(out.end(),
             {colour, float(m.emissionTexture), float(m.metallicRoughnessTexture),
              float(m.occlusionTexture), float(m.normalTexture), m.normalScale, m.occlusionStrength,
              m.transmissionFactor, m.baseColorFactor.x, m.baseColorFactor.y, m.baseColorFactor.z,
              m.metallicFactor, m.roughnessFactor, thick.x, thick.y, thick.z});
  // --- end textures ---
  // The lecture's bump map (scene_shading.glsl sceneBumpMapped): kind, texture, k, delta; wave.
  const BumpMap b = m.bump.value_or(BumpMap{});
  const float kind = !m.bump ? 0.f : b.texture >= 0 ? 1.f : 2.f;
  out.insert(out.end(), {kind, float(b.texture), b.k, b.delta, b.amplitude, b.frequency.x,
                         b.frequency.y, 0.f});
  // KHR_materials_iridescence (scene_shading.glsl sceneMaterialLod, as resolveMaterial).
  out.insert(out.end(), {m.iridescenceFactor, m.iridescenceIor, m.iridescenceThicknessMinimum,
                         m.iridescenceThicknessMaximum, float(m.iridescenceTexture),
                         float(m.iridescenceThicknessTexture), 0.f, 0.f});
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
  // A zero-sized buffer cannot back a buffer texture; one dummy element keeps every view valid.
  static const float dummy[4] = {0, 0, 0, 0};
  return bytes ? Buffer::create(bytes, data) : Buffer::create(sizeof(dummy), dummy);
}

}  // namespace

AlphaDraw alphaDraw(const Scene& scene, int material) {
  const Material& m = scene.material(material);
  if (m.alphaMode != AlphaMode::Mask) return AlphaDraw::Opaque;
  if (coverageTexture(scene, m)) return AlphaDraw::AlphaTested;
  return m.alpha < m.alphaCutoff ? AlphaDraw::Hidden : AlphaDraw::Opaque;
}

void GlShadingBuffers::bind() const {
  materialTexels.bind(UNIT_SCENE_MATERIALS);
  instanceTexels.bind(UNIT_SCENE_INSTANCES);
  lightTexels.bind(UNIT_SCENE_LIGHTS);
  glBindTextureUnit(UNIT_SCENE_ALPHA_MASKS, alphaMasks.id());
  textures.bind();
}

AlphaDraw GlShadingBuffers::alphaDraw(int material) const {
  const std::size_t i = material < 0 || material + 1 >= int(drawModes.size()) ? 0 : material + 1;
  return i < drawModes.size() ? drawModes[i] : AlphaDraw::Opaque;
}

GlShadingBuffers uploadShading(const Scene& scene, const GlSceneBuffers& geometry) {
  GlShadingBuffers out;
  // One layer per distinct colour texture of an alpha-tested material. Layers are as large as
  // the largest such texture (capped at kMaxAlphaMaskSize per side); each texture sits at its
  // own size in the corner of its layer, so that the shader's texel arithmetic is exactly
  // sampleTexture's. Only a texture above the cap is resampled (bilinear, at the new texel
  // centres): the one approximation of this path.
  std::vector<int> materialIndices{-1};
  for (int i = 0; i < int(scene.materials.size()); ++i) materialIndices.push_back(i);
  std::map<const diptych::Texture*, int> layerOf;
  std::vector<const diptych::Texture*> layerTextures;
  int layerWidth = 1, layerHeight = 1;
  for (int m : materialIndices) {
    out.drawModes.push_back(alphaDraw(scene, m));
    if (out.drawModes.back() != AlphaDraw::AlphaTested) continue;
    const diptych::Texture* t = coverageTexture(scene, scene.material(m));
    if (layerOf.emplace(t, int(layerTextures.size())).second) {
      layerTextures.push_back(t);
      layerWidth = std::max(layerWidth, std::min(t->image.width, kMaxAlphaMaskSize));
      layerHeight = std::max(layerHeight, std::min(t->image.height, kMaxAlphaMaskSize));
    }
  }
  out.alphaMaskLayers = int(layerTextures.size());
  out.alphaMasks = Texture::create2DArray(TextureFormat::R32F, layerWidth, layerHeight,
                                          std::max(1, out.alphaMaskLayers));
  out.alphaMasks.setLabel("scene.alpha_masks");
  std::vector<AlphaLane> lanes(materialIndices.size());
  for (std::size_t k = 0; k < layerTextures.size(); ++k) {
    const diptych::Texture& t = *layerTextures[k];
    const int w = std::min(t.image.width, layerWidth), h = std::min(t.image.height, layerHeight);
    const bool resample = w != t.image.width || h != t.image.height;
    std::vector<float> alpha(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const vec2 uv((float(x) + 0.5f) / float(w), (float(y) + 0.5f) / float(h));
        alpha[std::size_t(y) * std::size_t(w) + std::size_t(x)] =
            resample ? sampleBilinear(t.image, uv, t.wrapS, t.wrapT).w : texelAlpha(t.image, x, y);
      }
    }
    // Image row y goes to GL row y (no flip): the shader fetches texel (x, y) of the image.
    glTextureSubImage3D(out.alphaMasks.id(), 0, 0, 0, GLint(k), w, h, 1, GL_RED, GL_FLOAT,
                        alpha.data());
  }
  for (std::size_t i = 0; i < materialIndices.size(); ++i) {
    const Material& m = scene.material(materialIndices[i]);
    AlphaLane& lane = lanes[i];
    lane.flags = m.alphaMode == AlphaMode::Mask ? 32.f : 0.f;
    if (out.drawModes[i] != AlphaDraw::AlphaTested) continue;
    const diptych::Texture* t = coverageTexture(scene, m);
    const auto layer = layerOf.find(t);
    DIPTYCH_CHECK(layer != layerOf.end(), "an alpha-tested material's texture has no mask layer");
    lane.layer = float(layer->second);
    lane.width = float(std::min(t->image.width, layerWidth));
    lane.height = float(std::min(t->image.height, layerHeight));
    lane.flags +=
        float(wrapCode(t->wrapS) + 4 * wrapCode(t->wrapT) + (isNearest(t->magFilter) ? 0 : 16));
  }

  std::vector<float> materials;
  for (std::size_t i = 0; i < materialIndices.size(); ++i)
    packMaterial(scene.material(materialIndices[i]), lanes[i], materials);
  std::vector<std::int32_t> instances(2 * scene.instances.size(), 0);
  for (const GlMeshRange& range : geometry.meshes) {
    instances[2 * std::size_t(range.instance)] = range.material + 1;
    instances[2 * std::size_t(range.instance) + 1] = std::int32_t(range.firstTriangle);
  }
  std::vector<float> lights;
  for (const Light& l : scene.lights) packLight(l, lights);

  out.materials = makeBuffer(materials.data(), materials.size() * sizeof(float));
  out.instances = makeBuffer(instances.data(), instances.size() * sizeof(std::int32_t));
  out.lights = makeBuffer(lights.data(), lights.size() * sizeof(float));
  // GLSL reads records of GPU_MATERIAL_TEXELS and GPU_LIGHT_TEXELS texels (bindings.glsl).
  DIPTYCH_CHECK(materials.size() == materialIndices.size() * 4 * GPU_MATERIAL_TEXELS,
                "packMaterial wrote a record of another size than GLSL's GpuMaterial");
  DIPTYCH_CHECK(lights.size() == scene.lights.size() * 4 * GPU_LIGHT_TEXELS,
                "packLight wrote a record of another size than GLSL's GpuLight");
  out.materialTexels = BufferTexture::create(out.materials, GL_RGBA32F, 16, "scene.materials");
  out.instanceTexels = BufferTexture::create(out.instances, GL_RG32I, 8, "scene.instances");
  out.lightTexels = BufferTexture::create(out.lights, GL_RGBA32F, 16, "scene.lights");
  out.materialCount = int(scene.materials.size() + 1);
  out.instanceCount = int(scene.instances.size());
  out.lightCount = int(scene.lights.size());
  out.defines = sceneShaderDefines(scene);
  return out;
}

}  // namespace diptych::gl
