#pragma once
// A full-screen triangle drawn into one frame-size texture with a program of the caller's,
// for the per-pixel steps of the forward producers (mask, resolve) and GL shade. The scene and
// shading buffer textures are bound so that the fragment shader can rebuild G-buffer points
// (shaders/gl/scene_shading.glsl, surfaceFromHits). The triangle lies at depth 0
// (shaders/fullscreen.vert), the far end of the engine's reversed-Z (camera_math.h). Every draw
// of a world goes through that world's one framebuffer (fullscreen_resolve.cpp says why).
//
// State contract: after every draw, whatever the options, the framebuffer and vertex array 0
// are bound; the depth test is off, the depth mask on and the depth function GL_LESS (GL's
// initial values); blending is off with the factors (GL_ONE, GL_ZERO); the scissor test and
// face culling are off; all colour channels are written; the viewport is the target's; the
// clip control is (GL_LOWER_LEFT, GL_ZERO_TO_ONE), the reversed-Z convention. Fixed values
// rather than those found, so that no mode leaks its own (a depth mask left off stops the next
// G-buffer depth clear; GL_ALWAYS would pass anything). Passes that test depth set their own
// state (gbuffer_raster.cpp, forward_renderer.cpp) and must not rely on these.
#include <optional>

#include "engine/core/math.h"
#include "engine/gl/objects.h"

namespace diptych {
class RenderWorld;

// What a draw does with FullscreenOptions::depth.
enum class FullscreenDepth {
  // Depth function GL_ALWAYS, mask on: the program's gl_FragDepth is stored.
  Write,
  // Depth function `depthFunc`, mask off: each pixel is drawn where the triangle's depth 0
  // passes against the stored depth (GL_GEQUAL: where nothing was drawn, the cleared 0;
  // GL_LESS: where a surface was), tested before the shader runs as long as the program does
  // not write gl_FragDepth (GL 4.5, section 14.9.4, early fragment tests).
  Test,
};

struct FullscreenOptions {
  bool multiply = false;               // blend dst * src, (GL_ZERO, GL_SRC_COLOR)
  std::optional<glm::ivec4> scissor;   // x, y, width, height; all of the target without
  const gl::Texture* depth = nullptr;  // D32F, the target's size; no depth test without
  FullscreenDepth depthMode = FullscreenDepth::Write;
  GLenum depthFunc = GL_LESS;  // FullscreenDepth::Test only
  int layer = -1;              // the layer of a 2D-array target; -1 for a 2D one
  // Cleared on the framebuffer before the draw (all of the target, whatever the scissor): a
  // framebuffer clear stays in llvmpipe's scene, binned like the draw.
  std::optional<vec4> clearColor;
  std::optional<float> clearDepth;  // needs `depth`
};

class FullscreenResolve {
 public:
  explicit FullscreenResolve(gl::Program program);
  const gl::Program& program() const { return program_; }
  // Draws over `target` as `options` say (default: every pixel, no blending, no depth); the
  // caller set uniforms and textures. Leaves the state of the contract above.
  void draw(RenderWorld& world, const gl::Texture& target, const FullscreenOptions& options = {});

 private:
  gl::Program program_;
};

// Clears a float colour texture to zero (the slots' "0 elsewhere").
void clearToZero(const gl::Texture& texture);

}  // namespace diptych
