#include "engine/scene/scene.h"

namespace diptych {

const Material& Scene::defaultMaterial() {
  // Both sides visible (meshes without a material, JSON's default; docs/materials.md).
  static const Material material{.name = "default", .doubleSided = true};
  return material;
}

int Scene::movingInstances() const {
  int n = 0;
  for (const Instance& inst : instances) n += inst.motion != vec3(0.f);
  return n;
}

Aabb Scene::bounds() const {
  Aabb box;
  for (const Instance& inst : instances) {
    for (const vec3& p : meshes[inst.mesh].positions)
      box.extend(vec3(inst.transform * vec4(p, 1.f)));
  }
  return box;
}

}  // namespace diptych
