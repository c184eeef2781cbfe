#pragma once
// Analytic shapes tessellated into triangle meshes, in object space, counter-clockwise seen from
// outside, with unit normals and uvs. Pure functions: the JSON loader places them with a
// transform. Segment counts are clamped to sensible minimums (3 around, 2 from pole to pole).
#include <array>

#include "engine/scene/scene.h"

namespace diptych {

// Rectangle in the y = 0 plane centred on the origin, size.x along x and size.y along z,
// normal +y, split into segments.x * segments.y quads; uv = (x/size.x + 1/2, z/size.y + 1/2).
// Triangles: 2 * segments.x * segments.y.
Mesh makePlane(vec2 size, ivec2 segments = ivec2(1));

// Quad through four corners in order (counter-clockwise from the front): triangles (0,1,2) and
// (0,2,3); uvs (0,0),(1,0),(1,1),(0,1); one normal for all four vertices, the Newell normal
// (the area-weighted normal of the polygon, exact for planar quads, averaged for warped ones).
Mesh makeQuad(const std::array<vec3, 4>& corners);

// Axis-aligned box centred on the origin: 6 faces with their own 4 vertices (flat normals),
// each face uv-mapped to [0,1]^2. 12 triangles.
Mesh makeBox(vec3 size);

// UV sphere: p(u, v) = r (sin(theta) cos(phi), cos(theta), -sin(theta) sin(phi)) with
// phi = 2 pi u, theta = pi v, v = 0 at the +y pole; normal p / r. `slices` around (phi),
// `stacks` pole to pole (theta). Triangles: 2 * slices * (stacks - 1) (one per slice at each
// pole cap, two elsewhere).
Mesh makeUvSphere(float radius, int slices, int stacks);

// Disc of radius r in the y = 0 plane, normal +y: a centre vertex and `slices` rim vertices,
// uv = (x/2r + 1/2, z/2r + 1/2). Triangles: slices.
Mesh makeDisc(float radius, int slices);

// Cylinder around the y axis from y = -h/2 to +h/2. Side uv: (phi / 2pi, height fraction).
// Triangles: 2 * slices, plus slices per cap when capped.
Mesh makeCylinder(float radius, float height, int slices, bool capped = true);

// Cone around the y axis, base of radius r at y = -h/2, apex at y = +h/2. The side normal at
// angle phi is normalize(h cos(phi), r, -h sin(phi)) (perpendicular to the slant line); each
// side triangle has its own apex vertex so the apex normal is the one of its slice centre.
// Triangles: slices, plus slices for the base when capped.
Mesh makeCone(float radius, float height, int slices, bool capped = true);

// The scene with every analytic quadric (Mesh::analytic) replaced by its tessellation at
// `segments` around (spheres: segments x segments/2), traced as triangles: the "geometry"
// comparison axis of `diptych compare` (docs/geometry.md). SDF objects are replaced by their
// surface-nets polygonisation at `segments` cells per axis, traced as triangles too, unless that
// would exceed kMaxSdfEvaluations (then the object stays exact and a warning is added to the
// returned scene's warnings).
Scene tessellateAnalytic(const Scene& scene, int segments);

}  // namespace diptych
