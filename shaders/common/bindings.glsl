// bindings.glsl: every texture unit shared between passes (and the record sizes of the scene's
// buffer textures), defined once for GLSL and C++. GLSL includes it and writes
// `layout(binding = X)` (constant expressions in layout qualifiers: GLSL 4.40+, section 4.4);
// C++ includes it inside namespace diptych::gl through engine/gl/bindings.h.
// Same subset rules as shading.glsl: only `const int` declarations here.
#ifndef DIPTYCH_BINDINGS_GLSL
#define DIPTYCH_BINDINGS_GLSL

// The scene's read-only data, as buffer textures (samplerBuffer views of the uploaded buffers,
// engine/gl/objects.h BufferTexture; docs/gl.md, "Scene data"), on units 16 and up so that the
// passes' own units below stay as they were. Geometry (engine/gl/scene_buffers.cpp,
// shaders/gl/scene_buffers.glsl):
const int UNIT_SCENE_POSITIONS = 16;
const int UNIT_SCENE_NORMALS = 17;
const int UNIT_SCENE_UVS = 18;
const int UNIT_SCENE_INDICES = 19;
const int UNIT_SCENE_TANGENTS = 20;
// Materials, instances and lights (engine/gl/shading_buffers.cpp, shaders/gl/scene_shading.glsl).
const int UNIT_SCENE_MATERIALS = 21;
const int UNIT_SCENE_INSTANCES = 22;
const int UNIT_SCENE_LIGHTS = 23;
// Their records' sizes in RGBA32F texels: GpuMaterial and GpuLight (scene_shading.glsl), as
// engine/gl/shading_buffers.cpp packMaterial and packLight write them.
const int GPU_MATERIAL_TEXELS = 20;
const int GPU_LIGHT_TEXELS = 5;
// Per-texture records (engine/gl/scene_textures.cpp, shaders/gl/scene_textures.glsl).
const int UNIT_SCENE_TEXTURE_INFO = 24;
// The shadow-map lookup's per-layer matrices and per-light records (shadow_map_lookup.frag).
const int UNIT_SHADOW_LAYERS = 25;
const int UNIT_SHADOW_LIGHTS = 26;
// Texture units every stage must offer (GL_MAX_*_TEXTURE_IMAGE_UNITS; GL 4.5 guarantees 16,
// Mesa and the desktop GPUs' drivers give 32): checked when a context is created.
const int UNIT_COUNT = 27;

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
