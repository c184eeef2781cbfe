#pragma once
// The closed-form bump of the bump-mapping tests (test_bump.cpp, test_bump_material.cpp): a plane
// of side L displaced by k f_h(u, v) along its normal, f_h = A sin(2 pi u) cos(2 pi v), sampled
// into n x n height textures.
#include <cmath>

#include "engine/core/math.h"

namespace diptych::testing::bump {

constexpr float kPi = 3.14159265358979f;
constexpr float kA = 0.05f, kL = 2.f, kK = 1.5f;
constexpr int kN = 256;

inline float height(float u, float v) {
  return kA * std::sin(2.f * kPi * u) * std::cos(2.f * kPi * v);
}

// (f_u, f_v): the analytic partial derivatives of f_h.
inline vec2 heightGradient(float u, float v) {
  return {kA * 2.f * kPi * std::cos(2.f * kPi * u) * std::cos(2.f * kPi * v),
          -kA * 2.f * kPi * std::sin(2.f * kPi * u) * std::sin(2.f * kPi * v)};
}

}  // namespace diptych::testing::bump
