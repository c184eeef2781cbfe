#pragma once
// GL side of the shadow_map pass. Everything lives in RenderWorld::glCached<ShadowMapGl>() (never
// in the pass: a compiled graph may outlive its context). Several shadow_map passes in one graph
// (e.g. two bias modes side by side) share the programs; each execution renders its maps, then
// looks them up, before the next pass runs, so sharing the map textures is safe.
#include <array>
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "engine/gl/objects.h"
#include "engine/gl/scene_buffers.h"
#include "engine/scene/world_geometry.h"
#include "passes/raster/fullscreen_resolve.h"
#include "passes/raster/shadow_map_frusta.h"
#include "passes/raster/shadow_map_settings.h"

namespace diptych {
class RenderWorld;
}

namespace diptych::shadowmap {

class ShadowMapGl {
 public:
  ShadowMapGl();
  // 3x3 PCF of the cube maps' interior pass by four textureGather (true) or by nine texelFetch
  // (false): the same visibility, bit for bit (test ShadowLookup.GatheredPcfEqualsNineFetches);
  // the gathers cost less on llvmpipe (docs/shadow-maps.md).
  bool gatherPcf = true;
  // Cube maps looked up in two passes, an interior one without the cube-edge path and the full
  // shader behind a depth test where it left pixels (true), or the full shader everywhere
  // (false): the same visibility, bit for bit (test ShadowLookup.SplitCubeEqualsOnePass).
  bool splitCube = true;
  // What mapsFor did this frame, for the pass's counters and the world's one-time costs.
  struct Built {
    int draws = 0;          // caster draws issued (0 when the cached maps were used)
    bool rendered = false;  // the maps were rendered
    double ms = 0;          // render time including glFinish (static update only), ms
  };
  // The D32F array with every light's maps for `settings`. Static update (an engine's cached
  // shadow maps) renders only when the key of what the depth depends on changed: the map
  // settings (resolution, layer count, slope offset), every layer's view-projection (the light's
  // kind, position, direction, cone and the scene bounds it is fitted to) and the caster set
  // (which meshes cast, and which are alpha-tested). EveryFrame renders each call.
  const gl::Texture& mapsFor(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                             const Settings& settings, Built& built);
  // Renders the depth of every shadow-casting mesh into each light's layers, skipping meshes
  // outside a layer's frustum; returns the number of mesh draws issued.
  int renderMaps(RenderWorld& world, const std::vector<LightFrustum>& frusta,
                 const Settings& settings, const gl::Texture& maps);
  // Writes V_i for every light into `visibility` (R32F 2D, or 2D array with one layer per light),
  // reading the G-buffer's stored surface when `surface` is not null (gbuffer_surface.h).
  void lookup(RenderWorld& world, const std::vector<LightFrustum>& frusta, const Settings& settings,
              const gl::Texture& maps, const gl::Texture& gbuffer, const gl::Texture* surface,
              const gl::Texture& visibility);

 private:
  void uploadFrusta(const std::vector<LightFrustum>& frusta, const Settings& settings);
  // The lookup's full-screen draw for one (light kind, bias, filter, kernel, interior-only
  // variant, stored surface, gathered PCF), its program compiled on first use.
  FullscreenResolve& lookupDraw(RenderWorld& world, ViewKind kind, const Settings& settings,
                                bool interior, bool surface);
  gl::Program depth_;
  std::map<std::array<int, 7>, FullscreenResolve> lookups_;
  gl::Texture lookupDepth_;  // marks pixels the interior cube pass left to the full one
  gl::Program alphaDepth_;   // DIPTYCH_ALPHA_MASK variant of depth_, compiled on first need
  gl::Framebuffer depthFbo_;
  gl::Buffer layers_, lights_;
  gl::BufferTexture layerTexels_, lightTexels_;  // their views, read by the lookup
  // The bytes last uploaded to layers_ and lights_: a static light's frusta are uploaded once,
  // not every frame (an upload into a buffer that queued draws read makes llvmpipe wait for them).
  std::vector<std::byte> uploadedLayers_, uploadedLights_;
  // One D32F array per (resolution, layers); `key` is what its contents were rendered for (the
  // slope offset among them). A sweep of the slope offset re-renders one array instead of
  // keeping one per value (a 4096 cube is 384 MiB); two passes of one graph that differ only in
  // their slope offset re-render it in turn.
  struct Maps {
    gl::Texture texture;
    std::vector<float> key;
  };
  std::map<std::array<int, 2>, Maps> maps_;
  std::vector<vec2> poisson_;
};

// True when no point of `box` can pass the clip volume of `viewProj` (reversed-Z, ZERO_TO_ONE):
// a conservative test, so a draw it skips would have produced no fragment.
bool boxOutsideFrustum(const Aabb& box, const mat4& viewProj);

// `count` points in the unit disc, at least a fixed distance apart, by deterministic dart
// throwing (Cook 1986, "Stochastic sampling in computer graphics"): the distance shrinks when a
// point cannot be placed, so any count terminates. Same points every run.
std::vector<vec2> poissonDisk(int count);

}  // namespace diptych::shadowmap
