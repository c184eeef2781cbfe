// bindings.glsl: every SSBO binding point (and the one texture unit shared between passes),
// defined once for GLSL and C++. GLSL includes it and writes `layout(std430, binding = X)`
// (constant expressions in layout qualifiers: GLSL 4.40+, section 4.4); C++ includes it inside
// namespace diptych::gl through engine/gl/bindings.h. Same subset rules as shading.glsl: only
// `const int` declarations here.
#ifndef DIPTYCH_BINDINGS_GLSL
#define DIPTYCH_BINDINGS_GLSL

// The scene's geometry (engine/gl/scene_buffers.cpp, shaders/gl/scene_buffers.glsl).
const int BINDING_SCENE_POSITIONS = 0;
const int BINDING_SCENE_NORMALS = 1;
const int BINDING_SCENE_UVS = 2;
const int BINDING_SCENE_INDICES = 3;
// Materials, instances and lights (engine/gl/shading_buffers.cpp, shaders/gl/scene_shading.glsl).
const int BINDING_SCENE_MATERIALS = 4;
const int BINDING_SCENE_INSTANCES = 5;
const int BINDING_SCENE_LIGHTS = 6;
// The shadow-map lookup's per-layer matrices and per-light records (shadow_lookup.frag).
const int BINDING_SHADOW_LAYERS = 7;
const int BINDING_SHADOW_LIGHTS = 8;

// Per-texture records and tangents (engine/gl/scene_textures.cpp, engine/gl/scene_buffers.cpp).
const int BINDING_SCENE_TEXTURES = 12;
const int BINDING_SCENE_TANGENTS = 13;

// Texture unit of scene_shading.glsl's uSceneAlphaMasks; units 0 to 2 are each pass's own.
const int UNIT_SCENE_ALPHA_MASKS = 7;
// Texture unit of the blend producers' first-surface target (blend_transmission_first.frag's
// output), read as uFirst by forward.frag and blend_transmission.frag.
const int UNIT_BLEND_FIRST = 2;
// Texture unit of gl/gbuffer_surface.glsl's uGBufferSurface (the G-buffer's stored surface).
const int UNIT_GBUFFER_SURFACE = 8;
// Texture unit of gl/scene_environment.glsl's uEnvironmentTexels (the exact background lookup).
const int UNIT_SCENE_ENVIRONMENT = 15;
// Texture unit of scene_shading.glsl's uSceneTextures (every scene texture with its mip chain).
const int UNIT_SCENE_TEXTURES = 6;

#endif
