#include "passes/raster/blend_transmission.h"

#include <algorithm>
#include <optional>

#include "engine/gl/bindings.h"
#include "engine/gl/forward_renderer.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "engine/shading/shading.h"
#include "passes/raster/forward_texture_lod.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/gbuffer_surface.h"
#include "passes/raster/screen_rect.h"

namespace diptych {

namespace {

// GL state of the blend producers, one per world: the forward pass's own depth buffer (the
// G-buffer's depth is not an input of the slot), the per-pixel first surface
// (blend_transmission_first.frag) and the mask that zeroes non-transmissive pixels.
struct BlendCache {
  gl::Texture depth;
  gl::Texture first;  // RGBA32F: mask factor, first-surface distance (negative: not transmissive)
  // Compiled for the world's scene on first use; [1] reads the G-buffer's stored surface.
  std::optional<FullscreenResolve> firstSurface[2];
  std::optional<FullscreenResolve> mask;
  void ensure(int width, int height) {
    if (depth && depth.width() == width && depth.height() == height) return;
    depth = gl::Texture::create2D(gl::TextureFormat::D32F, width, height);
    depth.setLabel("blend_transmission.depth");
    first = gl::Texture::create2D(gl::TextureFormat::RGBA32F, width, height);
    first.setLabel("blend_transmission.first");
  }
};

vec3 meshCentre(const WorldMesh& mesh) {
  Aabb box;
  for (const vec3& p : mesh.positions) box.extend(p);
  return box.center();
}

}  // namespace

void renderBlendFirst(RenderWorld& world, const gl::Texture& hits, const gl::Texture* surface,
                      const vec3& eye, const gl::Texture& first, const glm::ivec4& scissor,
                      const gl::Texture* depth) {
  auto& cache = world.glCached<BlendCache>();
  std::optional<FullscreenResolve>& program = cache.firstSurface[surface ? 1 : 0];
  if (!program) {
    std::vector<gl::ShaderDefine> own;
    if (surface) own.push_back({"DIPTYCH_GBUFFER_SURFACE", "1"});  // gl/gbuffer_surface.glsl
    program.emplace(gl::loadProgram({"fullscreen.vert", "blend_transmission_first.frag"},
                                    gl::withDefines(world.glShading().defines, own)));
  }
  gl::glBindTextureUnit(0, hits.id());
  if (surface) gl::glBindTextureUnit(gl::UNIT_GBUFFER_SURFACE, surface->id());
  program->program().set("uEye", eye);
  program->draw(world, first, {.scissor = scissor, .depth = depth});
}

std::vector<int> transparentBackToFront(const Scene& scene, const WorldGeometry& world,
                                        const mat4& view) {
  std::vector<std::pair<float, int>> keyed;
  for (int i = 0; i < int(world.meshes.size()); ++i) {
    const WorldMesh& mesh = world.meshes[std::size_t(i)];
    if (mesh.indices.empty() || !shading::materialHasTransmission(scene.material(mesh.material)))
      continue;
    const vec4 c = view * vec4(meshCentre(mesh), 1.f);
    keyed.emplace_back(-c.z, i);  // view depth: larger is farther
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<int> order;
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

ParamSchema BlendTransmissionPass::schema() {
  return {ParamSpec::boolean("depth_prefill", true,
                             "write the forward passes' depth from the first-surface step so "
                             "that pixels the mask zeroes are rejected by the early depth test, "
                             "not shaded and discarded; same image"),
          forwardTextureLodParam()};
}

void BlendTransmissionPass::setup(PassBuilder& b) {
  depthPrefill_ = b.params().boolean("depth_prefill");
  textureLod_ = forwardTextureLod(b);
  io_ = slotIo(b, "transmission");
  surface_ = readSurface(b, io_.hits);
}

void BlendTransmissionPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const FrameSettings& frame = c.frame();
  const gl::Texture& hits = c.glTexture(io_.hits);
  const gl::Texture& out = c.glTexture(io_.signal);
  auto& cache = world.glCached<BlendCache>();
  cache.ensure(out.width(), out.height());
  auto& renderer = world.glCached<gl::ForwardRenderer>();
  const gl::ForwardView view =
      gl::cameraView(frame.camera, float(out.width()) / float(out.height()));

  // Only pixels covered by a transparent object can have a transmissive first surface, and
  // the mask below zeroes every other pixel: the two forward passes are scissored to the
  // transparent objects' window rectangle, and opaque meshes whose own rectangle misses it are
  // not drawn. This is what keeps re-rendering the opaque scene cheap (docs/benchmarks.md).
  const Scene& scene = world.scene();
  const WorldGeometry& geometry = world.geometry();
  const mat4 viewProj = view.projection * view.view;
  std::vector<PixelRect> rects;
  const PixelRect covered = unionRect(
      meshBounds(world), viewProj, out.width(), out.height(),
      [&](int m) {
        return shading::materialHasTransmission(
            scene.material(geometry.meshes[std::size_t(m)].material));
      },
      rects);
  c.count(
      "blend_scissor_pixels",
      covered.empty() ? 0.0 : double(covered.hi.x - covered.lo.x) * (covered.hi.y - covered.lo.y));

  // The slot's 0 outside the scissor (the passes below clear and write inside it only).
  clearToZero(out);
  if (covered.empty()) return;
  const glm::ivec4 scissor = covered.scissor();

  // The first visible surface of each pixel, rebuilt once here (the mask factor and the distance
  // the forward passes' "strictly behind" test needs) rather than in every forward fragment.
  // With depth_prefill it also writes the forward passes' depth: 1 (reversed-Z near) where the
  // first surface does not transmit, so llvmpipe's early depth test drops those fragments of
  // both passes per 4x4 block before the shader runs (forward.frag would discard them after two
  // texel fetches); the pixels the mask keeps see the cleared depth 0 as before.
  renderBlendFirst(world, hits, surface_ != kNoResource ? &c.glTexture(surface_) : nullptr,
                   view.eye, cache.first, scissor, depthPrefill_ ? &cache.depth : nullptr);

  // Lines 1-3 of the lecture's algorithm: opaque polygons with depth (and the background).
  gl::ForwardOptions opaque;
  opaque.instances = gl::InstanceSet::Opaque;
  opaque.behindVisibility = &hits;
  opaque.transmissiveFirst = &cache.first;
  opaque.scissor = scissor;
  opaque.clearDepth = !depthPrefill_;
  opaque.explicitOrder = true;
  opaque.textureLod = textureLod_;
  for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
    if (!shading::materialHasTransmission(scene.material(geometry.meshes[m].material)) &&
        overlap(rects[m], covered))
      opaque.order.push_back(int(m));
  // Only pixels whose first surface transmits keep their value (the mask below zeroes the
  // rest), so the re-rendered scene is shaded there only (opaque.transmissiveFirst).
  renderer.render(world.forwardScene(), view, out, cache.depth, opaque);

  // Lines 4-10: transparent polygons in Z order, I = I_m + k_t M_t I, depth-tested, not written.
  gl::ForwardOptions transparent;
  transparent.instances = gl::InstanceSet::Transparent;
  if (sorted_) {
    transparent.order = transparentBackToFront(scene, geometry, view.view);
  } else {  // scene order
    for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
      if (shading::materialHasTransmission(scene.material(geometry.meshes[m].material)))
        transparent.order.push_back(int(m));
  }
  transparent.clear = false;
  transparent.depthWrite = false;
  transparent.blend = true;
  transparent.behindVisibility = &hits;
  transparent.transmissiveFirst = &cache.first;
  transparent.scissor = scissor;
  transparent.explicitOrder = true;
  transparent.textureLod = textureLod_;
  renderer.render(world.forwardScene(), view, out, cache.depth, transparent);

  // The slot's contract: 0 where the first surface transmits nothing. Inside the scissor only:
  // outside it every pixel is already 0.
  gl::glBindTextureUnit(gl::UNIT_BLEND_FIRST, cache.first.id());
  if (!cache.mask)
    cache.mask.emplace(gl::loadProgram({"fullscreen.vert", "blend_transmission.frag"}));
  cache.mask->draw(world, out, {.multiply = true, .scissor = scissor});
}

}  // namespace diptych
