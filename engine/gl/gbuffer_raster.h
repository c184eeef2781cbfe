#pragma once
// Rasterized primary visibility: the G-buffer that the hybrid renderer's ray passes start from.
//
// Layout (all W x H, image row 0 at the top after readTexture):
//   hits RGBA32UI = (instance + 1, primitive, floatBitsToUint(u), floatBitsToUint(v));
//                         x = 0 is background. (u, v) are Embree barycentrics at the pixel
//                         centre: p = (1-u-v) p0 + u p1 + v p2, vertices in index order;
//                         NaN in a visibility buffer (GBufferTargets::barycentrics false).
//   normal     RGBA32F  = (shading normal xyz, unit, interpolated with (u, v); w = material
//                         index, -1 for the default material); (0, 0, 0, 0) for background.
//   depth      D32F     = reversed-Z depth near / -z_view (camera_math.h), 0 = background.
//   surface    RGBA32F, 3 layers (optional; needs the shading buffers): the surface point of
//              shaders/gl/scene_shading.glsl surfaceFromHits, resolved once per pixel after the
//              raster (shaders/gbuffer_surface.comp) so that
//              full-screen passes read three texels (shaders/gl/gbuffer_surface.glsl) instead of
//              rebuilding it from ~30 buffer gathers: layer 0 = (position, uv.x), layer 1 =
//              (unit face normal, uv.y), layer 2 = (shading normal with the normal and bump map
//              applied, material index); all 0 for background.
//
// (u, v) are not interpolated attributes: the fragment shader intersects the pixel-centre
// camera ray (the same ray as diptych::primaryRay) with the triangle fetched by gl_PrimitiveID
// (Moller-Trumbore), so that the reconstructed position is the point Embree's primary ray would
// hit, to float rounding. Every visible surface counts, whatever its winding: back faces are
// culled only on closed meshes seen from outside, where no back face can be the nearest.
#include <map>
#include <string>

#include "engine/gl/objects.h"
#include "engine/gl/scene_buffers.h"
#include "engine/gl/shading_buffers.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

struct GBufferTextures {
  Texture hits;     // RGBA32UI
  Texture normal;   // RGBA32F
  Texture depth;    // D32F
  Texture surface;  // RGBA32F, 3 layers; empty unless allocated with `surface`

  static GBufferTextures allocate(int width, int height, bool surface = false);
  int width() const { return hits.width(); }
  int height() const { return hits.height(); }
};

// The textures of one render: hits and depth always; normal and surface only when non-null
// (an attachment nobody reads is not written: its fill costs every frame on llvmpipe).
struct GBufferTargets {
  const Texture* hits = nullptr;
  const Texture* normal = nullptr;
  const Texture* surface = nullptr;
  const Texture* depth = nullptr;
  // false: a visibility buffer. Opaque meshes' hits texels are (instance + 1, primitive, NaN,
  // NaN) (quiet NaN bits 0x7fc00000: "not computed"):
  // their fragments fetch no triangle and intersect no ray, and whoever reads them computes
  // (u, v) itself (the CPU passes do: passes/common/hits_texel.h). Alpha-tested meshes still
  // write them (their test needs them), and so does every mesh when the normal or the surface
  // is written (both are built from them): false is then ignored.
  bool barycentrics = true;
  // With barycentrics false: analytic spheres seen from outside (GlMeshRange::sphere) are drawn
  // as ray-cast impostors, their box and a fragment program that intersects the pixel's ray
  // with the sphere (gbuffer_impostor.frag), instead of their triangles: texels (instance + 1,
  // kImpostorPrimitive (world_geometry.h), NaN, NaN), which name no triangle, for readers that lift
  // every texel onto the exact surface anyway (passes/common/hits_texel.h). A 128 x 64 sphere is
  // 16k triangles that llvmpipe transforms and bins on one core; its box is 12.
  bool impostors = false;
};

// Holds the compiled programs and framebuffers; create once per context, reuse every frame.
class GBufferRasterizer {
 public:
  GBufferRasterizer();  // compiles gbuffer.vert/.frag from shaderDirectory(); throws Error
  // Back-face culling of closed meshes seen from outside their bounds (closed_mesh.h): the same
  // G-buffer, fewer fragments (test GBufferCulling.*). false draws every face.
  bool cullClosed = true;
  // Meshes the last render drew with back-face culling of closed meshes (single-sided materials
  // are culled whatever cullClosed says, and counted only when closed and seen from outside).
  int culledMeshes() const { return culledMeshes_; }
  // Meshes the last render drew as impostors (GBufferTargets::impostors).
  int impostorMeshes() const { return impostorMeshes_; }
  // Renders into `targets` (the surface too when allocated), which must have the formats above at
  // any W x H (the viewport follows their size). Sets its own GL state: clip control
  // lower-left/zero-to-one, depth GREATER with clear 0, back faces culled for single-sided
  // materials of `materials` (Material::doubleSided false: primary visibility, as
  // engine/rt/camera_rays.h; null: none) and for closed meshes seen from outside (cullClosed,
  // closed_mesh.h), no blending. With `shading`
  // (uploaded from the same scene), alpha-masked materials cut out their holes: meshes whose
  // coverage is constant and below the cutoff are not drawn, textured masks are drawn with a
  // program variant that discards fragments below the cutoff (compiled on first need, so opaque
  // scenes run the plain program only). Without it every mesh is opaque, and the normal output
  // is the interpolated vertex normal; with it, the normal- or bump-mapped shading normal that
  // every pass reconstructs (surfaceFromHits), when the scene has those.
  void render(const GlSceneBuffers& scene, const Camera& camera, GBufferTextures& targets,
              const GlShadingBuffers* shading = nullptr);
  // The same, into textures owned elsewhere (the frame graph's pool).
  void render(const GlSceneBuffers& scene, const Camera& camera, const Texture& hits,
              const Texture& normal, const Texture& depth,
              const GlShadingBuffers* shading = nullptr);
  // Any subset of the attachments; a surface needs `shading` (its program is compiled with the
  // scene's defines, shader_features.h). Throws Error on a target of the wrong format or size.
  void render(const GlSceneBuffers& scene, const Camera& camera, const GBufferTargets& targets,
              const GlShadingBuffers* shading, const Scene* materials = nullptr);

 private:
  int culledMeshes_ = 0, impostorMeshes_ = 0;
  const Program& program(bool alpha, bool normal, bool barycentrics,
                         const GlShadingBuffers* shading);
  const Program& surfaceProgram(const GlShadingBuffers& shading);
  const Program& impostorProgram();
  // gbuffer_surface.comp over the finished hits: one surfaceFromHits per pixel, not per fragment.
  void resolveSurface(const Texture& hits, const Texture& surface, const GlShadingBuffers& shading);

  std::map<std::string, Program> programs_;  // by variant defines, compiled on first need
  std::map<int, Framebuffer> framebuffers_;  // with and without the normal target
};

// One-off convenience: allocates `targets` when empty or of another size, then renders with a
// temporary rasterizer (compiles the program each call; prefer GBufferRasterizer in loops).
void rasterizeGBuffer(const GlSceneBuffers& scene, const Camera& camera, int width, int height,
                      GBufferTextures& targets);

}  // namespace diptych::gl
