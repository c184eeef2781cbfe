// The scene as uploaded by engine/gl/scene_buffers.cpp: buffer textures over its tightly packed
// arrays, a vertex or a triangle a texel, read with texelFetch (not SSBOs, which llvmpipe reads
// a lane at a time; docs/gl.md, "Scene data"). Units: common/bindings.glsl.
#include "common/bindings.glsl"
layout(binding = UNIT_SCENE_POSITIONS) uniform samplerBuffer uScenePositions;  // RGB32F
layout(binding = UNIT_SCENE_NORMALS) uniform samplerBuffer uSceneNormals;      // RGB32F
layout(binding = UNIT_SCENE_UVS) uniform samplerBuffer uSceneUvs;              // RG32F
layout(binding = UNIT_SCENE_INDICES) uniform usamplerBuffer uSceneIndices;     // RGB32UI
// World tangent xyz and handedness w per vertex; zero where the mesh has none (no normal map).
layout(binding = UNIT_SCENE_TANGENTS) uniform samplerBuffer uSceneTangents;    // RGBA32F

vec4 sceneTangent(uint vertex) { return texelFetch(uSceneTangents, int(vertex)); }

uvec3 sceneTriangle(uint triangle) { return texelFetch(uSceneIndices, int(triangle)).xyz; }

vec3 scenePosition(uint vertex) { return texelFetch(uScenePositions, int(vertex)).xyz; }

vec3 sceneNormal(uint vertex) { return texelFetch(uSceneNormals, int(vertex)).xyz; }

// The texture coordinates of a vertex; (0, 0) for meshes without them.
vec2 sceneUv(uint vertex) { return texelFetch(uSceneUvs, int(vertex)).xy; }
