// Shadow-map lookup: a full-screen fragment pass per light (shaders/shadow_map_lookup.frag) that
// rebuilds each pixel's exact surface point from the visibility buffer and compares it with the
// light's map under the chosen bias and filter.
#include <cmath>
#include <cstdint>
#include <string>

#include "engine/gl/bindings.h"
#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "engine/gl/shader_features.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "passes/raster/shadow_map_gl.h"

namespace diptych::shadowmap {

namespace {

// The records of uShadowLayers (RGBA32F) and uShadowLights (RGBA32I) in
// shaders/shadow_map_lookup.frag.
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

// Uploads `data` unless `uploaded` (what the buffer holds) already equals it; a new buffer gets
// a new view `texels` of `format`, 16-byte texels.
template <class T>
void uploadArray(gl::Buffer& buffer, gl::BufferTexture& texels, GLenum format, const char* label,
                 const std::vector<T>& data, std::vector<std::byte>& uploaded) {
  const std::size_t bytes = std::max<std::size_t>(sizeof(T), data.size() * sizeof(T));
  const auto* first = reinterpret_cast<const std::byte*>(data.data());
  const std::vector<std::byte> now(first, first + data.size() * sizeof(T));
  if (buffer.id() && buffer.size() >= bytes && now == uploaded) return;
  if (!buffer.id() || buffer.size() < bytes) {
    buffer = gl::Buffer::create(bytes);
    texels = gl::BufferTexture::create(buffer, format, 16, label);
  }
  if (!data.empty()) buffer.upload(0, data.size() * sizeof(T), data.data());
  uploaded = now;
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
  uploadArray(layers_, layerTexels_, GL_RGBA32F, "shadow_map.layers", layers, uploadedLayers_);
  uploadArray(lights_, lightTexels_, GL_RGBA32I, "shadow_map.lights", lights, uploadedLights_);
}

FullscreenResolve& ShadowMapGl::lookupDraw(RenderWorld& world, ViewKind kind, const Settings& s,
                                           bool interior, bool surface) {
  const int kernel = s.filter == Filter::Pcf ? s.kernel : 1;  // only PCF reads the kernel
  const std::array<int, 7> key = {int(kind),     int(s.bias),  int(s.filter), kernel,
                                  int(interior), int(surface), int(gatherPcf)};
  auto found = lookups_.find(key);
  if (found == lookups_.end()) {
    std::vector<gl::ShaderDefine> defines = {{"DIPTYCH_KIND", std::to_string(int(kind))},
                                             {"DIPTYCH_BIAS", std::to_string(int(s.bias))},
                                             {"DIPTYCH_FILTER", std::to_string(int(s.filter))},
                                             {"DIPTYCH_KERNEL", std::to_string(kernel)}};
    if (interior) defines.push_back({"DIPTYCH_INTERIOR", ""});
    if (surface) defines.push_back({"DIPTYCH_GBUFFER_SURFACE", "1"});
    if (gatherPcf) defines.push_back({"DIPTYCH_PCF_GATHER", ""});
    // The engine's one full-screen triangle (shaders/fullscreen.vert): one lookup per pixel.
    found = lookups_
                .emplace(key, FullscreenResolve(gl::loadProgram(
                                  {"fullscreen.vert", "shadow_map_lookup.frag"},
                                  gl::withDefines(world.glShading().defines, defines))))
                .first;
  }
  return found->second;
}

void ShadowMapGl::lookup(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                         const Settings& s, const gl::Texture& maps, const gl::Texture& gbuffer,
                         const gl::Texture* surface, const gl::Texture& visibility) {
  gl::ScopedGlLabel label("shadow_map.lookup");
  uploadFrusta(frusta, s);
  const gl::GlShadingBuffers& shading = world.glShading();
  layerTexels_.bind(gl::UNIT_SHADOW_LAYERS);
  lightTexels_.bind(gl::UNIT_SHADOW_LIGHTS);
  gl::glBindTextureUnit(0, gbuffer.id());
  gl::glBindTextureUnit(1, maps.id());
  if (surface) gl::glBindTextureUnit(gl::UNIT_GBUFFER_SURFACE, surface->id());

  const Aabb& b = world.geometry().bounds;
  const float diagonal = b.empty() ? 1.f : glm::length(b.hi - b.lo);
  const auto setUniforms = [&](const gl::Program& p) {
    p.set("uLightCount", shading.lightCount);
    p.set("uResolution", maps.width());
    p.set("uTaps", s.taps);
    p.set("uConstantBias", s.constantBias);
    p.set("uNormalScale", s.normalScale);
    p.set("uPlaneEpsilon", s.planeEpsilon);
    p.set("uAdaptiveEpsilon", s.adaptiveEpsilon * diagonal);  // scene-scaled, world units
    p.set("uRadius", s.radius);
    p.set("uMaxRadius", s.maxRadius);
    // Only the Poisson and PCSS programs declare the disc (an unused array is optimised out).
    if (s.filter == Filter::Poisson || s.filter == Filter::Pcss)
      for (int i = 0; i < int(poisson_.size()); ++i)
        p.set(("uPoisson[" + std::to_string(i) + "]").c_str(), poisson_[std::size_t(i)]);
  };

  if (!lookupDepth_ || lookupDepth_.width() != visibility.width() ||
      lookupDepth_.height() != visibility.height()) {
    lookupDepth_ =
        gl::Texture::create2D(gl::TextureFormat::D32F, visibility.width(), visibility.height());
    lookupDepth_.setLabel("shadow_map.lookup_depth");
  }
  const bool layered = visibility.kind() == gl::TextureKind::Tex2DArray;
  for (int light = 0; light < visibility.layers(); ++light) {
    // A layer without a light (a scene with no lights still has one) reads as lit.
    const bool hasLight = light < int(frusta.size());
    const ViewKind kind = hasLight ? frusta[std::size_t(light)].kind : ViewKind::Unshadowed;
    const auto draw = [&](FullscreenResolve& resolve, FullscreenOptions options) {
      setUniforms(resolve.program());
      resolve.program().set("uLight", hasLight ? light : -1);
      options.layer = layered ? light : -1;
      resolve.draw(world, visibility, options);
    };
    // Lit (1) where the lookup discards: background pixels (shadow_map_lookup.frag).
    const vec4 lit(1.f);
    // Receiver-plane bias keeps one pass: its depth gradient comes from screen derivatives,
    // and with the split its visibility moved (MSE 2e-5 on whitted), so it is left exact.
    if (kind != ViewKind::Cube || s.bias == Bias::ReceiverPlane || !splitCube) {
      draw(lookupDraw(world, kind, s, false, surface != nullptr), {.clearColor = lit});
      continue;
    }
    // Cube maps: the interior variant (no cube-edge path) writes every pixel whose taps all
    // stay on its own face and marks the others with depth 1 (Write mode stores its
    // gl_FragDepth); the full shader then runs, behind an early depth test, only there (Test
    // mode, GL_LESS: the triangle's depth 0 passes where 1; shadow_map_lookup.frag). The depth
    // is cleared to 0 ("done") so that background pixels, which the interior pass discards,
    // keep the cleared lit colour and are skipped by the second pass too.
    draw(lookupDraw(world, kind, s, true, surface != nullptr),
         {.depth = &lookupDepth_, .clearColor = lit, .clearDepth = 0.f});
    draw(lookupDraw(world, kind, s, false, surface != nullptr),
         {.depth = &lookupDepth_, .depthMode = FullscreenDepth::Test, .depthFunc = GL_LESS});
  }
}

}  // namespace diptych::shadowmap
