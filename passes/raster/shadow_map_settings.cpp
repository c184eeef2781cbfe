#include "passes/raster/shadow_map_settings.h"

#include <array>
#include <utility>

#include "engine/core/error.h"

namespace diptych::shadowmap {

namespace {

[[noreturn]] void fail(const PassParams& params, const std::string& key,
                       const std::string& message) {
  params.fail(key, message);
}

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

template <class Enum, std::size_t N>
Enum parseEnum(const PassParams& params, const std::string& key, const std::string& fallback,
               const std::array<std::pair<const char*, Enum>, N>& table) {
  const std::string value = params.string(key, fallback);
  std::string known;
  for (const auto& [name, e] : table) {
    if (value == name) return e;
    known += (known.empty() ? "" : ", ") + std::string(name);
  }
  fail(params, key, "unknown " + key + " mode '" + value + "' (known: " + known + ")");
}

template <class Enum, std::size_t N>
std::string nameOf(Enum e, const std::array<std::pair<const char*, Enum>, N>& table) {
  for (const auto& [name, v] : table)
    if (v == e) return name;
  return "?";
}

}  // namespace

Settings readSettings(const PassParams& p) {
  Settings s;
  s.resolution = p.integer("resolution", s.resolution, 16, 16384);
  s.bias = parseEnum(p, "bias", biasName(s.bias), kBiases);
  s.constantBias = float(p.number("constant_bias", s.constantBias, 0.0, 1e30));
  s.slopeFactor = float(p.number("factor", s.slopeFactor, -1e4, 1e4));
  s.slopeUnits = float(p.number("units", s.slopeUnits, -1e9, 1e9));
  s.normalScale = float(p.number("normal_scale", s.normalScale, 0.0, 1e4));
  s.planeEpsilon = float(p.number("plane_epsilon", s.planeEpsilon, 0.0, 1.0));
  s.adaptiveEpsilon = float(p.number("adaptive_epsilon", s.adaptiveEpsilon, 0.0, 1.0));
  s.filter = parseEnum(p, "filter", filterName(s.filter), kFilters);
  s.kernel = p.integer("kernel", s.kernel, 1, 15);
  s.taps = p.integer("taps", s.taps, 1, 64);
  s.radius = float(p.number("radius", s.radius, 0.0, 256.0));
  s.lightSize = float(p.number("light_size", s.lightSize, 0.0, 1e30));
  s.lightAngle = float(p.number("light_angle", s.lightAngle, 0.0, 1.5));
  s.maxRadius = float(p.number("max_radius", s.maxRadius, 1.0, 256.0));
  if (s.kernel % 2 == 0)
    fail(p, "kernel",
         "kernel must be odd (got " + std::to_string(s.kernel) +
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
