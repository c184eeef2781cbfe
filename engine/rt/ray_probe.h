#pragma once
// Secondary-ray health of one view, for numerical checks (`diptych check`, tests/numerics):
// every pixel-centre primary hit spawns its shadow rays (one per light, toward the light's
// position) and, for mirrors and transmitters, its reflected and transmitted ray, exactly as the
// Whitted tracer does (spawnRay, makeShadowRay). A flat triangle can never be hit again by a ray
// that leaves it, so any secondary ray whose closest hit is its own triangle is a
// self-intersection, whatever the scene.
#include <cstdint>
#include <vector>

#include "engine/rt/rt_scene.h"
#include "engine/scene/scene.h"

namespace diptych {

struct RayProbe {
  int width = 0, height = 0, lights = 0;
  long primaryHits = 0;
  long secondaryRays = 0;  // shadow + reflected + transmitted rays traced
  long selfHits = 0;       // of those, the ones whose closest hit was their own triangle
  // occluded[(y * width + x) * lights + l]: 1 shadowed, 0 lit, 2 no primary hit / inactive ray.
  std::vector<std::uint8_t> occluded;
};

RayProbe probeSecondaryRays(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                            const Camera& camera, int width, int height);

// Pixels (x lights) that are shadowed in `reference` and lit in `test` (lost shadows), and the
// converse (gained: false occlusion, acne). Probes must have the same size and light count.
struct ShadowDifference {
  long lost = 0, gained = 0, compared = 0;
};
ShadowDifference compareShadows(const RayProbe& test, const RayProbe& reference);

}  // namespace diptych
