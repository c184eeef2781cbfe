#pragma once
// What a pass may require of the scene. A pass whose need is absent is culled with the reason
// below, and its consumers read the default value each of its outputs declares.
#include "engine/scene/scene.h"

namespace diptych {

enum class SceneNeed {
  Geometry,              // at least one triangle
  Lights,                // any light
  ShadowCastingLight,    // a light with castsShadows
  AreaLight,             // quad, disc or sphere light
  ReflectiveMaterial,    // kps > 0 on a used material
  TransmissiveMaterial,  // kt > 0 on a used material
  EmissiveMaterial,      // M_E > 0 on a used material
  EnvironmentMap,        // equirect or cube environment (not a solid colour)
  TexturedMaterial,      // a used material with a colour texture (and no checker)
};

const char* sceneNeedName(SceneNeed need);
const char* missingReason(SceneNeed need);  // "scene has no transmissive materials"
bool sceneSatisfies(const Scene& scene, SceneNeed need);
// A material with a colour texture (and no checker, which replaces it): what TexturedMaterial
// asks of a used material, and the pixels the texture_filtering signal is measured on.
bool readsColorTexture(const Scene& scene, const Material& material);

}  // namespace diptych
