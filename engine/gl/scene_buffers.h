#pragma once
// A WorldGeometry on the GPU. All meshes share one set of buffers; mesh m's triangles are
// triangles [firstTriangle, firstTriangle + triangleCount) of the shared index buffer, whose
// indices are already offset to the shared vertex arrays. The buffers are tightly packed float
// and uint arrays, so shaders read them as std430 `float[]`/`uint[]` SSBOs (a vec3[] would have
// a 16-byte stride) as well as vertex attributes.
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
  Buffer positions;                 // 3 floats per vertex, world space
  Buffer normals;                   // 3 floats per vertex, world space, unit
  Buffer uvs;                       // 2 floats per vertex; (0, 0) for meshes without uvs
  Buffer indices;                   // 3 uints per triangle, into the shared vertex arrays
  Buffer tangents;                  // 4 floats per vertex (xyz, handedness); 0 without a normal map
  VertexArray vertexArray;          // attribute 0 = position, element buffer = indices
  std::vector<GlMeshRange> meshes;  // same order as WorldGeometry::meshes
  std::size_t vertexCount = 0;
  std::size_t triangleCount = 0;

  // Binds the five buffers to the BINDING_SCENE_* SSBO points (engine/gl/bindings.h).
  void bindStorage() const;
};

GlSceneBuffers uploadScene(const WorldGeometry& geometry);

}  // namespace diptych::gl
