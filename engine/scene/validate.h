#pragma once
// Checks a loaded scene before anything renders it. Errors are InputErrors naming
// Scene::sourcePath and the element; recoveries are appended to Scene::warnings.
#include "engine/scene/scene.h"

namespace diptych {

// Rejects: non-finite numbers anywhere (positions, normals, uvs, tangents, instance transforms,
// material coefficients, light and camera parameters, ambient, environment); index buffers not
// made of whole triangles or pointing past the vertices; per-vertex arrays whose length differs
// from the positions; material, mesh and texture references out of range; negative
// coefficients, radii, intensities, IOR <= 0, field of view outside (0, 180) degrees, zero-size
// area lights, a camera whose target equals its position.
// Recovers (with one warning per mesh): zero-length normals are replaced by the area-weighted
// normal of the faces around the vertex (or +Y if those faces are degenerate too), and
// non-unit normals are renormalised silently.
void validateScene(Scene& scene);

// Area-weighted vertex normals: sum over incident triangles of cross(e1, e2) (its length is
// twice the area, so larger faces weigh more), normalised. Zero where every face is degenerate.
std::vector<vec3> areaWeightedNormals(const Mesh& mesh);

}  // namespace diptych
