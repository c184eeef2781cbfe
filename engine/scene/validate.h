#pragma once
// Checks a loaded scene before anything renders it. Errors are InputErrors naming
// Scene::sourcePath and the element; recoveries are appended to Scene::warnings.
#include "engine/core/work_limit.h"
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
// Also rejects, naming the element, anything beyond these limits (docs/robustness.md): finite
// values whose products in shading overflow a float (3.4e38) become Inf pixels otherwise.
void validateScene(Scene& scene);

// Lights are looped over per pixel (cost = pixels x lights); meshes are held in memory twice
// (ours and Embree's or GL's).
constexpr std::size_t kMaxLights = 1024;
constexpr std::size_t kMaxTriangles =
    std::size_t(double(std::size_t(1) << 23) * kWorkLimitScale);  // 8.4 million
// World-space coordinates, lengths, radii, near/far: squares of lengths stay below 1e24.
constexpr float kMaxCoordinate = 1e12f;
// Emitted quantities: light colour x intensity, emission, ambient, environment colour x
// intensity and pixels. A point light at 1e6 units needs intensity ~1e12 x its unit-scale value.
constexpr float kMaxEmitted = 1e20f;
// Reflectances and coefficients (colours, ka, kd, ks, kps, kt, checker colours): a product over
// 8 bounces stays below 1e16, and times kMaxEmitted below the float range.
constexpr float kMaxReflectance = 100.f;
constexpr float kMaxExponent = 1e6f;  // Phong exponent

// Area-weighted vertex normals: sum over incident triangles of cross(e1, e2) (its length is
// twice the area, so larger faces weigh more), normalised. Zero where every face is degenerate.
std::vector<vec3> areaWeightedNormals(const Mesh& mesh);

}  // namespace diptych
