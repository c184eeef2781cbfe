#pragma once
// Rasterized primary visibility: the G-buffer that the hybrid renderer's ray passes start from.
//
// Layout (all W x H, image row 0 at the top after readTexture):
//   hits RGBA32UI = (instance + 1, primitive, floatBitsToUint(u), floatBitsToUint(v));
//                         x = 0 is background. (u, v) are Embree barycentrics at the pixel
//                         centre: p = (1-u-v) p0 + u p1 + v p2, vertices in index order.
//   normal     RGBA32F  = (shading normal xyz, unit, interpolated with (u, v); w = material
//                         index, -1 for the default material); (0, 0, 0, 0) for background.
//   depth      D32F     = reversed-Z depth near / -z_view (camera_math.h), 0 = background.
//
// (u, v) are not interpolated attributes: the fragment shader intersects the pixel-centre
// camera ray (the same ray as diptych::primaryRay) with the triangle fetched by gl_PrimitiveID
// (Moller-Trumbore), so that the reconstructed position is the point Embree's primary ray would
// hit, to float rounding. Culling is off: every visible surface counts, whatever its winding.
#include "engine/gl/objects.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/shading_buffers.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

struct GBufferTextures {
  Texture hits;    // RGBA32UI
  Texture normal;  // RGBA32F
  Texture depth;   // D32F

  static GBufferTextures allocate(int width, int height);
  int width() const { return hits.width(); }
  int height() const { return hits.height(); }
};

// Holds the compiled program and the framebuffer; create once per context, reuse every frame.
class GBufferRasterizer {
 public:
  GBufferRasterizer();  // compiles gbuffer.vert/.frag from shaderDirectory(); throws Error
  // Renders into `targets`, which must be allocated with the formats above at any W x H (the
  // viewport follows their size). Sets its own GL state: clip control lower-left/zero-to-one,
  // depth GREATER with clear 0, no culling, no blending.
  // With `shading` (uploaded from the same scene), alpha-masked materials cut out their holes:
  // meshes whose coverage is constant and below the cutoff are not drawn, textured masks are
  // drawn with a program variant that discards fragments below the cutoff (compiled on first
  // need, so opaque scenes run the plain program only). Without it every mesh is opaque, and
  // the normal output is the interpolated vertex normal; with it, the normal- or bump-mapped
  // shading normal that every pass reconstructs (surfaceFromHits), when the scene has those.
  void render(const GlSceneBuffers& scene, const Camera& camera, GBufferTextures& targets,
              const GlShadingBuffers* shading = nullptr);
  // The same, into textures owned elsewhere (the frame graph's pool).
  void render(const GlSceneBuffers& scene, const Camera& camera, const Texture& hits,
              const Texture& normal, const Texture& depth,
              const GlShadingBuffers* shading = nullptr);

 private:
  Program program_;
  Program alphaProgram_;  // DIPTYCH_ALPHA_MASK variant; empty until a scene needs it
  // DIPTYCH_DETAIL_NORMAL variants (plain, alpha-masked), compiled with the scene's defines when
  // `shading` has normal maps or bump: the normal output is then surfaceFromHits' shading normal.
  Program detailProgram_, detailAlphaProgram_;
  Framebuffer framebuffer_;
};

// One-off convenience: allocates `targets` when empty or of another size, then renders with a
// temporary rasterizer (compiles the program each call; prefer GBufferRasterizer in loops).
void rasterizeGBuffer(const GlSceneBuffers& scene, const Camera& camera, int width, int height,
                      GBufferTextures& targets);

}  // namespace diptych::gl
