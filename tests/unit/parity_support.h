#pragma once
// What the GLSL-vs-C++ parity tests share (test_shading_parity.cpp, test_pbr_parity.cpp): a
// random source of ordinary and extreme inputs, and one compute dispatch of the cases through a
// shader of tests/unit/shaders, whose outputs are read back for comparison with the C++ side.
#include <gtest/gtest.h>

#include <cstddef>
#include <initializer_list>
#include <random>
#include <vector>

#include "engine/core/math.h"
#include "engine/gl/debug.h"
#include "engine/gl/objects.h"
#include "engine/gl/shader.h"
#include "engine/shading/shading.h"

namespace diptych::testing {

// Uniform values with a share of extremes; grazing directions within 1e-3 rad of a plane.
class RandomInputs {
 public:
  // extremeShare: how often pick() returns one of its extremes instead of the usual value.
  RandomInputs(unsigned seed, float extremeShare) : rng_(seed), extremeShare_(extremeShare) {}

  float uniform(float a, float b) { return std::uniform_real_distribution<float>(a, b)(rng_); }
  bool chance(float p) { return uniform(0, 1) < p; }
  float pick(std::initializer_list<float> extremes, float usual) {
    if (!chance(extremeShare_)) return usual;
    return *(extremes.begin() + int(uniform(0, float(extremes.size()))) % extremes.size());
  }
  vec3 unit() {
    std::normal_distribution<float> g;
    vec3 x(g(rng_), g(rng_), g(rng_));
    return glm::length(x) > 0.f ? glm::normalize(x) : vec3(0.f, 1.f, 0.f);
  }
  // Nearly perpendicular to n: grazing by up to 1e-3 rad, on either side.
  vec3 grazing(vec3 n) {
    const vec3 un = shading::safeNormalize(n), t = shading::safeNormalize(glm::cross(un, unit()));
    if (glm::length(t) == 0.f || glm::length(un) == 0.f) return unit();
    return glm::normalize(t + uniform(-1e-3f, 1e-3f) * un);
  }

 private:
  std::mt19937 rng_;
  float extremeShare_;
};

// The cases, written `inStride` floats apart into buffer 0, run by `program` (one invocation per
// case, local size 64, uniform uCount) into buffer 1, `outStride` floats apart; returns buffer 1.
// Fails the calling test if GL reported an error.
template <typename Case>
std::vector<float> dispatchCases(const std::vector<Case>& cases, int inStride, int outStride,
                                 const gl::Program& program) {
  const int errorsBefore = gl::glDebugErrorCount();
  const int count = int(cases.size());
  std::vector<float> in(std::size_t(count) * inStride, 0.f);
  for (int i = 0; i < count; ++i) cases[std::size_t(i)].write(&in[std::size_t(i) * inStride]);
  const gl::Buffer inputs = gl::Buffer::create(in.size() * 4, in.data());
  const gl::Buffer outputs = gl::Buffer::create(std::size_t(count) * outStride * 4);
  program.use();
  program.set("uCount", count);
  inputs.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  outputs.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  gl::glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
  gl::glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(std::size_t(count) * outStride);
  outputs.download(0, gpu.size() * 4, gpu.data());
  EXPECT_EQ(gl::glDebugErrorCount(), errorsBefore);
  return gpu;
}

}  // namespace diptych::testing
