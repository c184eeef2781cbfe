#pragma once
// Parameters of the `shadow_map` pass (docs/shadow-maps.md), parsed once in setup.
#include <string>

#include "engine/graph/params.h"

namespace diptych::shadowmap {

// Values match the BIAS_* / FILTER_* constants of shaders/shadow_lookup.frag.
enum class Bias { None = 0, Constant, Slope, NormalOffset, ReceiverPlane, Adaptive };
enum class Filter { None = 0, Pcf, Poisson, Pcss };

struct Settings {
  int resolution = 2048;          // texels per side of every map (cube faces included)
  Bias bias = Bias::Slope;        // depth-bias technique
  float constantBias = 0.01f;     // world units along the light ray (Bias::Constant)
  float slopeFactor = 2.f;        // glPolygonOffset factor (Bias::Slope)
  float slopeUnits = 4.f;         // glPolygonOffset units (Bias::Slope)
  float normalScale = 1.f;        // texel footprints along the normal (Bias::NormalOffset)
  float planeEpsilon = 1e-5f;     // relative depth margin (Bias::ReceiverPlane)
  float adaptiveEpsilon = 1e-4f;  // x scene diagonal, world units (Bias::Adaptive)
  Filter filter = Filter::None;
  int kernel = 3;              // PCF kernel side, odd
  int taps = 16;               // Poisson / PCSS taps
  float radius = 2.f;          // Poisson radius, texels
  float lightSize = 0.1f;      // PCSS: point/spot light world diameter (area lights: their own)
  float lightAngle = 0.0093f;  // PCSS: directional light angular diameter, radians (the sun's)
  float maxRadius = 32.f;      // PCSS: cap of the blocker search and penumbra radius, texels
};

// Reads every parameter unconditionally (so any valid key is accepted whatever the mode) and
// validates values and combinations, each error an InputError naming the recipe place.
Settings readSettings(const PassParams& params);

std::string biasName(Bias bias);
std::string filterName(Filter filter);

}  // namespace diptych::shadowmap
