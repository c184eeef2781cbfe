#include "engine/gl/gbuffer_raster.h"

#include "engine/core/error.h"
#include "engine/gl/closed_mesh.h"
#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "engine/scene/camera_math.h"

namespace diptych::gl {

GBufferTextures GBufferTextures::allocate(int width, int height, bool surface) {
  GBufferTextures t;
  if (surface) {
    t.surface = Texture::create2DArray(TextureFormat::RGBA32F, width, height, 3);
    t.surface.setLabel("gbuffer.surface");
  }
  t.hits = Texture::create2D(TextureFormat::RGBA32UI, width, height);
  t.normal = Texture::create2D(TextureFormat::RGBA32F, width, height);
  t.depth = Texture::create2D(TextureFormat::D32F, width, height);
  t.hits.setLabel("gbuffer.hits");
  t.normal.setLabel("gbuffer.normal");
  t.depth.setLabel("gbuffer.depth");
  return t;
}

GBufferRasterizer::GBufferRasterizer() {
  program(false, true, true, nullptr);
}

namespace {

std::string keyOf(const std::vector<ShaderDefine>& defines) {
  std::string key;
  for (const ShaderDefine& d : defines) key += d.name + "=" + d.value + ";";
  return key;
}

// Whether the scene's permutation (shader_features.h) has normal maps or bump maps.
bool hasDetailNormals(const std::vector<ShaderDefine>& defines) {
  for (const ShaderDefine& d : defines)
    if ((d.name == "DIPTYCH_SCENE_NORMAL_MAPS" || d.name == "DIPTYCH_SCENE_BUMP") && d.value == "1")
      return true;
  return false;
}

}  // namespace

const Program& GBufferRasterizer::program(bool alpha, bool normal, bool barycentrics,
                                          const GlShadingBuffers* shading) {
  // The alpha-tested and detail-normal variants include scene_shading.glsl: the scene's
  // permutation. With normal or bump maps the normal output is surfaceFromHits' shading normal.
  const bool detail = normal && shading && hasDetailNormals(shading->defines);
  std::vector<ShaderDefine> defines;
  if ((alpha || detail) && shading) defines = shading->defines;
  if (alpha) defines.push_back({"DIPTYCH_ALPHA_MASK", ""});
  if (normal) defines.push_back({"GBUFFER_NORMAL", ""});
  if (detail) defines.push_back({"DIPTYCH_DETAIL_NORMAL", ""});
  // The visibility buffer: no triangle fetched, no ray intersected (the alpha test and the
  // normal need the exact (u, v), so those variants always compute them).
  if (!barycentrics && !alpha && !normal) defines.push_back({"GBUFFER_VISIBILITY", ""});
  const std::string key = "raster:" + keyOf(defines);
  auto it = programs_.find(key);
  if (it == programs_.end())
    it = programs_.emplace(key, loadProgram({"gbuffer.vert", "gbuffer.frag"}, defines)).first;
  return it->second;
}

const Program& GBufferRasterizer::impostorProgram() {
  auto it = programs_.find("impostor");
  if (it == programs_.end())
    it = programs_
             .emplace("impostor",
                      loadProgram({"gbuffer_impostor.vert", "gbuffer_impostor.frag"}, {}))
             .first;
  return it->second;
}

const Program& GBufferRasterizer::surfaceProgram(const GlShadingBuffers& shading) {
  const std::string key = "surface:" + keyOf(shading.defines);
  auto it = programs_.find(key);
  if (it == programs_.end())
    it = programs_.emplace(key, loadProgram({"gbuffer_surface.comp"}, shading.defines)).first;
  return it->second;
}

namespace {

void checkTargets(const GBufferTargets& t) {
  if (!t.hits || !t.depth) throw Error("G-buffer: the hits and depth targets are required");
  const int width = t.hits->width(), height = t.hits->height();
  const auto expect = [&](const Texture* tex, TextureFormat format, int layers, const char* what) {
    if (!tex) return;
    const TextureKind kind = layers > 1 ? TextureKind::Tex2DArray : TextureKind::Tex2D;
    if (!*tex || tex->format() != format || tex->kind() != kind || tex->width() != width ||
        tex->height() != height || (layers > 1 && tex->layers() != layers)) {
      throw Error(std::string("G-buffer target '") + what + "' must be a " +
                  std::string(formatInfo(format).name) + " 2D " +
                  (layers > 1 ? "array texture of " + std::to_string(layers) + " layers of "
                              : std::string("texture of ")) +
                  std::to_string(width) + "x" + std::to_string(height));
    }
  };
  expect(t.hits, TextureFormat::RGBA32UI, 1, "hits");
  expect(t.normal, TextureFormat::RGBA32F, 1, "normal");
  expect(t.surface, TextureFormat::RGBA32F, 3, "surface");
  expect(t.depth, TextureFormat::D32F, 1, "depth");
}

}  // namespace

void GBufferRasterizer::render(const GlSceneBuffers& scene, const Camera& camera,
                               GBufferTextures& targets, const GlShadingBuffers* shading) {
  render(scene, camera,
         {&targets.hits, &targets.normal, targets.surface ? &targets.surface : nullptr,
          &targets.depth},
         shading);
}

void GBufferRasterizer::render(const GlSceneBuffers& scene, const Camera& camera,
                               const Texture& hits, const Texture& normal, const Texture& depth,
                               const GlShadingBuffers* shading) {
  render(scene, camera, {&hits, &normal, nullptr, &depth}, shading);
}

void GBufferRasterizer::render(const GlSceneBuffers& scene, const Camera& camera,
                               const GBufferTargets& targets, const GlShadingBuffers* shading,
                               const Scene* materials) {
  ScopedGlLabel label("gbuffer");
  checkTargets(targets);
  if (targets.surface && !shading)
    throw Error("G-buffer: the surface target needs the scene's shading buffers");
  const bool withNormal = targets.normal != nullptr, withSurface = targets.surface != nullptr;
  const int width = targets.hits->width(), height = targets.hits->height();
  auto fb = framebuffers_.find(int(withNormal));
  if (fb == framebuffers_.end())
    fb = framebuffers_.emplace(int(withNormal), Framebuffer::create()).first;
  Framebuffer& framebuffer = fb->second;
  framebuffer.attachColor(0, *targets.hits);
  if (withNormal) framebuffer.attachColor(1, *targets.normal);
  framebuffer.attachDepth(*targets.depth);
  framebuffer.checkComplete("gbuffer");
  framebuffer.bind();

  // Reversed-Z (camera_math.h): depth = near / -z_view in [0, 1], nearer is greater.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_TRUE);
  glDisable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);
  glDisable(GL_BLEND);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glViewport(0, 0, width, height);
  const GLuint zeroU[4] = {0, 0, 0, 0};
  const GLfloat zeroF[4] = {0.f, 0.f, 0.f, 0.f};
  glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 0, zeroU);
  if (withNormal) glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 1, zeroF);
  glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, zeroF);

  // The ray frame is built as in primaryRay() so both sides trace the same pixel-centre ray.
  const float aspect = float(width) / float(height);
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const vec3 up = glm::cross(right, forward);
  const bool alphaTested = shading && shading->anyAlphaTested();
  // The surface target is built from the hits texels' (u, v) (resolveSurface), so, like the
  // normal, it needs them computed: a visibility buffer is only drawn without both.
  const bool barycentrics = targets.barycentrics || withSurface;
  const Program& opaqueProgram = program(false, withNormal, barycentrics, shading);
  const Program* alphaProgram = alphaTested ? &program(true, withNormal, true, shading) : nullptr;
  const bool impostors = targets.impostors && !barycentrics && !withNormal;
  const Program* sphereProgram = impostors ? &impostorProgram() : nullptr;
  if (sphereProgram) sphereProgram->set("uNear", camera.znear);
  for (const Program* program : {&opaqueProgram, alphaProgram, sphereProgram}) {
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
  scene.bind();
  if (shading) shading->bind();
  culledMeshes_ = 0;
  impostorMeshes_ = 0;
  const float nearReach = nearPlaneReach(camera.znear, camera.verticalFov, aspect);
  for (const GlMeshRange& mesh : scene.meshes) {
    if (mesh.triangleCount == 0) continue;
    const AlphaDraw mode = shading ? shading->alphaDraw(mesh.material) : AlphaDraw::Opaque;
    if (mode == AlphaDraw::Hidden) continue;
    // The box with a margin around the sphere's (rounded outward) bounds: the conservative
    // near-misses of the fragment test lie within a relative 5e-4 of the radius.
    const vec3 margin = 1e-3f * (mesh.boundsHi - mesh.boundsLo) + vec3(1e-6f);
    const vec3 boxLo = mesh.boundsLo - margin, boxHi = mesh.boundsHi + margin;
    // Seen from outside, a sphere's nearest root is on its front: what its triangles would show
    // (a single-sided material included); and the box's front faces, clear of the near plane,
    // give each pixel it covers one fragment.
    if (sphereProgram && mesh.sphere && mode == AlphaDraw::Opaque &&
        outsideBounds(camera.position, boxLo, boxHi, nearReach)) {
      glEnable(GL_CULL_FACE);  // back faces (gbuffer_impostor.vert winds them outward CCW)
      sphereProgram->use();
      sphereProgram->set("uInstance", std::uint32_t(mesh.instance));
      sphereProgram->set("uToObject", mesh.toObject);
      sphereProgram->set("uRadius", mesh.sphereRadius);
      sphereProgram->set("uBoxLo", boxLo);
      sphereProgram->set("uBoxHi", boxHi);
      glDrawArrays(GL_TRIANGLES, 0, 36);
      ++impostorMeshes_;
      continue;
    }
    const Program& program = mode == AlphaDraw::AlphaTested ? *alphaProgram : opaqueProgram;
    // A closed mesh seen from outside: its back faces are hidden by its own front faces
    // (closed_mesh.h). Alpha-tested meshes have holes: never culled.
    const bool cull = cullClosed && mode == AlphaDraw::Opaque && mesh.closedOutward &&
                      outsideBounds(camera.position, mesh.boundsLo, mesh.boundsHi, nearReach);
    culledMeshes_ += cull ? 1 : 0;
    // A single-sided material (glTF doubleSided false) shows no back face to the camera, holes
    // or not: the rule itself, not an optimisation (engine/rt/camera_rays.h traces the same).
    // WorldMesh winding is CCW for mirrored instances too (world_geometry.h).
    const bool singleSided = materials && !materials->material(mesh.material).doubleSided;
    if (cull || singleSided)
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    program.use();
    program.set("uInstance", std::uint32_t(mesh.instance));
    program.set("uFirstTriangle", mesh.firstTriangle);
    program.set("uMaterial", float(mesh.material));
    // gl_PrimitiveID restarts at 0 for each draw, so it is the primitive index within the mesh.
    glDrawElements(GL_TRIANGLES, GLsizei(3 * mesh.triangleCount), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(std::uintptr_t(mesh.firstTriangle) * 12));
  }
  glDisable(GL_CULL_FACE);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (withSurface) resolveSurface(*targets.hits, *targets.surface, *shading);
}

void GBufferRasterizer::resolveSurface(const Texture& hits, const Texture& surface,
                                       const GlShadingBuffers& shading) {
  ScopedGlLabel label("gbuffer.surface");
  const Program& resolve = surfaceProgram(shading);
  resolve.use();
  shading.bind();
  glBindTextureUnit(0, hits.id());
  glBindImageTexture(0, surface.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glDispatchCompute(GLuint((hits.width() + 7) / 8), GLuint((hits.height() + 7) / 8), 1);
  // Consumers fetch it as a texture, or copy it in a readback.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void rasterizeGBuffer(const GlSceneBuffers& scene, const Camera& camera, int width, int height,
                      GBufferTextures& targets) {
  if (!targets.hits || targets.width() != width || targets.height() != height) {
    targets = GBufferTextures::allocate(width, height);
  }
  GBufferRasterizer().render(scene, camera, targets);
}

}  // namespace diptych::gl
