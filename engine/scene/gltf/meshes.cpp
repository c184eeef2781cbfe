// glTF mesh primitives -> Mesh: attributes read through the bounds-checked accessor reader,
// strips and fans converted to triangle lists, point and line primitives skipped.
#include "engine/core/error.h"
#include "engine/scene/gltf/accessors.h"
#include "engine/scene/gltf/gltf_internal.h"

namespace diptych::gltf {
namespace {

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_STRIP:
      return "TRIANGLE_STRIP";
    case TINYGLTF_MODE_TRIANGLE_FAN:
      return "TRIANGLE_FAN";
    default:
      return "TRIANGLES";
  }
}

// glTF 2.0 spec 3.7.2.1: strip triangle i is (p_i, p_i+1, p_i+2) for even i and
// (p_i+1, p_i, p_i+2) for odd i, which keeps every triangle's winding; fan triangle i is
// (p_i+1, p_i+2, p_0), written here in the equivalent rotation (p_0, p_i+1, p_i+2).
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& v, int mode) {
  std::vector<std::uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (std::size_t i = 0; i + 2 < v.size(); ++i) {
      if (i % 2 == 0)
        out.insert(out.end(), {v[i], v[i + 1], v[i + 2]});
      else
        out.insert(out.end(), {v[i + 1], v[i], v[i + 2]});
    }
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (std::size_t i = 1; i + 1 < v.size(); ++i) out.insert(out.end(), {v[0], v[i], v[i + 1]});
  } else {
    out.assign(v.begin(), v.end() - v.size() % 3);
  }
  return out;
}

template <typename Vec, int N>
std::vector<Vec> unpack(const std::vector<float>& flat) {
  std::vector<Vec> out(flat.size() / N);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int c = 0; c < N; ++c) out[i][c] = flat[i * N + c];
  return out;
}

Mesh convertPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim,
                      const std::string& file, const std::string& place, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  auto attribute = [&](const char* key) {
    auto it = prim.attributes.find(key);
    return it == prim.attributes.end() ? -1 : it->second;
  };
  const int position = attribute("POSITION");
  if (position < 0) throw InputError(file, place + ".attributes.POSITION", "missing");
  mesh.positions = unpack<vec3, 3>(
      readFloatAccessor(model, position, 3, {file, place + ".attributes.POSITION"}));
  const std::size_t vertexCount = mesh.positions.size();

  auto optional = [&](const char* key, int components) {
    const int index = attribute(key);
    if (index < 0) return std::vector<float>{};
    const std::string where = place + ".attributes." + key;
    std::vector<float> flat = readFloatAccessor(model, index, components, {file, where});
    if (flat.size() / components != vertexCount)
      throw InputError(file, where,
                       "has " + std::to_string(flat.size() / components) +
                           " elements but POSITION has " + std::to_string(vertexCount));
    return flat;
  };
  mesh.normals = unpack<vec3, 3>(optional("NORMAL", 3));
  mesh.uvs = unpack<vec2, 2>(optional("TEXCOORD_0", 2));
  mesh.tangents = unpack<vec4, 4>(optional("TANGENT", 4));

  std::vector<std::uint32_t> vertices;
  if (prim.indices >= 0) {
    vertices = readIndexAccessor(model, prim.indices, {file, place + ".indices"});
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      if (vertices[i] >= vertexCount)
        throw InputError(file, place + ".indices",
                         "index " + std::to_string(vertices[i]) + " at position " +
                             std::to_string(i) + " is out of range (mesh '" + name + "' has " +
                             std::to_string(vertexCount) + " vertices)");
    }
  } else {
    vertices.resize(vertexCount);
    for (std::size_t i = 0; i < vertexCount; ++i) vertices[i] = std::uint32_t(i);
  }
  mesh.indices = toTriangleList(vertices, prim.mode);
  mesh.material = prim.material;
  if (prim.material >= int(model.materials.size()))
    throw InputError(file, place + ".material",
                     "material " + std::to_string(prim.material) + " does not exist");
  return mesh;
}

}  // namespace

std::vector<std::vector<int>> convertMeshes(const tinygltf::Model& model, const std::string& file,
                                            Scene& scene) {
  std::vector<std::vector<int>> made(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& src = model.meshes[m];
    for (std::size_t p = 0; p < src.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = src.primitives[p];
      const std::string place =
          "meshes[" + std::to_string(m) + "].primitives[" + std::to_string(p) + "]";
      const std::string name =
          "meshes[" + std::to_string(m) + "] '" + src.name + "' primitive " + std::to_string(p);
      const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        scene.warnings.push_back(file + ": " + place + ": skipped " + modeName(mode) +
                                 " primitive (only triangles are rendered)");
        continue;
      }
      if (!prim.targets.empty())
        scene.warnings.push_back(file + ": " + place + ": morph targets ignored");
      scene.meshes.push_back(convertPrimitive(model, prim, file, place, name));
      made[m].push_back(int(scene.meshes.size()) - 1);
    }
  }
  return made;
}

}  // namespace diptych::gltf
