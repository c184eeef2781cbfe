#pragma once
// Closed meshes, for back-face culling in the G-buffer (gbuffer_raster.h): a ray from a point
// outside a closed solid meets its surface first where it enters, on a face turned toward the
// ray's origin. So for a mesh that bounds a solid with its counter-clockwise faces turned
// outward, seen from outside, culling its back faces removes only fragments that a nearer front
// face of the same mesh covers: the G-buffer is unchanged and the rasterizer skips half of the
// triangles. What a GPU engine does for closed geometry, checked here instead of assumed.
#include <cstdint>
#include <vector>

#include "engine/core/math.h"

namespace diptych::gl {

// Vertices closer than this fraction of the mesh's bounding-box diagonal are one corner: a
// tessellated sphere's seam (u = 0 and u = 1) and bottom pole (sin(pi) in float is not 0) are
// apart by ~1e-7 of the radius, a crack no pixel-centre ray is expected to pass through.
inline constexpr float kClosedMeshWeld = 1e-6f;

// True when the triangles bound a solid with outward (counter-clockwise) winding: with corners
// welded as above, every directed edge is used by one triangle and its reverse by exactly one
// other, and the enclosed signed volume is positive. Triangles with two equal corners (the poles
// of a UV sphere) cover no pixel and are left out. Non-finite positions, open borders,
// non-manifold or inconsistently wound edges give false.
bool isClosedOutward(const std::vector<vec3>& positions, const std::vector<std::uint32_t>& indices);

// Whether `eye` is farther than `clearance` from the box that holds a mesh, with a relative
// margin: then it is outside the solid too. Conservative: an eye inside the box but outside the
// solid is not culled. The G-buffer passes its near plane's reach as `clearance`: nearer, the
// near plane could clip the front faces and leave the back faces nearest.
bool outsideBounds(const vec3& eye, const vec3& lo, const vec3& hi, float clearance = 0.f);
// The farthest a point of the near plane's visible rectangle is from the eye: znear at the
// centre, znear sqrt(1 + tan^2(fov/2) (1 + aspect^2)) at its corners.
float nearPlaneReach(float znear, float verticalFov, float aspect);

}  // namespace diptych::gl
