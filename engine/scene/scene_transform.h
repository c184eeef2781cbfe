#pragma once
// Whole-scene similarity transforms and camera-relative rebasing (docs/numerics.md).
#include <glm/vec3.hpp>

#include "engine/scene/scene.h"

namespace diptych {

// The scene scaled uniformly by `scale` about the origin, then translated by `translation`:
// instance transforms, camera (position, target, near/far, focus distance, aperture), light
// positions, quad edges, radii and ranges. Point and spot intensities (candela) are multiplied
// by scale^2 so that the 1/d^2 falloff leaves the image unchanged; directional lights (lux) and
// area lights (radiance per unit area: area x 1/d^2 is invariant) are left as they are. The
// arithmetic is double, rounded once to the scene's float fields, like a file written at that
// scale. Throws Error for a scale that is not finite and positive.
Scene similarityTransformed(const Scene& scene, double scale, const glm::dvec3& translation);

// The static snapshot of a scene at shutter time `time` in [0, 1]: every instance with a
// motion placed where it is then, translate((time - kFrameTime) * motion) * transform, and its
// motion zeroed. The raster side's motion blur renders such snapshots and averages them (the
// accumulation buffer, Haeberli and Akeley, SIGGRAPH 1990); a ray at `time` sees the moving
// scene as a ray at kFrameTime sees the snapshot (tested).
Scene sceneAtTime(const Scene& scene, float time);

// Camera-relative world: every instance translation, light position and the camera are moved by
// -origin, computed in double and rounded to float once, so that float coordinates hold the
// geometry near the camera to the precision of its own size rather than of |origin|. Geometry,
// ray tracing, rasterization and shading all read the moved scene, so they stay consistent.
void rebaseScene(Scene& scene, const glm::dvec3& origin);

// Rebases when the geometry is far from the origin compared with its own extent (max |c_i| of
// the bounding-box centre c > kRebaseRatio * largest side): there float coordinates would spend
// their bits on the offset. The trigger looks at the geometry, not the camera, so a small scene
// near the origin seen from far away is left where it is. The new origin is the camera position
// (camera-relative world, as engines do it) when the camera is near the geometry (within
// kRebaseRatio extents of the centre), else the box centre. Records the origin in
// scene.worldOrigin and returns it (0 when not moved).
inline constexpr double kRebaseRatio = 16.0;
glm::dvec3 rebaseIfFar(Scene& scene);

}  // namespace diptych
