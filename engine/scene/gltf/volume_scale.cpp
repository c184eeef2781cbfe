#include <cmath>
#include <map>
#include <vector>

#include "engine/scene/gltf/gltf_internal.h"

namespace diptych::gltf {
namespace {

// World length per mesh length, isotropically: cbrt |det M| (a thickness is a length along the
// surface's normal, whose direction a per-material constant cannot follow; for a uniform scale
// every choice agrees, and for a non-uniform one this is the geometric mean of the axis scales).
float meanScale(const mat4& transform) {
  return std::cbrt(std::abs(glm::determinant(mat3(transform))));
}

bool sameScale(float a, float b) {
  return std::abs(a - b) <= 1e-6f * std::max(a, b);
}

}  // namespace

void scaleVolumeThickness(Scene& scene) {
  const std::size_t materialCount = scene.materials.size();
  // Per volume material, the distinct scales it is placed at, in instance order.
  std::vector<std::vector<float>> scales(materialCount);
  auto scaleIndex = [&](int material, float s) {
    std::vector<float>& list = scales[std::size_t(material)];
    for (std::size_t k = 0; k < list.size(); ++k)
      if (sameScale(list[k], s)) return int(k);
    list.push_back(s);
    return int(list.size()) - 1;
  };
  std::map<std::pair<int, int>, int> meshCopy;      // (mesh, scale index) -> mesh used
  std::map<std::pair<int, int>, int> materialCopy;  // (material, scale index) -> material
  for (Instance& instance : scene.instances) {
    const int material = scene.meshes[std::size_t(instance.mesh)].material;
    if (material < 0 || std::size_t(material) >= materialCount ||
        !(scene.materials[std::size_t(material)].thickness > 0.f))
      continue;
    const float s = meanScale(instance.transform);
    const int k = scaleIndex(material, s);
    if (k == 0) continue;  // the first scale keeps the original mesh and material
    auto [mat, newMaterial] = materialCopy.try_emplace({material, k}, -1);
    if (newMaterial) {
      Material copy = scene.materials[std::size_t(material)];
      copy.name += " (instance scale " + std::to_string(s) + ")";
      mat->second = int(scene.materials.size());
      scene.materials.push_back(std::move(copy));
    }
    auto [mesh, newMesh] = meshCopy.try_emplace({instance.mesh, k}, -1);
    if (newMesh) {
      Mesh copy = scene.meshes[std::size_t(instance.mesh)];
      copy.material = mat->second;
      mesh->second = int(scene.meshes.size());
      scene.meshes.push_back(std::move(copy));
    }
    instance.mesh = mesh->second;
  }
  for (std::size_t m = 0; m < materialCount; ++m) {
    if (scales[m].empty()) continue;
    scene.materials[m].thickness *= scales[m][0];
  }
  for (const auto& [key, copy] : materialCopy)
    scene.materials[std::size_t(copy)].thickness *=
        scales[std::size_t(key.first)][std::size_t(key.second)];
}

}  // namespace diptych::gltf
