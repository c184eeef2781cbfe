#include "passes/raster/texture_filter.h"

#include <cmath>
#include <map>
#include <string>

#include "engine/gl/objects.h"
#include "engine/gl/shader.h"
#include "engine/gl/shader_features.h"
#include "engine/gl/shading_buffers.h"
#include "engine/graph/render_world.h"

namespace diptych {
namespace {

// GL state of the texture_* passes, one per RenderWorld (never in the pass): one program per
// filter, the filter a compile-time constant. With a uniform mode llvmpipe ran every branch
// under a mask (the anisotropic loop included) for every pixel, about 4x the cost.
struct TextureFilterGl {
  std::map<TextureFilterKind, gl::Program> programs;
  const gl::Program& get(TextureFilterKind kind, const std::vector<gl::ShaderDefine>& scene) {
    auto it = programs.find(kind);
    if (it != programs.end()) return it->second;
    return programs
        .emplace(kind,
                 gl::loadProgram(
                     {"texture_filter.comp"},
                     gl::withDefines(scene, {{"TEXTURE_FILTER_MODE", std::to_string(int(kind))}})))
        .first->second;
  }
};

}  // namespace

ParamSchema TextureFilterPass::schema(TextureFilterKind kind) {
  if (kind != TextureFilterKind::Anisotropic) return {};
  return {ParamSpec::integer("max_anisotropy", 16, 1, 64,
                             "most trilinear probes along the footprint's long axis")};
}

void TextureFilterPass::setup(PassBuilder& b) {
  if (kind_ == TextureFilterKind::Anisotropic)
    maxAnisotropy_ = b.params().integer("max_anisotropy");
  io_ = slotIo(b, "texture_filtering");
}

void TextureFilterPass::execute(PassContext& c) {
  RenderWorld& world = c.world();
  const Camera& camera = c.frame().camera;
  const gl::GlShadingBuffers& shading = world.glShading();
  world.glScene().bind();
  shading.bind();
  const gl::Texture& out = c.glTexture(io_.signal);
  // The pinhole of engine/scene/camera_math.cpp primaryRay: d = forward + ndc.x right' +
  // ndc.y up' with right' = right aspect tan(fov/2), up' = up tan(fov/2).
  const vec3 forward = glm::normalize(camera.target - camera.position);
  const vec3 right = glm::normalize(glm::cross(forward, camera.up));
  const vec3 up = glm::cross(right, forward);
  const float tanHalf = std::tan(0.5f * camera.verticalFov);
  const float aspect = float(out.width()) / float(out.height());
  const gl::Program& program =
      world.glCached<TextureFilterGl>().get(kind_, world.glShading().defines);
  program.use();
  program.set("uMaxAnisotropy", maxAnisotropy_);
  program.set("uEye", camera.position);
  program.set("uForward", forward);
  program.set("uRight", right * (aspect * tanHalf));
  program.set("uUp", up * tanHalf);
  gl::glBindTextureUnit(0, c.glTexture(io_.hits).id());
  gl::glBindImageTexture(0, out.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gl::glDispatchCompute(GLuint((out.width() + 7) / 8), GLuint((out.height() + 7) / 8), 1);
  gl::glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                      GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace diptych
