#pragma once
// The cases of `diptych check` (docs/numerics.md): the scene as given, uniformly scaled,
// translated, and seen by a grazing camera, each compared with its untransformed twin.
#include <string>
#include <vector>

#include "engine/scene/scene.h"

namespace diptych::cli {

struct CheckCase {
  std::string name;  // "scale 1e-06", "offset +1e+05 x", "grazing", "grazing scale 1e+06"
  double scale = 1.0;
  double offset = 0.0;   // added to x
  bool grazing = false;  // camera lowered to skim the scene's lowest plane
  bool reference() const { return scale == 1.0 && offset == 0.0; }
};

// References first (as given; grazing), then each scale and offset, then the grazing camera at
// the extreme scales and the largest offset.
std::vector<CheckCase> checkCases(const std::vector<double>& scales,
                                  const std::vector<double>& offsets);

// The camera moved down to 1/100 of its distance to the target above the scene's lowest
// horizontal plane (bounds.lo.y, "up" = +y), looking at the target's foot point on that plane:
// primary rays meet the floor at about 0.6 degrees.
Camera grazingCamera(const Scene& scene);

// The scene for one case: grazing camera, similarity transform, then camera-relative rebasing
// (when `rebase` and the camera is far, as loadScene does). The camera becomes explicit.
// `rebasedTo` receives the origin subtracted (0 when not rebased).
Scene caseScene(const Scene& base, const CheckCase& c, bool rebase, glm::dvec3& rebasedTo);

// Shadow-map depth-precision warnings for the shadow_map pass's light frusta at `resolution`:
// the float depth error (storage in reversed-Z D32F, 2^-24 z, plus the light view transform's
// rounding, 2^-22 max|coordinate|) against a quarter of the shadow-map texel's world footprint,
// the scale a slope-scaled bias of a few units is sized for. Non-finite frusta are reported too.
std::vector<std::string> shadowMapDepthWarnings(const Scene& scene, int resolution);

}  // namespace diptych::cli
