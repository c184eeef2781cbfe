#pragma once
// The path tracer's scattering for materials shaded by the glTF model (shaders/common/pbr.glsl):
// the same BRDF the hybrid and Whitted frames shade with, sampled so that every bounce is
// unbiased for it.
#include "engine/core/math.h"
#include "engine/shading/shading.h"

namespace diptych {

struct PbrScatter {
  vec3 direction{0.f};
  vec3 weight{0.f};    // f cos / pdf, divided by the lobe's selection probability
  bool delta = false;  // the transmission lobe (a delta, as in the hybrid's signal)
  bool valid = false;  // false: the path ends (the sample fell below the surface, or no lobe)
};

// One sample of the glTF model at a point with unit shading normal n, unit v toward the viewer,
// and eta = n_i / n_t for the refraction. The delta transmission lobe (weight
// pbrSecondaryWeights().transmission) is chosen with probability proportional to its luminance
// against an estimate of the reflection's albedo; otherwise the reflection (diffuse + GGX) is
// sampled by a one-sample mixture of cosine and GGX-NDF sampling (Walter et al. 2007, eq. 35-36:
// pdf_l = D(n.h) n.h / (4 v.h)), the weight divided by the mixture pdf (balance heuristic), so
// that neither strategy's variance dominates at roughness 0 or 1.
PbrScatter samplePbr(const shading::ShadingMaterial& m, const vec3& n, const vec3& v, float eta,
                     float uLobe, vec2 u);

}  // namespace diptych
