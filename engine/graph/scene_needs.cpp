#include "engine/graph/scene_needs.h"

#include "engine/shading/shading.h"

namespace diptych {
namespace {

template <class Pred>
bool anyUsedMaterial(const Scene& s, Pred pred) {
  for (const Instance& inst : s.instances)
    if (pred(s.material(s.meshes[inst.mesh].material))) return true;
  return false;
}

bool positive(const vec3& v) {
  return v.x > 0.f || v.y > 0.f || v.z > 0.f;
}

}  // namespace

const char* sceneNeedName(SceneNeed need) {
  switch (need) {
    case SceneNeed::Geometry:
      return "geometry";
    case SceneNeed::Lights:
      return "lights";
    case SceneNeed::ShadowCastingLight:
      return "shadow_casting_light";
    case SceneNeed::AreaLight:
      return "area_light";
    case SceneNeed::ReflectiveMaterial:
      return "reflective_material";
    case SceneNeed::TransmissiveMaterial:
      return "transmissive_material";
    case SceneNeed::EmissiveMaterial:
      return "emissive_material";
    case SceneNeed::EnvironmentMap:
      return "environment_map";
    case SceneNeed::TexturedMaterial:
      return "textured_material";
  }
  return "?";
}

const char* missingReason(SceneNeed need) {
  switch (need) {
    case SceneNeed::Geometry:
      return "scene has no geometry";
    case SceneNeed::Lights:
      return "scene has no lights";
    case SceneNeed::ShadowCastingLight:
      return "scene has no shadow-casting lights";
    case SceneNeed::AreaLight:
      return "scene has no area lights";
    case SceneNeed::ReflectiveMaterial:
      return "scene has no reflective materials";
    case SceneNeed::TransmissiveMaterial:
      return "scene has no transmissive materials";
    case SceneNeed::EmissiveMaterial:
      return "scene has no emissive materials";
    case SceneNeed::EnvironmentMap:
      return "scene has no environment map";
    case SceneNeed::TexturedMaterial:
      return "scene has no colour-textured materials";
  }
  return "?";
}

bool sceneSatisfies(const Scene& s, SceneNeed need) {
  switch (need) {
    case SceneNeed::Geometry:
      for (const Instance& inst : s.instances)
        if (!s.meshes[inst.mesh].indices.empty()) return true;
      return false;
    case SceneNeed::Lights:
      return !s.lights.empty();
    case SceneNeed::ShadowCastingLight:
      for (const Light& l : s.lights)
        if (l.castsShadows) return true;
      return false;
    case SceneNeed::AreaLight:
      for (const Light& l : s.lights)
        if (l.type == LightType::QuadArea || l.type == LightType::DiscArea ||
            l.type == LightType::SphereArea)
          return true;
      return false;
    case SceneNeed::ReflectiveMaterial:
      // lobe: a prefiltered environment lookup also serves rough glTF lobes.
      return anyUsedMaterial(
          s, [](const Material& m) { return shading::materialHasReflection(m, /*lobe=*/true); });
    case SceneNeed::TransmissiveMaterial:
      return anyUsedMaterial(s,
                             [](const Material& m) { return shading::materialHasTransmission(m); });
    case SceneNeed::EmissiveMaterial:
      return anyUsedMaterial(s, [](const Material& m) { return positive(m.emission); });
    case SceneNeed::EnvironmentMap:
      return s.environment.type != EnvironmentType::Color;
    case SceneNeed::TexturedMaterial:
      return anyUsedMaterial(s, [&](const Material& m) { return readsColorTexture(s, m); });
  }
  return false;
}

bool readsColorTexture(const Scene& scene, const Material& m) {
  return !m.checker && m.colorTexture >= 0 && m.colorTexture < int(scene.textures.size());
}

}  // namespace diptych
