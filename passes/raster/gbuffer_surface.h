#pragma once
// The G-buffer's stored surface (engine/gl/gbuffer_raster.h, `surface`: position, uv, face and
// shading normals, material) for the GL passes that would otherwise rebuild it per pixel from the
// hits (shaders/gl/gbuffer_surface.glsl). A GL pass reads it in setup beside its `hits`, compiles
// its program with surfaceDefines() and binds it with bindSurface() before drawing; when the
// recipe's G-buffer writes no surface the pass keeps rebuilding, with the same image.
#include <vector>

#include "engine/gl/shader.h"
#include "engine/graph/pass.h"

namespace diptych {

inline constexpr const char* kSurface = "surface";

// gbuffer.surface beside `hits` (PassBuilder setup), or kNoResource. A glOnly read: a pass the
// compiler places on the CPU (shade) drops it and costs no readback.
ResourceId readSurface(PassBuilder& builder, ResourceId hits);

// DIPTYCH_GBUFFER_SURFACE when `surface` is connected, else nothing.
std::vector<gl::ShaderDefine> surfaceDefines(ResourceId surface);

// Binds gbuffer.surface at UNIT_GBUFFER_SURFACE when connected.
void bindSurface(PassContext& context, ResourceId surface);

}  // namespace diptych
