// Shadow-map depth render: every shadow-casting mesh from the scene's shared GPU buffers into
// each layer of the D32F array, reversed-Z (see shadow_map_frusta.h), depth only.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>

#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"
#include "passes/raster/screen_rect.h"
#include "passes/raster/shadow_map_gl.h"

namespace diptych::shadowmap {

ShadowMapGl::ShadowMapGl()
    : depth_(gl::loadProgram({"shadow_map_depth.vert", "shadow_map_depth.frag"})),
      depthFbo_(gl::Framebuffer::create()),
      poisson_(poissonDisk(64)) {}

const gl::Texture& ShadowMapGl::mapsFor(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                                        const Settings& settings, Built& built) {
  const int layers = std::max(1, totalLayers(frusta));
  // glPolygonOffset is baked into the depth: only slope bias renders differently.
  const bool slope = settings.bias == Bias::Slope;
  Maps& maps = maps_[{settings.resolution, layers}];
  if (!maps.texture) {
    maps.texture = gl::Texture::create2DArray(gl::TextureFormat::D32F, settings.resolution,
                                              settings.resolution, layers);
    maps.texture.setLabel("shadow_map.maps");
  }
  // The key: the slope offset, every layer's view-projection (it encodes the light and the bounds
  // it is fitted to), then per mesh of the scene buffers whether it casts and how alpha is drawn.
  // The world geometry itself is fixed for the RenderWorld this object lives in.
  std::vector<float> key = {slope ? settings.slopeFactor : 0.f, slope ? settings.slopeUnits : 0.f};
  for (const LightFrustum& f : frusta) {
    key.push_back(float(f.kind));
    for (const mat4& m : f.viewProj)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) key.push_back(m[c][r]);
  }
  const gl::GlSceneBuffers& scene = world.glScene();
  const gl::GlShadingBuffers& shading = world.glShading();
  for (const gl::GlMeshRange& mesh : scene.meshes)
    key.push_back(world.scene().material(mesh.material).castsShadows
                      ? 1.f + float(int(shading.alphaDraw(mesh.material)))
                      : 0.f);
  const bool everyFrame = settings.update == Update::EveryFrame;
  if (!everyFrame && maps.key == key) return maps.texture;
  const auto start = std::chrono::steady_clock::now();
  built.draws = renderMaps(world, frusta, settings, maps.texture);
  built.rendered = true;
  maps.key = std::move(key);
  if (!everyFrame) {
    // A one-time cost: wait for llvmpipe (or the GPU) to finish the maps so that the time is
    // the render's, not just its submission.
    gl::glFinish();
    built.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  return maps.texture;
}

bool boxOutsideFrustum(const Aabb& box, const mat4& viewProj) {
  // The six clip planes are linear in homogeneous clip space (-w <= x, y <= w, 0 <= z <= w for
  // ZERO_TO_ONE), so a box whose 8 corners all fail the same plane lies wholly outside: none
  // of its triangles could survive clipping, and skipping its draw changes no texel. Corners
  // behind a perspective eye (w < 0) are handled by the same linear tests.
  if (box.empty()) return true;
  std::array<int, 6> outside{};
  for (int i = 0; i < 8; ++i) {
    const vec4 c = viewProj * vec4(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                                   i & 4 ? box.hi.z : box.lo.z, 1.f);
    outside[0] += c.x < -c.w;
    outside[1] += c.x > c.w;
    outside[2] += c.y < -c.w;
    outside[3] += c.y > c.w;
    outside[4] += c.z < 0.f;
    outside[5] += c.z > c.w;
  }
  return std::find(outside.begin(), outside.end(), 8) != outside.end();
}

int ShadowMapGl::renderMaps(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                            const Settings& settings, const gl::Texture& maps) {
  gl::ScopedGlLabel label("shadow_map.render");
  const gl::GlSceneBuffers& scene = world.glScene();
  const Scene& source = world.scene();

  gl::glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl::glEnable(GL_DEPTH_TEST);
  gl::glDepthFunc(GL_GREATER);  // reversed-Z: nearer is greater
  gl::glDepthMask(GL_TRUE);
  gl::glDisable(GL_CULL_FACE);  // triangles are two-sided, as in Embree
  gl::glDisable(GL_BLEND);
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glViewport(0, 0, maps.width(), maps.height());
  if (settings.bias == Bias::Slope) {
    // glPolygonOffset adds factor * max|dz/dx, dz/dy| + units * r to the window depth. The
    // parameters keep the usual sign (positive = away from the light); reversed-Z stores
    // farther as smaller, so both are negated here.
    gl::glEnable(GL_POLYGON_OFFSET_FILL);
    gl::glPolygonOffset(-settings.slopeFactor, -settings.slopeUnits);
  }
  // Alpha-masked casters (gl::AlphaDraw): cut out everywhere -> not drawn; textured -> drawn
  // with the discarding variant, compiled on first need so that other scenes keep a depth
  // program without discard.
  const gl::GlShadingBuffers& shading = world.glShading();
  if (shading.anyAlphaTested() && !alphaDepth_) {
    alphaDepth_ = gl::loadProgram({"shadow_map_depth.vert", "shadow_map_depth.frag"},
                                  {{"DIPTYCH_ALPHA_MASK", ""}});
  }
  if (shading.anyAlphaTested()) {
    scene.bind();
    shading.bind();
  }
  scene.vertexArray.bind();
  const std::vector<Aabb>& bounds = meshBounds(world);  // screen_rect.h: one per world
  const GLfloat zero = 0.f;
  int draws = 0;
  for (const LightFrustum& f : frusta) {
    for (int i = 0; i < f.layers; ++i) {
      depthFbo_.attachDepth(maps, 0, f.firstLayer + i);
      depthFbo_.checkComplete("shadow_map.depth");
      depthFbo_.bind();
      gl::glClearNamedFramebufferfv(depthFbo_.id(), GL_DEPTH, 0, &zero);
      depth_.set("uViewProjection", f.viewProj[std::size_t(i)]);
      if (alphaDepth_) alphaDepth_.set("uViewProjection", f.viewProj[std::size_t(i)]);
      // Each cube face (or map) draws only the casters its frustum can see: a GPU engine's
      // per-view culling. Without it every mesh went through every face (docs/benchmarks.md).
      for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
        const gl::GlMeshRange& mesh = scene.meshes[m];
        if (mesh.triangleCount == 0 || !source.material(mesh.material).castsShadows) continue;
        if (m < bounds.size() && boxOutsideFrustum(bounds[m], f.viewProj[std::size_t(i)])) continue;
        const gl::AlphaDraw mode = shading.alphaDraw(mesh.material);
        if (mode == gl::AlphaDraw::Hidden) continue;
        if (mode == gl::AlphaDraw::AlphaTested) {
          alphaDepth_.use();
          alphaDepth_.set("uMaterial", mesh.material);
        } else {
          depth_.use();
        }
        gl::glDrawElements(GL_TRIANGLES, GLsizei(3 * mesh.triangleCount), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(std::uintptr_t(mesh.firstTriangle) * 12));
        ++draws;
      }
    }
  }
  gl::glDisable(GL_POLYGON_OFFSET_FILL);
  gl::glPolygonOffset(0.f, 0.f);
  gl::glBindVertexArray(0);
  gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return draws;
}

}  // namespace diptych::shadowmap
