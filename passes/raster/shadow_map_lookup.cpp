// Shadow-map lookup: a full-screen fragment pass per light (shaders/shadow_map_lookup.frag) that
// rebuilds each pixel's exact surface point from the visibility buffer and compares it with the
// light's map under the chosen bias and filter.
#include <cmath>
#include <cstdint>
#include <string>

#include "engine/gl/bindings.h"
#include "engine/gl/debug.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "passes/raster/shadow_map_gl.h"

namespace diptych::shadowmap {

namespace {

// std430 layouts of ShadowLayers / ShadowLights in shaders/shadow_map_lookup.frag.
struct GpuLayer {
  mat4 viewProj, invViewProj;
};
struct GpuShadowLight {
  std::int32_t kind, firstLayer, layers, pad;
  vec4 positionNear;
  vec4 directionFar;
  vec4 texelScaleSize;  // texelScale, lightSize, 0, 0
};
static_assert(sizeof(GpuLayer) == 128 && sizeof(GpuShadowLight) == 64);

template <class T>
void uploadArray(gl::Buffer& buffer, const std::vector<T>& data) {
  const std::size_t bytes = std::max<std::size_t>(sizeof(T), data.size() * sizeof(T));
  if (!buffer.id() || buffer.size() < bytes) buffer = gl::Buffer::create(bytes);
  if (!data.empty()) buffer.upload(0, data.size() * sizeof(T), data.data());
}

}  // namespace

std::vector<vec2> poissonDisk(int count) {
  std::vector<vec2> points;
  std::uint32_t state = 0x9e3779b9u;
  const auto next = [&state] {  // xorshift32 (Marsaglia 2003): deterministic, no library state
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    return float(state >> 8) / float(1u << 24);
  };
  // Start near the densest packing distance for `count` discs and relax on failure.
  float minDistance = 1.6f / std::sqrt(float(count));
  while (int(points.size()) < count) {
    bool placed = false;
    for (int attempt = 0; attempt < 1000 && !placed; ++attempt) {
      const vec2 p(2.f * next() - 1.f, 2.f * next() - 1.f);
      if (glm::dot(p, p) > 1.f) continue;
      placed = true;
      for (const vec2& q : points) placed = placed && glm::distance(p, q) >= minDistance;
      if (placed) points.push_back(p);
    }
    if (!placed) minDistance *= 0.9f;
  }
  return points;
}

void ShadowMapGl::uploadFrusta(const std::vector<LightFrustum>& frusta, const Settings&) {
  std::vector<GpuLayer> layers;
  std::vector<GpuShadowLight> lights;
  for (const LightFrustum& f : frusta) {
    for (const mat4& m : f.viewProj) layers.push_back({m, glm::inverse(m)});
    lights.push_back({int(f.kind), f.firstLayer, f.layers, 0, vec4(f.position, f.zNear),
                      vec4(f.direction, f.zFar), vec4(f.texelScale, f.lightSize, 0.f, 0.f)});
  }
  uploadArray(layers_, layers);
  uploadArray(lights_, lights);
}

void ShadowMapGl::lookup(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                         const Settings& s, const gl::Texture& maps, const gl::Texture& gbuffer,
                         const gl::Texture& visibility) {
  gl::ScopedGlLabel label("shadow_map.lookup");
  uploadFrusta(frusta, s);
  world.glScene().bindStorage();
  const gl::GlShadingBuffers& shading = world.glShading();
  shading.bindStorage();
  layers_.bindBase(GL_SHADER_STORAGE_BUFFER, gl::BINDING_SHADOW_LAYERS);
  lights_.bindBase(GL_SHADER_STORAGE_BUFFER, gl::BINDING_SHADOW_LIGHTS);
  gl::glBindTextureUnit(0, gbuffer.id());
  gl::glBindTextureUnit(1, maps.id());

  const Aabb& b = world.geometry().bounds;
  const float diagonal = b.empty() ? 1.f : glm::length(b.hi - b.lo);
  lookup_.set("uLightCount", shading.lightCount);
  lookup_.set("uResolution", maps.width());
  lookup_.set("uBias", int(s.bias));
  lookup_.set("uFilter", int(s.filter));
  lookup_.set("uKernel", s.kernel);
  lookup_.set("uTaps", s.taps);
  lookup_.set("uConstantBias", s.constantBias);
  lookup_.set("uNormalScale", s.normalScale);
  lookup_.set("uPlaneEpsilon", s.planeEpsilon);
  lookup_.set("uAdaptiveEpsilon", s.adaptiveEpsilon * diagonal);  // scene-scaled, world units
  lookup_.set("uRadius", s.radius);
  lookup_.set("uMaxRadius", s.maxRadius);
  for (int i = 0; i < int(poisson_.size()); ++i)
    lookup_.set(("uPoisson[" + std::to_string(i) + "]").c_str(), poisson_[std::size_t(i)]);

  gl::glDisable(GL_DEPTH_TEST);
  gl::glDisable(GL_BLEND);
  gl::glDisable(GL_CULL_FACE);
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  gl::glViewport(0, 0, visibility.width(), visibility.height());
  lookup_.use();
  emptyVao_.bind();
  const bool layered = visibility.kind() == gl::TextureKind::Tex2DArray;
  for (int light = 0; light < visibility.layers(); ++light) {
    lookupFbo_.attachColor(0, visibility, 0, layered ? light : -1);
    lookupFbo_.checkComplete("shadow_map.lookup");
    lookupFbo_.bind();
    // A layer without a light (a scene with no lights still has one) reads as lit.
    lookup_.set("uLight", light < int(frusta.size()) ? light : -1);
    gl::glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  gl::glBindVertexArray(0);
  gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace diptych::shadowmap
