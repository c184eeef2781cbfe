#include "passes/raster/shadow_map_settings.h"

#include <array>
#include <utility>
#include <vector>

#include "engine/core/error.h"

namespace diptych::shadowmap {

namespace {

constexpr std::array<std::pair<const char*, Bias>, 6> kBiases{
    {{"none", Bias::None},
     {"constant", Bias::Constant},
     {"slope", Bias::Slope},
     {"normal_offset", Bias::NormalOffset},
     {"receiver_plane", Bias::ReceiverPlane},
     {"adaptive", Bias::Adaptive}}};
constexpr std::array<std::pair<const char*, Filter>, 4> kFilters{{{"none", Filter::None},
                                                                  {"pcf", Filter::Pcf},
                                                                  {"poisson", Filter::Poisson},
                                                                  {"pcss", Filter::Pcss}}};
constexpr std::array<std::pair<const char*, Update>, 2> kUpdates{
    {{"static", Update::Static}, {"every_frame", Update::EveryFrame}}};

template <class Enum, std::size_t N>
std::vector<std::string> namesOf(const std::array<std::pair<const char*, Enum>, N>& table) {
  std::vector<std::string> out;
  for (const auto& [name, e] : table) out.push_back(name);
  return out;
}

// The schema has checked the value against namesOf(table).
template <class Enum, std::size_t N>
Enum parseEnum(const PassParams& params, const std::string& key,
               const std::array<std::pair<const char*, Enum>, N>& table) {
  const std::string value = params.string(key);
  for (const auto& [name, e] : table)
    if (value == name) return e;
  params.fail(key, "unhandled " + key + " mode '" + value + "'");
}

template <class Enum, std::size_t N>
std::string nameOf(Enum e, const std::array<std::pair<const char*, Enum>, N>& table) {
  for (const auto& [name, v] : table)
    if (v == e) return name;
  return "?";
}

}  // namespace

ParamSchema schema() {
  using P = ParamSpec;
  return {
      P::integer("resolution", 2048, 16, 16384, "texels per side of every map (cube faces too)"),
      P::choice("bias", "slope", namesOf(kBiases), "depth-bias technique"),
      P::number("constant_bias", 0.01, 0.0, 1e30, "world units along the light ray (constant)"),
      P::number("factor", 2.0, -1e4, 1e4, "glPolygonOffset factor (slope)"),
      P::number("units", 4.0, -1e9, 1e9, "glPolygonOffset units (slope)"),
      P::number("normal_scale", 1.0, 0.0, 1e4, "texel footprints along the normal (normal_offset)"),
      P::number("plane_epsilon", 1e-5, 0.0, 1.0, "relative depth margin (receiver_plane)"),
      P::number("adaptive_epsilon", 1e-4, 0.0, 1.0,
                "times the scene diagonal, world units (adaptive)"),
      P::choice("filter", "none", namesOf(kFilters), "lookup filter"),
      P::integer("kernel", 3, 1, 15, "PCF kernel side, odd"),
      P::integer("taps", 16, 1, 64, "Poisson and PCSS taps"),
      P::number("radius", 2.0, 0.0, 256.0, "Poisson radius, texels"),
      P::number("light_fraction", 0.005, 0.0, 1.0,
                "PCSS: point/spot light diameter, times the scene diagonal (area lights: their "
                "own)"),
      P::number("light_angle", 0.0093, 0.0, 1.5,
                "PCSS: directional light angular diameter, radians (the sun's)"),
      P::number("max_radius", 32.0, 1.0, 256.0,
                "PCSS: cap of the blocker search and penumbra radius, texels"),
      P::choice("update", "static", namesOf(kUpdates),
                "static: maps rendered once per world, again only when the lights, casters or map "
                "settings change (a one-time cost); every_frame: rendered in every frame"),
  };
}

Settings readSettings(const PassParams& p) {
  Settings s;
  s.resolution = p.integer("resolution");
  s.bias = parseEnum(p, "bias", kBiases);
  s.constantBias = float(p.number("constant_bias"));
  s.slopeFactor = float(p.number("factor"));
  s.slopeUnits = float(p.number("units"));
  s.normalScale = float(p.number("normal_scale"));
  s.planeEpsilon = float(p.number("plane_epsilon"));
  s.adaptiveEpsilon = float(p.number("adaptive_epsilon"));
  s.filter = parseEnum(p, "filter", kFilters);
  s.kernel = p.integer("kernel");
  s.taps = p.integer("taps");
  s.radius = float(p.number("radius"));
  s.lightFraction = float(p.number("light_fraction"));
  s.lightAngle = float(p.number("light_angle"));
  s.maxRadius = float(p.number("max_radius"));
  s.update = parseEnum(p, "update", kUpdates);
  if (s.kernel % 2 == 0)
    p.fail("kernel", "kernel must be odd (got " + std::to_string(s.kernel) +
                         "): an N x N PCF kernel is centred on the receiver's texel");
  return s;
}

std::string biasName(Bias bias) {
  return nameOf(bias, kBiases);
}
std::string filterName(Filter filter) {
  return nameOf(filter, kFilters);
}

}  // namespace diptych::shadowmap
