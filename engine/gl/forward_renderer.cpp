#include "engine/gl/forward_renderer.h"

#include "engine/gl/bindings.h"
#include "engine/gl/debug.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/gl/transfer.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/environment.h"
#include "engine/shading/shading.h"

namespace diptych::gl {

vec3 cubeFaceDirection(int face, float a, float b) {
  // Inverse of table 8.19 (major axis, sc, tc) with |ma| = 1, a = sc, b = tc.
  switch (face) {
    case 0:
      return {1.f, -b, -a};
    case 1:
      return {-1.f, -b, a};
    case 2:
      return {a, 1.f, b};
    case 3:
      return {a, -1.f, -b};
    case 4:
      return {a, -b, 1.f};
    default:
      return {-a, -b, -1.f};
  }
}

ForwardView cubeFaceView(const vec3& centre, int face, float znear) {
  // The face camera looks at the face centre; window x and y (GL texel s and t of the face)
  // grow along the face's a and b axes, which lookAt reproduces from forward and up.
  const vec3 forward = cubeFaceDirection(face, 0.f, 0.f);
  const vec3 up = cubeFaceDirection(face, 0.f, 1.f) - forward;
  Camera c;
  c.position = centre;
  c.target = centre + forward;
  c.up = up;
  c.verticalFov = glm::radians(90.f);
  c.znear = znear;
  return cameraView(c, 1.f);
}

ForwardView cameraView(const Camera& camera, float aspect) {
  return {viewMatrix(camera), reversedZProjection(camera, aspect), camera.position};
}

ForwardRenderer::ForwardRenderer()
    : background_(loadProgram({"fullscreen.vert", "forward_background.frag"})),
      framebuffer_(Framebuffer::create()),
      empty_(VertexArray::create()) {}

void ForwardRenderer::ensureEnvironment(const Scene& scene) {
  if (environment_) return;
  // Resampled with the CPU lookup so that every environment type (colour, equirect, cube) is
  // one cube texture here. Engine rows run top down, GL texel rows (t) bottom up.
  const int n = kEnvironmentCubeSize;
  environment_ = Texture::createCube(TextureFormat::RGBA32F, n);
  environment_.setLabel("forward.environment");
  std::vector<float> texels(std::size_t(n) * n * 4);
  for (int face = 0; face < 6; ++face) {
    for (int y = 0; y < n; ++y) {
      const float b = 2.f * (float(n - 1 - y) + 0.5f) / float(n) - 1.f;
      for (int x = 0; x < n; ++x) {
        const float a = 2.f * (float(x) + 0.5f) / float(n) - 1.f;
        const vec3 c = sampleEnvironment(scene.environment, cubeFaceDirection(face, a, b));
        float* t = &texels[(std::size_t(y) * n + x) * 4];
        t[0] = c.x, t[1] = c.y, t[2] = c.z, t[3] = 1.f;
      }
    }
    uploadTextureFloats(environment_, texels, face);
  }
}

namespace {

std::vector<int> drawList(const Scene& scene, const GlSceneBuffers& buffers,
                          const ForwardOptions& o) {
  if (o.explicitOrder || !o.order.empty()) return o.order;
  std::vector<int> list;
  for (int i = 0; i < int(buffers.meshes.size()); ++i) {
    const bool transparent =
        shading::materialHasTransmission(scene.material(buffers.meshes[i].material));
    if (o.instances == InstanceSet::All || transparent == (o.instances == InstanceSet::Transparent))
      list.push_back(i);
  }
  return list;
}

void setCamera(const Program& p, const ForwardView& view, const mat4& viewProjection, int width,
               int height) {
  p.set("uInverseViewProjection", glm::inverse(viewProjection));
  p.set("uEye", view.eye);
  p.set("uViewportSize", vec2(float(width), float(height)));
}

}  // namespace

const Program& ForwardRenderer::surface(const GlShadingBuffers& shading, bool behind,
                                        bool transmissiveOnly, bool textureLod) {
  const int key = (behind ? 1 : 0) + (transmissiveOnly ? 2 : 0) + (textureLod ? 4 : 0);
  Program& p = surfaces_[key];
  if (!p) {
    const std::vector<ShaderDefine> own = {
        {"FORWARD_BEHIND", behind ? "1" : "0"},
        {"FORWARD_TRANSMISSIVE_ONLY", transmissiveOnly ? "1" : "0"},
        {"FORWARD_TEXTURE_LOD", textureLod ? "1" : "0"}};
    p = loadProgram({"forward.vert", "forward.frag"}, withDefines(shading.defines, own));
  }
  return p;
}

void ForwardRenderer::render(const ForwardScene& input, const ForwardView& view,
                             const Texture& color, const Texture& depth, const ForwardOptions& o,
                             int layer) {
  ScopedGlLabel label("forward");
  const Scene& scene = input.scene;
  const GlSceneBuffers& buffers = input.geometry;
  const GlShadingBuffers& shading = input.shading;
  ensureEnvironment(scene);

  framebuffer_.attachColor(0, color, 0, layer);
  framebuffer_.attachDepth(depth);
  framebuffer_.checkComplete("forward");
  framebuffer_.bind();
  const int width = depth.width(), height = depth.height();
  const mat4 viewProjection = view.projection * view.view;
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glViewport(0, 0, width, height);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  if (o.scissor) {
    glEnable(GL_SCISSOR_TEST);  // also limits the clears below
    glScissor(o.scissor->x, o.scissor->y, o.scissor->z, o.scissor->w);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);

  // The environment background: a full-screen triangle at depth 0, the cleared (far) depth.
  const auto drawBackground = [&] {
    glDisable(GL_BLEND);
    setCamera(background_, view, viewProjection, width, height);
    background_.use();
    glBindTextureUnit(1, environment_.id());
    empty_.bind();
    glDrawArrays(GL_TRIANGLES, 0, 3);
  };
  // Drawn after the meshes where their depth marks what they covered, as engines draw the sky:
  // then only pixels no mesh wrote run its cube lookup (the early depth test rejects the
  // others), and every pixel ends as it did with the background drawn first and overwritten.
  const bool backgroundLast = o.clear && o.depthWrite && !o.blend;
  if (o.clear) {
    const GLfloat zero[4] = {0.f, 0.f, 0.f, 0.f};
    glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 0, zero);
    if (o.clearDepth) glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, zero);
    if (!backgroundLast) {
      glDisable(GL_DEPTH_TEST);
      drawBackground();
    }
  }

  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(o.depthWrite ? GL_TRUE : GL_FALSE);
  if (o.blend) {
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // I = I_m + (k_t M_T) I
  } else {
    glDisable(GL_BLEND);
  }
  if (o.clipPlane) glEnable(GL_CLIP_DISTANCE0);
  const bool transmissiveOnly = o.behindVisibility && o.transmissiveFirst;
  const Program& program =
      surface(shading, o.behindVisibility != nullptr, transmissiveOnly, o.textureLod);
  program.set("uViewProjection", viewProjection);
  setCamera(program, view, viewProjection, width, height);
  program.set("uClipPlane", o.clipPlane.value_or(vec4(0.f, 0.f, 0.f, 1.f)));
  program.set("uAmbient", scene.ambient);
  program.set("uLightCount", shading.lightCount);
  program.set("uBlend", o.blend ? 1 : 0);
  if (o.behindVisibility) glBindTextureUnit(0, o.behindVisibility->id());
  if (transmissiveOnly) glBindTextureUnit(UNIT_BLEND_FIRST, o.transmissiveFirst->id());
  program.use();
  buffers.vertexArray.bind();
  buffers.bind();
  shading.bind();
  for (const int i : drawList(scene, buffers, o)) {
    const GlMeshRange& mesh = buffers.meshes[std::size_t(i)];
    if (mesh.triangleCount == 0 || mesh.instance == o.excludeInstance) continue;
    program.set("uInstance", std::uint32_t(mesh.instance));
    program.set("uFirstTriangle", mesh.firstTriangle);
    program.set("uMaterial", mesh.material);
    glDrawElements(GL_TRIANGLES, GLsizei(3 * mesh.triangleCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(std::uintptr_t(mesh.firstTriangle) * 12));
  }
  glDisable(GL_CLIP_DISTANCE0);
  if (backgroundLast) {
    // Reversed-Z: a mesh fragment's depth is > 0, so GEQUAL passes only where none was written.
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    drawBackground();
  }
  // The state FullscreenResolve leaves (passes/raster/fullscreen_resolve.h), so that no caller
  // inherits the reversed-Z depth test: set once per render, not per draw.
  glDisable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  // Mesa rejects draws into several colour buffers while a dual-source factor is set, even with
  // blending disabled (the G-buffer has two): restore the default factors.
  glBlendFunc(GL_ONE, GL_ZERO);
  glDepthMask(GL_TRUE);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace diptych::gl
