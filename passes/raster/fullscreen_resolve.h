#pragma once
// A full-screen triangle drawn into one frame-size texture with a program of the caller's,
// for the per-pixel steps of the forward producers (mask, resolve). The scene and shading
// SSBOs are bound so that the fragment shader can rebuild G-buffer points
// (shaders/gl/scene_shading.glsl, surfaceFromHits).
#include <optional>

#include "engine/core/math.h"
#include "engine/gl/objects.h"

namespace diptych {
class RenderWorld;

class FullscreenResolve {
 public:
  explicit FullscreenResolve(gl::Program program);
  const gl::Program& program() const { return program_; }
  // Draws over all of `target` (no depth, no blending, or with `multiply` dst * src), or over
  // the `scissor` rectangle (x, y, width, height) only; the caller set uniforms and textures.
  // With `depth` (D32F, the target's size) the program's gl_FragDepth is written there too
  // (depth test GL_ALWAYS).
  void draw(RenderWorld& world, const gl::Texture& target, bool multiply = false,
            const std::optional<glm::ivec4>& scissor = std::nullopt,
            const gl::Texture* depth = nullptr);

 private:
  gl::Program program_;
  gl::Framebuffer framebuffer_;
  gl::VertexArray empty_;
};

// Clears a float colour texture to zero (the slots' "0 elsewhere").
void clearToZero(const gl::Texture& texture);

}  // namespace diptych
