#include "engine/gl/scene_buffers.h"

#include <limits>

#include "engine/core/error.h"
#include "engine/gl/bindings.h"
#include "engine/gl/closed_mesh.h"

namespace diptych::gl {

GlSceneBuffers uploadScene(const WorldGeometry& geometry) {
  std::vector<float> positions, normals, uvs, tangents;
  std::vector<std::uint32_t> indices;
  GlSceneBuffers out;
  for (std::size_t m = 0; m < geometry.meshes.size(); ++m) {
    const WorldMesh& mesh = geometry.meshes[m];
    const std::size_t base = positions.size() / 3;
    if (mesh.normals.size() != mesh.positions.size() ||
        (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) ||
        mesh.indices.size() % 3 != 0) {
      throw Error("world mesh " + std::to_string(m) + " (instance " +
                  std::to_string(mesh.instance) + ") has inconsistent attribute counts");
    }
    if (base + mesh.positions.size() > std::numeric_limits<std::uint32_t>::max()) {
      throw Error("scene has more vertices than 32-bit indices can address");
    }
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      positions.insert(positions.end(),
                       {mesh.positions[v].x, mesh.positions[v].y, mesh.positions[v].z});
      normals.insert(normals.end(), {mesh.normals[v].x, mesh.normals[v].y, mesh.normals[v].z});
      const vec2 uv = mesh.uvs.empty() ? vec2(0.f) : mesh.uvs[v];
      uvs.insert(uvs.end(), {uv.x, uv.y});
      const vec4 t = v < mesh.tangents.size() ? mesh.tangents[v] : vec4(0.f);
      tangents.insert(tangents.end(), {t.x, t.y, t.z, t.w});
    }
    GlMeshRange range;
    range.instance = mesh.instance;
    range.material = mesh.material;
    range.firstTriangle = std::uint32_t(indices.size() / 3);
    range.triangleCount = std::uint32_t(mesh.indices.size() / 3);
    for (std::uint32_t i : mesh.indices) {
      if (i >= mesh.positions.size()) {
        throw Error("world mesh " + std::to_string(m) + " has index " + std::to_string(i) +
                    " past its " + std::to_string(mesh.positions.size()) + " vertices");
      }
      indices.push_back(std::uint32_t(base + i));
    }
    range.closedOutward = isClosedOutward(mesh.positions, mesh.indices);
    Aabb box;
    for (const vec3& p : mesh.positions) box.extend(p);
    range.boundsLo = box.lo;
    range.boundsHi = box.hi;
    if (mesh.analytic && !mesh.analytic->sdf && mesh.analytic->shape.type == ShapeType::Sphere) {
      range.sphere = true;
      range.sphereRadius = mesh.analytic->shape.radius;
      range.toObject = mat4(mesh.analytic->toObject);
    }
    out.meshes.push_back(range);
  }
  out.vertexCount = positions.size() / 3;
  out.triangleCount = indices.size() / 3;
  out.positions = Buffer::create(positions.size() * 4, positions.data());
  out.normals = Buffer::create(normals.size() * 4, normals.data());
  out.uvs = Buffer::create(uvs.size() * 4, uvs.data());
  out.tangents = Buffer::create(tangents.size() * 4, tangents.data());
  out.indices = Buffer::create(indices.size() * 4, indices.data());
  out.positionTexels = BufferTexture::create(out.positions, GL_RGB32F, 12, "scene.positions");
  out.normalTexels = BufferTexture::create(out.normals, GL_RGB32F, 12, "scene.normals");
  out.uvTexels = BufferTexture::create(out.uvs, GL_RG32F, 8, "scene.uvs");
  out.indexTexels = BufferTexture::create(out.indices, GL_RGB32UI, 12, "scene.indices");
  out.tangentTexels = BufferTexture::create(out.tangents, GL_RGBA32F, 16, "scene.tangents");

  out.vertexArray = VertexArray::create();
  const GLuint vao = out.vertexArray.id();
  glVertexArrayVertexBuffer(vao, 0, out.positions.id(), 0, 3 * sizeof(float));
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  glVertexArrayElementBuffer(vao, out.indices.id());
  return out;
}

void GlSceneBuffers::bind() const {
  positionTexels.bind(UNIT_SCENE_POSITIONS);
  normalTexels.bind(UNIT_SCENE_NORMALS);
  uvTexels.bind(UNIT_SCENE_UVS);
  indexTexels.bind(UNIT_SCENE_INDICES);
  tangentTexels.bind(UNIT_SCENE_TANGENTS);
}

}  // namespace diptych::gl
