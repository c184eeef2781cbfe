#pragma once
// Parameters of the `shadow_map` pass (docs/shadow-maps.md), parsed once in setup.
#include <string>

#include "engine/graph/params.h"

namespace diptych::shadowmap {

// Values match the BIAS_* / FILTER_* constants of shaders/shadow_map_lookup.frag.
enum class Bias { None = 0, Constant, Slope, NormalOffset, ReceiverPlane, Adaptive };
enum class Filter { None = 0, Pcf, Poisson, Pcss };
// When the maps are rendered: Static = once per world and again only when their key changes
// (ShadowMapGl::mapsFor); EveryFrame = every frame, as before caching.
enum class Update { Static = 0, EveryFrame };

// The values of schema()'s parameters (their defaults and docs are there).
struct Settings {
  int resolution = 0;
  Bias bias = Bias::None;
  float constantBias = 0, slopeFactor = 0, slopeUnits = 0, normalScale = 0, planeEpsilon = 0,
        adaptiveEpsilon = 0;
  Filter filter = Filter::None;
  int kernel = 0, taps = 0;
  float radius = 0, lightFraction = 0, lightAngle = 0, maxRadius = 0;
  Update update = Update::Static;
};

// The shadow_map pass's parameters: names, ranges, defaults, doc lines.
ParamSchema schema();
// Reads every parameter unconditionally (so any valid key is accepted whatever the mode) and
// validates combinations, each error an InputError naming the recipe place.
Settings readSettings(const PassParams& params);

std::string biasName(Bias bias);
std::string filterName(Filter filter);

}  // namespace diptych::shadowmap
