#pragma once
// Light frusta of the shadow_map pass: one view-projection per shadow-map layer, fitted to the
// scene bounds. Depth convention: reversed-Z on [0, 1] (glClipControl ZERO_TO_ONE, depth 1 at
// the near plane, 0 at the far plane, cleared to 0, GL_GREATER), as the camera raster uses, so
// that D32F keeps a nearly constant relative precision along the whole light range.
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/scene.h"

namespace diptych::shadowmap {

// Values match the KIND_* constants of shaders/shadow_map_lookup.frag.
enum class ViewKind { Unshadowed = 0, Ortho = 1, Perspective = 2, Cube = 3 };

struct LightFrustum {
  ViewKind kind = ViewKind::Unshadowed;
  int firstLayer = 0;             // into the shadow-map array
  int layers = 0;                 // 1 (ortho, perspective) or 6 (cube faces +x, -x, +y, -y, +z, -z)
  std::vector<mat4> viewProj;     // one per layer, reversed-Z
  float zNear = 0.f, zFar = 1.f;  // along the view axis, world units
  // World size of one texel: ortho, in world units; perspective and cube, per unit of axis depth
  // (so the footprint at axis depth z is z * texelScale).
  float texelScale = 0.f;
  // PCSS light extent: world diameter (perspective, cube) or angular diameter in radians (ortho).
  float lightSize = 0.f;
  vec3 position{0.f};   // the light's (or area light's centre) position
  vec3 direction{0.f};  // travel direction (ortho, perspective)
};

struct FrustumOptions {
  int resolution = 2048;
  float pointLightSize = 0.1f;       // PCSS world diameter for point and spot lights (the pass
                                     // passes light_fraction times the scene diagonal)
  float directionalAngle = 0.0093f;  // PCSS angular diameter for directional lights (the sun)
};

// Reversed-Z perspective with a finite far plane, ZERO_TO_ONE: depth = 1 at zNear, 0 at zFar.
mat4 reversedPerspective(float verticalFov, float aspect, float zNear, float zFar);

// One frustum per light (Scene::lights order); lights that cast no shadow get Unshadowed and no
// layer. `bounds` is the scene's world bounds (WorldGeometry::bounds).
std::vector<LightFrustum> fitLightFrusta(const std::vector<Light>& lights, const Aabb& bounds,
                                         const FrustumOptions& options);

int totalLayers(const std::vector<LightFrustum>& frusta);

}  // namespace diptych::shadowmap
