#include "engine/core/tonemap.h"

#include <algorithm>
#include <cmath>

namespace diptych {

float luminance709(const vec3& c) {
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}

float autoExposure(const Image& image) {
  if (image.channels < 3) return 0.f;
  constexpr double kDelta = 1e-4;  // keeps log finite on black pixels (Reinhard 2002, eq. 1)
  constexpr double kMiddleGrey = 0.18;
  double sumLog = 0.0;
  std::size_t count = 0, lit = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const vec3 c(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
      const float l = luminance709(c);
      if (!std::isfinite(l)) continue;
      const double clamped = std::max(0.0, double(l));
      sumLog += std::log(kDelta + clamped);
      ++count;
      lit += clamped > 0.0;
    }
  if (count == 0 || lit == 0) return 0.f;
  const double logAverage = std::exp(sumLog / double(count));
  return float(std::log2(kMiddleGrey / logAverage));
}

vec3 toneMapPixel(const vec3& linear, const ToneMap& tone) {
  vec3 c = linear * std::exp2(tone.exposure);
  for (int i = 0; i < 3; ++i) c[i] = std::isfinite(c[i]) ? std::max(c[i], 0.f) : 0.f;
  switch (tone.op) {
    case ToneOperator::Clamp:
      break;
    case ToneOperator::Reinhard: {
      // Eq. 3 of Reinhard et al. 2002, Ld = L / (1 + L), on luminance; the colour is scaled by
      // Ld / L so that hue and saturation are kept.
      const float l = luminance709(c);
      if (l > 0.f) c *= (1.f / (1.f + l));
      break;
    }
    case ToneOperator::AcesFit:
      // K. Narkowicz, "ACES Filmic Tone Mapping Curve" (2015): x (a x + b) / (x (c x + d) + e)
      // per channel, with his 0.6 pre-scale so that exposure 0 keeps mid-grey near mid-grey.
      for (int i = 0; i < 3; ++i) {
        const float x = 0.6f * c[i];
        c[i] = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
      }
      break;
  }
  return glm::clamp(c, vec3(0.f), vec3(1.f));
}

std::optional<ToneOperator> parseToneOperator(const std::string& name) {
  if (name == "clamp") return ToneOperator::Clamp;
  if (name == "reinhard") return ToneOperator::Reinhard;
  if (name == "aces") return ToneOperator::AcesFit;
  return std::nullopt;
}

}  // namespace diptych
