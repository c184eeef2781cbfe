#pragma once
// Camera motions of the viewer, on the scene's own Camera (position, target, up), so that a
// moved camera is saved and rendered exactly like one written in a JSON scene.
#include <nlohmann/json.hpp>

#include "engine/scene/scene.h"

namespace diptych::view {

// Turntable orbit about the target: yaw about `up`, pitch about the camera's right axis,
// stopping short of the poles so that up never becomes parallel to the view direction.
void orbit(Camera& camera, float yawRadians, float pitchRadians);
// Moves position and target together across the image plane; dx, dy are fractions of the
// distance to the target (so a drag across the window moves about one view width).
void pan(Camera& camera, float dx, float dy);
// Moves the position toward (factor < 1) or away from (factor > 1) the target.
void dolly(Camera& camera, float factor);
// First-person motion: `move` is (right, up, forward) in multiples of the distance to the
// target; yaw/pitch turn the view about the position (the target moves, the position stays).
void fly(Camera& camera, vec3 move, float yawRadians, float pitchRadians);

// The float d (in degrees) with glm::radians(d) == radians, as the scene loader computes the
// field of view, when one lies within a few ulps; so a saved camera reads back bit for bit.
float fovDegrees(float radians);
// Snaps the field of view to glm::radians(d) for a float d, which fovDegrees then finds.
inline void snapFov(Camera& c) {
  c.verticalFov = glm::radians(fovDegrees(c.verticalFov));
}

// The camera as a JSON scene's "camera" object (docs/scene-format.md), near/far included so
// that a renderer reading it back gets the same clip range.
// `worldOrigin`: where a rebased scene's file origin went (Scene::worldOrigin); position and
// target are written in the file's coordinates (+ worldOrigin, in double), as cameras are read.
nlohmann::json cameraToJson(const Camera& camera, const glm::dvec3& worldOrigin = {});

}  // namespace diptych::view
