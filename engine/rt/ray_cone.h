#pragma once
// Ray cones for texture level of detail at traced hits (Akenine-Möller, Nilsson, Andersson,
// Barré-Brisebois, Toth, Karras, "Texture Level of Detail Strategies for Real-Time Ray
// Tracing", Ray Tracing Gems, ch. 20, 2019, section 20.3.4; curvature spread after
// Akenine-Möller, Crassin, Boksansky, Belcour, Panteleev, Wright, "Improved Shader and Texture
// Level of Detail Using Ray Cones", JCGT 10(1), 2021). A cone is carried along a ray: its width
// grows by W' = W + spread * t; at a hit the texture LOD is
//   lambda = Delta_0 + log2(W) - log2(|n . d|) + 0.5 log2(w h)            (RTG eq. 20.23)
// with Delta_0 = 0.5 log2(uv area / world area) of the hit triangle (eq. 20.19). The texture
// size term is added per texture by resolveMaterial; coneUvLod returns the rest.
// A reflection at a surface of curvature k adds 2 k W to the spread (the normal turns by k W
// across the cone's footprint and the reflected direction by twice that; convex surfaces assumed,
// the sign of concave curvature is not tracked). Refraction keeps the spread (not modelled).
#include "engine/rt/surface_point.h"

namespace diptych {

struct RayCone {
  float width = 0.f;   // world-space width at the ray's origin
  float spread = 0.f;  // angle in radians by which the width grows per unit distance
};

// The pixel's spread angle, RTG eq. 20.30: atan(2 tan(fovY / 2) / height).
float pixelSpreadAngle(const Camera& camera, int height);

// log2 of the cone's footprint in uv units at the hit (lambda without the texture size term);
// -infinity when it cannot be computed (no uv, degenerate triangle), which means level 0.
float coneUvLod(const WorldGeometry& world, const SurfacePoint& p, const vec3& direction,
                float width);

// Curvature estimate at p for the spread update: for triangles, the largest change of the vertex
// normal per unit length along an edge (0 for flat shading); for analytic shapes, the same from
// finite differences of the exact normal.
float surfaceCurvature(const WorldGeometry& world, const SurfacePoint& p);

// The cone leaving p by reflection (spread + 2 k W) or refraction (unchanged), W its width at p.
RayCone reflectedCone(const WorldGeometry& world, const SurfacePoint& p, float width, float spread);

}  // namespace diptych
