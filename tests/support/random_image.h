#pragma once
// An image of uniform random values in [0, 1), reproducible from its seed (std::mt19937).
#include <random>

#include "engine/core/image.h"

namespace diptych::testing {

inline Image randomImage(int w, int h, int channels, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  Image image(w, h, channels);
  for (float& v : image.pixels) v = unit(rng);
  return image;
}

}  // namespace diptych::testing
