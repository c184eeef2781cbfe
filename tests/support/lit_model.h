#pragma once
// A glTF model that ships without lights (Khronos' test models, ../shared/scenes) made
// renderable the same way by every test that needs it: a point light above the model's centre
// and in front of it, and the model framed when the file has no camera.
#include "engine/scene/camera_math.h"
#include "engine/scene/scene.h"

namespace diptych::testing {

inline void addTestLight(Scene& scene, float intensity = 50.f) {
  const Aabb b = scene.bounds();
  Light l;
  l.type = LightType::Point;
  l.position = 0.5f * (b.lo + b.hi) + vec3(0.f, 1.5f * (b.hi.y - b.lo.y), 0.f) +
               vec3(0.f, 0.f, 0.5f * (b.hi.z - b.lo.z));
  l.intensity = intensity;
  scene.lights.push_back(l);
  if (!scene.hasCamera) scene.camera = frameBounds(b);
}

}  // namespace diptych::testing
