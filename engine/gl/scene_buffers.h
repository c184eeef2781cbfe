#pragma once
// A WorldGeometry on the GPU. All meshes share one set of buffers; mesh m's triangles are
// triangles [firstTriangle, firstTriangle + triangleCount) of the shared index buffer, whose
// indices are already offset to the shared vertex arrays. The buffers are tightly packed float
// and uint arrays: vertex attributes and the element buffer for draws, and buffer textures of
// one vertex (RGB32F, RG32F, RGBA32F) or one triangle (RGB32UI) a texel for the shaders that
// rebuild a hit (shaders/gl/scene_buffers.glsl).
#include <cstdint>
#include <vector>

#include "engine/gl/objects.h"
#include "engine/scene/world_geometry.h"

namespace diptych::gl {

struct GlMeshRange {
  int instance = 0;   // WorldMesh::instance
  int material = -1;  // WorldMesh::material, -1 = default material
  std::uint32_t firstTriangle = 0;
  std::uint32_t triangleCount = 0;
  // The mesh bounds a solid with outward faces (closed_mesh.h), and its world bounds: the
  // G-buffer culls its back faces when the eye is outside them.
  bool closedOutward = false;
  vec3 boundsLo{0.f}, boundsHi{0.f};
  // An analytic sphere (WorldMesh::analytic, not an SDF): the G-buffer may draw it as a
  // ray-cast impostor instead of its triangles (gbuffer_raster.h, GBufferTargets::impostors).
  // Object space is the sphere's (centre 0, `sphereRadius`); the world ray maps to it by
  // `toObject` (the instance transform's inverse, rounded to float).
  bool sphere = false;
  float sphereRadius = 0.f;
  mat4 toObject{1.f};
};

struct GlSceneBuffers {
  Buffer positions;  // 3 floats per vertex, world space
  Buffer normals;    // 3 floats per vertex, world space, unit
  Buffer uvs;        // 2 floats per vertex; (0, 0) for meshes without uvs
  Buffer indices;    // 3 uints per triangle, into the shared vertex arrays
  Buffer tangents;   // 4 floats per vertex (xyz, handedness); 0 without a normal map
  // The five buffers' views, in the order above (UNIT_SCENE_POSITIONS ... UNIT_SCENE_TANGENTS).
  BufferTexture positionTexels, normalTexels, uvTexels, indexTexels, tangentTexels;
  VertexArray vertexArray;          // attribute 0 = position, element buffer = indices
  std::vector<GlMeshRange> meshes;  // same order as WorldGeometry::meshes
  std::size_t vertexCount = 0;
  std::size_t triangleCount = 0;

  // Binds the five views to their UNIT_SCENE_* texture units (engine/gl/bindings.h).
  void bind() const;
};

GlSceneBuffers uploadScene(const WorldGeometry& geometry);

}  // namespace diptych::gl
