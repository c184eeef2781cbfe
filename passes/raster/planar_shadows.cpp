#include "passes/raster/planar_shadows.h"

#include <cstdint>

#include "engine/gl/forward_renderer.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/shader.h"
#include "engine/graph/render_world.h"
#include "passes/raster/planar_instances.h"

namespace diptych {

namespace {

struct PlanarShadowsGl {
  gl::Program program = gl::loadProgram({"planar_shadows.vert", "planar_shadows.frag"});
  gl::Framebuffer framebuffer = gl::Framebuffer::create();
  bool found = false;
  std::vector<PlanarInstance> receivers;
};

// The light as a homogeneous point: its centre, or for a directional light the direction toward
// it at infinity.
vec4 homogeneousLight(const Light& light) {
  if (light.type == LightType::Directional) return vec4(-light.direction, 0.f);
  return vec4(light.position, 1.f);
}

}  // namespace

void PlanarShadowsPass::setup(PassBuilder& b) {
  io_ = slotIo(b, "visibility");
}

void PlanarShadowsPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Scene& scene = world.scene();
  const gl::Texture& hits = c.glTexture(io_.hits);
  const gl::Texture& out = c.glTexture(io_.signal);
  auto& state = world.glCached<PlanarShadowsGl>();
  if (!state.found) {
    // A receiver is one planar instance; an instance drawn as several meshes is left out (the
    // hits name the instance, not the mesh, so one plane's shadows would fall on the others).
    std::vector<PlanarInstance> planes =
        findPlanarInstances(world.geometry(), [](const WorldMesh&) { return true; });
    for (const PlanarInstance& p : planes) {
      int meshes = 0;
      for (const WorldMesh& m : world.geometry().meshes) meshes += m.instance == p.instance;
      if (meshes == 1) state.receivers.push_back(p);
    }
    state.found = true;
  }
  const gl::ForwardView eye = gl::cameraView(c.frame().camera, float(out.width()) / out.height());
  const mat4 viewProjection = eye.projection * eye.view;
  const gl::GlSceneBuffers& buffers = world.glScene();
  const bool layered = out.kind() == gl::TextureKind::Tex2DArray;

  gl::glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  gl::glDisable(GL_DEPTH_TEST);
  gl::glDisable(GL_CULL_FACE);  // a projected triangle's winding depends on the light's side
  gl::glDisable(GL_BLEND);
  gl::glDisable(GL_SCISSOR_TEST);
  gl::glEnable(GL_CLIP_DISTANCE0);
  gl::glEnable(GL_CLIP_DISTANCE1);
  gl::glViewport(0, 0, out.width(), out.height());
  gl::glBindTextureUnit(0, hits.id());
  buffers.vertexArray.bind();
  state.program.use();
  state.program.set("uViewProjection", viewProjection);
  const GLfloat lit[4] = {1.f, 1.f, 1.f, 1.f};
  int draws = 0;
  for (int layer = 0; layer < out.layers(); ++layer) {
    state.framebuffer.attachColor(0, out, 0, layered ? layer : -1);
    state.framebuffer.checkComplete("planar_shadows");
    state.framebuffer.bind();
    gl::glClearNamedFramebufferfv(state.framebuffer.id(), GL_COLOR, 0, lit);
    // A layer without a light (a scene with no lights still has one) reads as lit.
    if (std::size_t(layer) >= scene.lights.size() || !scene.lights[std::size_t(layer)].castsShadows)
      continue;
    const vec4 light = homogeneousLight(scene.lights[std::size_t(layer)]);
    state.program.set("uLight", light);
    for (const PlanarInstance& receiver : state.receivers) {
      // Orient the plane toward the light: casters on the light's side, P.L > 0.
      vec4 plane(receiver.normal, receiver.offset);
      const float side = glm::dot(plane, light);
      if (side == 0.f) continue;  // the light in the receiver's plane lights none of it
      if (side < 0.f) plane = -plane;
      state.program.set("uPlane", plane);
      state.program.set("uTolerance", receiver.tolerance);
      state.program.set("uReceiver", receiver.instance);
      for (const gl::GlMeshRange& mesh : buffers.meshes) {
        if (mesh.triangleCount == 0 || mesh.instance == receiver.instance ||
            !scene.material(mesh.material).castsShadows)
          continue;
        gl::glDrawElements(GL_TRIANGLES, GLsizei(3 * mesh.triangleCount), GL_UNSIGNED_INT,
                           reinterpret_cast<const void*>(std::uintptr_t(mesh.firstTriangle) * 12));
        ++draws;
      }
    }
  }
  gl::glDisable(GL_CLIP_DISTANCE0);
  gl::glDisable(GL_CLIP_DISTANCE1);
  gl::glBindVertexArray(0);
  gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
  c.count("planar_shadows_receivers", double(state.receivers.size()));
  c.count("planar_shadows_caster_draws", draws);
}

}  // namespace diptych
