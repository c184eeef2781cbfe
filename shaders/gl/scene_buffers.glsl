// The scene as uploaded by engine/gl/scene_buffers.cpp: tightly packed float/uint arrays (std430
// `float[]`, since a vec3[] would be padded to 16 bytes). Bindings: common/bindings.glsl.
#include "common/bindings.glsl"
layout(std430, binding = BINDING_SCENE_POSITIONS) readonly buffer ScenePositions { float scenePositions[]; };
layout(std430, binding = BINDING_SCENE_NORMALS) readonly buffer SceneNormals { float sceneNormals[]; };
layout(std430, binding = BINDING_SCENE_UVS) readonly buffer SceneUvs { float sceneUvs[]; };
layout(std430, binding = BINDING_SCENE_INDICES) readonly buffer SceneIndices { uint sceneIndices[]; };
// World tangent xyz and handedness w per vertex; zero where the mesh has none (no normal map).
layout(std430, binding = BINDING_SCENE_TANGENTS) readonly buffer SceneTangents { vec4 sceneTangents[]; };

vec4 sceneTangent(uint vertex) { return sceneTangents[vertex]; }

uvec3 sceneTriangle(uint triangle) {
  return uvec3(sceneIndices[3u * triangle], sceneIndices[3u * triangle + 1u],
               sceneIndices[3u * triangle + 2u]);
}

vec3 scenePosition(uint vertex) {
  return vec3(scenePositions[3u * vertex], scenePositions[3u * vertex + 1u],
              scenePositions[3u * vertex + 2u]);
}

vec3 sceneNormal(uint vertex) {
  return vec3(sceneNormals[3u * vertex], sceneNormals[3u * vertex + 1u],
              sceneNormals[3u * vertex + 2u]);
}
