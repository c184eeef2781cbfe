#pragma once
// A last check before an image leaves the program: no NaN or Inf may be written without failing
// (a PNG would clamp it to black silently, an EXR would store it). docs/robustness.md.
#include <cstddef>
#include <string>

#include "engine/core/image.h"

namespace diptych {

struct NonFiniteValues {
  std::size_t count = 0;  // NaN or Inf values (channels counted separately)
  int x = 0, y = 0;       // the first pixel holding one
};

NonFiniteValues findNonFinite(const Image& image);

// Throws Error("NAME: N NaN/Inf values (first at pixel x, y)...") when the image has any.
void requireFinite(const Image& image, const std::string& name);

}  // namespace diptych
