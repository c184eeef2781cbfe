#pragma once
// Points on area lights for stratified shadow rays (the distributed-ray-tracing estimate of
// the lecture's visibility V_i in [0,1]: the fraction of the light's samples a point sees).
#include <cstdint>

#include "engine/scene/scene.h"

namespace diptych {

// The number of strata actually used for a request of n samples: k x k with
// k = max(1, round(sqrt(n))), so that the strata tile the unit square.
int stratifiedSampleCount(int requested);

// Sample `index` of a k x k jittered grid in [0,1)^2 (k^2 = stratifiedSampleCount), jittered
// by a hash of (seed, index) so that a pixel's pattern is reproducible frame after frame.
vec2 stratifiedSample(int index, int count, std::uint32_t seed);

// A point on the light for the unit-square sample s, as seen from `receiver`:
//  quad: position + (s.x - 1/2) edgeU + (s.y - 1/2) edgeV;
//  disc: Shirley & Chiu's concentric map ("A Low Distortion Map Between Disk and Square",
//        JGT 1997) onto the disc of `radius` perpendicular to `direction`;
//  sphere: uniform on the hemisphere of the sphere facing the receiver (cos theta = s.x,
//          phi = 2 pi s.y), which is where every visible point of the sphere lies;
//  point/spot: the light's position. Directional lights have no position: not to be called.
vec3 areaLightPoint(const Light& light, vec2 s, const vec3& receiver);

bool isAreaLight(const Light& light);

// Unit tangents t, b with (t, b, n) orthonormal, for a unit n (Duff et al., "Building an
// Orthonormal Basis, Revisited", JCGT 6(1), 2017: branchless and continuous except at n.z = 0-).
void orthonormalBasis(const vec3& n, vec3& t, vec3& b);

// The unit direction at polar angle acos(cosT) from the unit `axis` and azimuth phi about it
// (in orthonormalBasis's frame): what every sampler drawing (cos theta, phi) builds.
vec3 directionAbout(const vec3& axis, float cosT, float phi);

// Cosine-weighted hemisphere about the unit n (Malley's method: Shirley & Chiu's concentric disc
// lifted onto the hemisphere), pdf cos(theta) / pi.
vec3 sampleCosine(const vec3& n, vec2 u);

// A hash that decorrelates per-pixel sample patterns (Jarzynski & Olano, "Hash Functions for
// GPU Rendering", JCGT 2020: PCG-style 32-bit permutation).
std::uint32_t pcgHash(std::uint32_t v);

// The 24 high bits of a hash as a float in [0, 1): exactly representable, never 1.
inline float unitFloat(std::uint32_t h) {
  return float(h >> 8) * (1.f / 16777216.f);
}

}  // namespace diptych
