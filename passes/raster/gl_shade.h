#pragma once
// The GL side of the `shade` pass (passes/cpu/shade.h): when the compiler places shade in the
// GL domain (docs/frame-graph.md, "Placement"), it runs shaders/gl_shade.frag as one full-screen
// pass over the G-buffer, with the shading code the CPU side runs (shaders/common/shading.glsl
// through shaders/gl/scene_shading.glsl), and writes the same `color` signal. The background
// is the exact environment lookup of shaders/gl/scene_environment.glsl.
//
// Differences from the CPU side, by design or not yet done (docs/gl-shade.md): hits on the
// tessellation of analytic instances are shaded on the triangles (the CPU side lifts them onto
// the exact surface); textured materials get what sceneMaterial() resolves on GL.
#include "engine/graph/pass.h"

namespace diptych {

// The resources of one shade pass; optional inputs are kNoResource when unconnected.
struct ShadeIo {
  ResourceId hits = kNoResource, lightVisibility = kNoResource, reflection = kNoResource;
  ResourceId transmission = kNoResource, albedo = kNoResource, color = kNoResource;
  ResourceId surface = kNoResource;  // gbuffer.surface (passes/raster/gbuffer_surface.h)
  // gbuffer.depth (reversed-Z, 0 where no surface): when connected, the background and the
  // surfaces are drawn by two programs, each behind an early depth test against it.
  ResourceId depth = kNoResource;
};

// Per world (RenderWorld::glCached<GlShadeOptions>()): `split` false draws every pixel with the
// one program of a frame without the G-buffer's depth, so that tests compare the two draws.
struct GlShadeOptions {
  bool split = true;
};

void shadeOnGl(PassContext& context, const ShadeIo& io);

}  // namespace diptych
