#include "passes/raster/blend_transmission.h"

#include <algorithm>

#include "engine/gl/forward_renderer.h"
#include "engine/gl/shader.h"
#include "engine/graph/render_world.h"
#include "passes/raster/fullscreen_resolve.h"

namespace diptych {

namespace {

// GL state of the blend producers, one per world: the forward pass's own depth buffer (the
// G-buffer's depth is not an input of the slot) and the mask that zeroes non-transmissive pixels.
struct BlendCache {
  gl::Texture depth;
  FullscreenResolve mask{gl::loadProgram({"fullscreen.vert", "blend_transmission.frag"})};
  void ensure(int width, int height) {
    if (depth && depth.width() == width && depth.height() == height) return;
    depth = gl::Texture::create2D(gl::TextureFormat::D32F, width, height);
    depth.setLabel("blend_transmission.depth");
  }
};

vec3 meshCentre(const WorldMesh& mesh) {
  Aabb box;
  for (const vec3& p : mesh.positions) box.extend(p);
  return box.center();
}

}  // namespace

std::vector<int> transparentBackToFront(const Scene& scene, const WorldGeometry& world,
                                        const mat4& view) {
  std::vector<std::pair<float, int>> keyed;
  for (int i = 0; i < int(world.meshes.size()); ++i) {
    const WorldMesh& mesh = world.meshes[std::size_t(i)];
    if (mesh.indices.empty() || scene.material(mesh.material).kt <= 0.f) continue;
    const vec4 c = view * vec4(meshCentre(mesh), 1.f);
    keyed.emplace_back(-c.z, i);  // view depth: larger is farther
  }
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  std::vector<int> order;
  for (const auto& k : keyed) order.push_back(k.second);
  return order;
}

void BlendTransmissionPass::setup(PassBuilder& b) {
  io_ = slotIo(b, "transmission");
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

  // Lines 1-3 of the lecture's algorithm: opaque polygons with depth (and the background).
  gl::ForwardOptions opaque;
  opaque.instances = gl::InstanceSet::Opaque;
  opaque.behindVisibility = &hits;
  renderer.render(world.forwardScene(), view, out, cache.depth, opaque);

  // Lines 4-10: transparent polygons in Z order, I = I_m + k_t M_t I, depth-tested, not written.
  gl::ForwardOptions transparent;
  transparent.instances = gl::InstanceSet::Transparent;
  if (sorted_)
    transparent.order = transparentBackToFront(world.scene(), world.geometry(), view.view);
  transparent.clear = false;
  transparent.depthWrite = false;
  transparent.blend = true;
  transparent.behindVisibility = &hits;
  renderer.render(world.forwardScene(), view, out, cache.depth, transparent);

  // The slot's contract: 0 where the first surface transmits nothing.
  gl::glBindTextureUnit(0, hits.id());
  cache.mask.draw(world, out);
}

}  // namespace diptych
