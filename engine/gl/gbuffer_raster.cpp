#include "engine/gl/gbuffer_raster.h"

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "engine/scene/camera_math.h"

namespace diptych::gl {

GBufferTextures GBufferTextures::allocate(int width, int height) {
  GBufferTextures t;
  t.hits = Texture::create2D(TextureFormat::RGBA32UI, width, height);
  t.normal = Texture::create2D(TextureFormat::RGBA32F, width, height);
  t.depth = Texture::create2D(TextureFormat::D32F, width, height);
  t.hits.setLabel("gbuffer.hits");
  t.normal.setLabel("gbuffer.normal");
  t.depth.setLabel("gbuffer.depth");
  return t;
}

GBufferRasterizer::GBufferRasterizer()
    : program_(loadProgram({"gbuffer.vert", "gbuffer.frag"})),
      framebuffer_(Framebuffer::create()) {}

namespace {

void checkTargets(const Texture& hits, const Texture& normal, const Texture& depth) {
  const int width = hits.width(), height = hits.height();
  const auto expect = [&](const Texture& tex, TextureFormat format, const char* what) {
    if (!tex || tex.format() != format || tex.kind() != TextureKind::Tex2D ||
        tex.width() != width || tex.height() != height) {
      throw Error(std::string("G-buffer target '") + what + "' must be a " +
                  std::string(formatInfo(format).name) + " 2D texture of " + std::to_string(width) +
                  "x" + std::to_string(height));
    }
  };
  expect(hits, TextureFormat::RGBA32UI, "hits");
  expect(normal, TextureFormat::RGBA32F, "normal");
  expect(depth, TextureFormat::D32F, "depth");
}

// Whether the scene's permutation (shader_features.h) has normal maps or bump maps.
bool hasDetailNormals(const std::vector<ShaderDefine>& defines) {
  for (const ShaderDefine& d : defines)
    if ((d.name == "DIPTYCH_SCENE_NORMAL_MAPS" || d.name == "DIPTYCH_SCENE_BUMP") && d.value == "1")
      return true;
  return false;
}

}  // namespace

void GBufferRasterizer::render(const GlSceneBuffers& scene, const Camera& camera,
                               GBufferTextures& targets, const GlShadingBuffers* shading) {
  render(scene, camera, targets.hits, targets.normal, targets.depth, shading);
}

void GBufferRasterizer::render(const GlSceneBuffers& scene, const Camera& camera,
                               const Texture& hits, const Texture& normal, const Texture& depth,
                               const GlShadingBuffers* shading) {
  ScopedGlLabel label("gbuffer");
  checkTargets(hits, normal, depth);
  const int width = hits.width(), height = hits.height();
  framebuffer_.attachColor(0, hits);
  framebuffer_.attachColor(1, normal);
  framebuffer_.attachDepth(depth);
  framebuffer_.checkComplete("gbuffer");
  framebuffer_.bind();

  // Reversed-Z (camera_math.h): depth = near / -z_view in [0, 1], nearer is greater.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glViewport(0, 0, width, height);
  const GLuint zeroU[4] = {0, 0, 0, 0};
  const GLfloat zeroF[4] = {0.f, 0.f, 0.f, 0.f};
  glClearNamedFramebufferuiv(framebuffer_.id(), GL_COLOR, 0, zeroU);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_COLOR, 1, zeroF);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, zeroF);

  // The ray frame is built as in primaryRay() so both sides trace the same pixel-centre ray.
  const float aspect = float(width) / float(height);
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const vec3 up = glm::cross(right, forward);
  const bool alphaTested = shading && shading->anyAlphaTested();
  if (alphaTested && !alphaProgram_)
    alphaProgram_ = loadProgram({"gbuffer.vert", "gbuffer.frag"}, {{"DIPTYCH_ALPHA_MASK", ""}});
  const bool detail = shading && hasDetailNormals(shading->defines);
  if (detail && !detailProgram_) {
    const auto defines = withDefines(shading->defines, {{"DIPTYCH_DETAIL_NORMAL", ""}});
    detailProgram_ = loadProgram({"gbuffer.vert", "gbuffer.frag"}, defines);
    detailAlphaProgram_ = loadProgram({"gbuffer.vert", "gbuffer.frag"},
                                      withDefines(defines, {{"DIPTYCH_ALPHA_MASK", ""}}));
  }
  const Program& opaque = detail ? detailProgram_ : program_;
  const Program& masked = detail ? detailAlphaProgram_ : alphaProgram_;
  for (const Program* program : {&opaque, alphaTested ? &masked : nullptr}) {
    if (!program) continue;
    program->set("uViewProjection", reversedZProjection(camera, aspect) * viewMatrix(camera));
    program->set("uCameraPosition", camera.position);
    program->set("uForward", forward);
    program->set("uRight", right);
    program->set("uUp", up);
    program->set("uAspect", aspect);
    program->set("uTanHalfFov", std::tan(0.5f * camera.verticalFov));
    program->set("uViewportSize", vec2(float(width), float(height)));
  }

  scene.vertexArray.bind();
  scene.bindStorage();
  if (shading) shading->bindStorage();
  for (const GlMeshRange& mesh : scene.meshes) {
    if (mesh.triangleCount == 0) continue;
    const AlphaDraw mode = shading ? shading->alphaDraw(mesh.material) : AlphaDraw::Opaque;
    if (mode == AlphaDraw::Hidden) continue;
    const Program& program = mode == AlphaDraw::AlphaTested ? masked : opaque;
    program.use();
    program.set("uInstance", std::uint32_t(mesh.instance));
    program.set("uFirstTriangle", mesh.firstTriangle);
    program.set("uMaterial", float(mesh.material));
    // gl_PrimitiveID restarts at 0 for each draw, so it is the primitive index within the mesh.
    glDrawElements(GL_TRIANGLES, GLsizei(3 * mesh.triangleCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(std::uintptr_t(mesh.firstTriangle) * 12));
  }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void rasterizeGBuffer(const GlSceneBuffers& scene, const Camera& camera, int width, int height,
                      GBufferTextures& targets) {
  if (!targets.hits || targets.width() != width || targets.height() != height) {
    targets = GBufferTextures::allocate(width, height);
  }
  GBufferRasterizer().render(scene, camera, targets);
}

}  // namespace diptych::gl
