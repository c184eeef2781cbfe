#include "engine/core/image_check.h"

#include <cmath>

#include "engine/core/error.h"

namespace diptych {

NonFiniteValues findNonFinite(const Image& image) {
  NonFiniteValues out;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    if (std::isfinite(image.pixels[i])) continue;
    if (out.count++ == 0) {
      const std::size_t pixel = i / std::size_t(image.channels);
      out.x = int(pixel % std::size_t(image.width));
      out.y = int(pixel / std::size_t(image.width));
    }
  }
  return out;
}

void requireFinite(const Image& image, const std::string& name) {
  const NonFiniteValues bad = findNonFinite(image);
  if (bad.count)
    throw Error(name + ": " + std::to_string(bad.count) + " NaN/Inf values (first at pixel " +
                std::to_string(bad.x) + ", " + std::to_string(bad.y) +
                "); refusing to write any output");
}

}  // namespace diptych
