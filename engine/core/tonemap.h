#pragma once
// Display mapping for 8-bit outputs (PNG/JPEG); EXR/HDR stay linear. docs/materials.md,
// "Exposure and tone mapping".
#include <optional>
#include <string>

#include "engine/core/image.h"

namespace diptych {

// Rec. 709 luminance of a linear RGB value.
float luminance709(const vec3& rgb);

// Reinhard et al. 2002 ("Photographic Tone Reproduction for Digital Images", eq. 1-2): the
// log-average luminance Lw = exp(mean(log(delta + L))) over the finite pixels, delta = 1e-4,
// mapped to middle grey a = 0.18: returns log2(a / Lw), the exposure in EV. 0 for an image with
// no finite non-black pixel (nothing to expose for).
float autoExposure(const Image& image);

// One linear RGB value to display-linear [0,1] (before sRGB encoding): scale by 2^exposure,
// then the operator, then clamp. Non-finite values give 0.
vec3 toneMapPixel(const vec3& linear, const ToneMap& tone);

// "clamp", "reinhard", "aces" -> the operator; nullopt for anything else.
std::optional<ToneOperator> parseToneOperator(const std::string& name);

}  // namespace diptych
