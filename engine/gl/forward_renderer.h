#pragma once
// A forward renderer of the shaded scene, for the raster producers of the reflection and
// transmission slots (sorted blending, planar mirror, dynamic cube capture).
//
// Every fragment is shaded with the shared model (shaders/common/shading.glsl) on the scene's
// materials and lights (shaders/gl/scene_shading.glsl):
//   L = M_E + A_G + sum_i S_i L_dir,i
// with V_i = 1 (no shadows) and the secondary terms k_ps M_PS L_refl and k_t M_T L_trans left
// out (0): a forward-shaded surface is one bounce of the lecture's model, no recursion.
// The surface point is not interpolated: like the G-buffer (docs/gl.md), the fragment shader
// intersects the pixel-centre ray of the given camera with the fragment's triangle, so a
// forward-shaded hit is the point a ray tracer finds on the same ray, shaded the same way.
//
// Background: the environment resampled once per world into a cube map (kEnvironmentCubeSize)
// with sampleEnvironment() and looked up along the pixel ray. A solid colour is exact; image
// environments are bilinear on the resampled cube (an approximation of the CPU lookup).
//
// Depth: reversed-Z (clip control lower-left / zero-to-one, D32F cleared to 0, GL_GREATER), as
// the G-buffer. Culling is off: both sides of every triangle are drawn.
#include <map>
#include <optional>
#include <vector>

#include "engine/gl/objects.h"
#include "engine/scene/scene.h"

namespace diptych::gl {

struct GlSceneBuffers;
struct GlShadingBuffers;

inline constexpr int kEnvironmentCubeSize = 64;

// A camera given by matrices: any view and projection (mirrored, oblique, cube faces).
struct ForwardView {
  mat4 view{1.f};
  mat4 projection{1.f};  // maps the visible depth range to [0, 1], nearer greater (reversed-Z)
  vec3 eye{0.f};         // world-space ray origin of every pixel (the camera's centre)
};

enum class InstanceSet { Opaque, Transparent, All };  // transparent: material k_t > 0

struct ForwardOptions {
  InstanceSet instances = InstanceSet::All;
  // Explicit draw order (mesh indices); empty: scene order filtered by `instances`, unless
  // explicitOrder is set (then an empty order draws no mesh).
  std::vector<int> order;
  bool explicitOrder = false;
  // Window rectangle (x, y, width, height; GL window coordinates, origin bottom left) outside
  // which nothing is drawn or cleared (GL scissor test).
  std::optional<glm::ivec4> scissor;
  int excludeInstance = -1;  // e.g. the reflective object a cube is captured from
  // World-space plane (n, d): only points with dot(n, x) + d >= 0 are drawn (gl_ClipDistance).
  std::optional<vec4> clipPlane;
  // Clear colour and depth, then draw the environment background.
  bool clear = true;
  // With clear: false keeps the depth the caller pre-filled (the blend producers' early-rejected
  // pixels, passes/raster/blend_transmission.cpp); colour is still cleared.
  bool clearDepth = true;
  bool depthWrite = true;
  // Composite each fragment with the lecture's I = I_m + k_t M_T I (dual-source blending,
  // src = ONE, dst = SRC1_COLOR): I_m is the fragment's shaded colour.
  bool blend = false;
  // G-buffer visibility of the same camera and size: draw only fragments strictly behind the
  // pixel's first visible surface (see docs/forward-producers.md).
  const Texture* behindVisibility = nullptr;
  // With behindVisibility: draw only pixels whose first visible surface transmits (k_t > 0),
  // for producers that zero every other pixel anyway (the blend producers). The texture holds,
  // per pixel in .a, the distance from `eye` to that first surface where it transmits and a
  // negative value where it does not (RGBA32F, same size; passes/raster/blend_transmission.h
  // renderBlendFirst): both tests then read one texel instead of rebuilding the first surface
  // and its material in every fragment.
  const Texture* transmissiveFirst = nullptr;
  // Colour textures filtered at the fragment's level of detail (GL 4.5 core 8.14.1, as a GPU
  // engine's raster draws are; docs/forward-producers.md); false: level 0 with the magnification
  // filter, the lookup of a ray tracer's level-0 hit.
  bool textureLod = true;
};

// What a forward render draws: the scene and its uploaded geometry and shading buffers (passes
// take them from the RenderWorld, so this layer does not depend on the frame graph).
struct ForwardScene {
  const Scene& scene;
  const GlSceneBuffers& geometry;
  const GlShadingBuffers& shading;
};

// Compiled programs, the environment cube and a framebuffer; one per world (glCached).
class ForwardRenderer {
 public:
  ForwardRenderer();
  // Renders into colour (RGBA32F 2D, or a cube face with `layer`) and depth (D32F, same size).
  // Leaves the state the passes' full-screen draws leave (passes/raster/fullscreen_resolve.h):
  // depth test off with GL_LESS and the mask on, blending off with (GL_ONE, GL_ZERO), scissor,
  // culling and clip distance 0 off, all colour channels written, clip control (GL_LOWER_LEFT,
  // GL_ZERO_TO_ONE), framebuffer and vertex array 0.
  void render(const ForwardScene& input, const ForwardView& view, const Texture& color,
              const Texture& depth, const ForwardOptions& options, int layer = -1);

 private:
  void ensureEnvironment(const Scene& scene);
  // forward.frag for (behind, transmissive-only) compiled for the scene on first use: constants
  // instead of uniforms, since llvmpipe would run the visibility-texel path for every fragment.
  const Program& surface(const GlShadingBuffers& shading, bool behind, bool transmissiveOnly,
                         bool textureLod);
  std::map<int, Program> surfaces_;
  Program background_;
  Framebuffer framebuffer_;
  VertexArray empty_;
  Texture environment_;
};

// World-space direction of the texel (a, b) in [-1, 1]^2 of cube face `face` (+x, -x, +y,
// -y, +z, -z) in GL's cube-map convention (OpenGL 4.5, table 8.19), with b = 2t - 1 and t
// growing with GL texel rows (bottom up), i.e. with window y when rendering into the face.
vec3 cubeFaceDirection(int face, float a, float b);

// The view of cube face `face` seen from `centre` (90 degree fov, reversed-Z with near plane
// `znear`), such that rendering it into that face stores what a lookup along each direction sees.
ForwardView cubeFaceView(const vec3& centre, int face, float znear);

// A perspective camera's view (viewMatrix, reversedZProjection) at the given aspect.
ForwardView cameraView(const Camera& camera, float aspect);

}  // namespace diptych::gl
