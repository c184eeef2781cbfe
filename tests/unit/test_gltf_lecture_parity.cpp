// The glTF -> lecture mapping (shaders/common/gltf_lecture.glsl), one definition compiled as C++
// (engine/scene/gltf_pbr.h: the loaders and the CPU surface code) and as GLSL (the GL scene code),
// on random inputs with a share of extremes: metallic and roughness outside [0, 1] (clamped),
// roughness 0 (the exponent's clamp), black and HDR base colours, and IORs below 1 (down to 0):
// (n-1)/(n+1) is negative there, which GLSL's pow leaves undefined (llvmpipe folds pow(x, 2.0)
// into x * x, so only a GPU driver could show that; the file squares by a product).
// Norm, per output: |g - c| <= 1e-5 max(|c|, 1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>

#include "engine/scene/gltf_pbr.h"
#include "gl_test_context.h"
#include "parity_support.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kInStride = 8, kOutStride = 20;

struct Case {
  vec3 base{0.f};
  float metallic = 0.f, roughness = 0.f, transmission = 0.f, ior = 1.5f;

  void write(float* r) const {
    r[0] = base.x, r[1] = base.y, r[2] = base.z;
    r[3] = metallic, r[4] = roughness, r[5] = transmission, r[6] = ior;
  }
  std::array<float, kOutStride> evaluate() const {
    const LectureCoefficients k = gltfPbrToLecture(base, metallic, roughness, transmission, ior);
    const vec3 d = gltfDiffuseColor(base, metallic);
    return {k.color.x,
            k.color.y,
            k.color.z,
            k.kd,
            k.ks,
            k.exponent,
            k.specularColor.x,
            k.specularColor.y,
            k.specularColor.z,
            k.kps,
            k.mirrorColor.x,
            k.mirrorColor.y,
            k.mirrorColor.z,
            k.kt,
            k.transmitColor.x,
            k.transmitColor.y,
            k.transmitColor.z,
            d.x,
            d.y,
            d.z};
  }
};

TEST(GltfLectureParity, GlslAndCppAgreeIncludingIorsBelowOne) {
  gl::testing::osmesaContext();
  testing::RandomInputs random(20261130u, 0.2f);
  std::vector<Case> cases;
  int belowOne = 0;
  for (int i = 0; i < 4096; ++i) {
    Case c;
    const float hdr = random.pick({0.f, 4.f}, 1.f);
    c.base = hdr * vec3(random.uniform(0, 1), random.uniform(0, 1), random.uniform(0, 1));
    c.metallic = random.pick({0.f, 1.f, -0.5f, 1.5f}, random.uniform(0, 1));
    c.roughness = random.pick({0.f, 1.f, -1.f, 2.f}, random.uniform(0, 1));
    c.transmission = random.pick({0.f, 1.f}, random.uniform(0, 1));
    c.ior = random.chance(0.3f) ? random.pick({0.f, 1.f}, random.uniform(0.f, 1.f))
                                : random.pick({3.f, 1e6f}, random.uniform(1.f, 2.5f));
    belowOne += c.ior < 1.f;
    cases.push_back(c);
  }
  ASSERT_GT(belowOne, 500);
  const std::vector<float> gpu = testing::dispatchCases(
      cases, kInStride, kOutStride,
      std::filesystem::path(DIPTYCH_TESTS_DIR) / "unit/shaders/gltf_lecture_parity.comp");
  int failures = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto cpu = cases[i].evaluate();
    for (int k = 0; k < kOutStride; ++k) {
      const float g = gpu[i * kOutStride + std::size_t(k)];
      ASSERT_TRUE(std::isfinite(cpu[std::size_t(k)])) << "case " << i << " output " << k;
      if (!std::isfinite(g) ||
          std::abs(g - cpu[std::size_t(k)]) > 1e-5f * std::max(std::abs(cpu[std::size_t(k)]), 1.f))
        if (++failures <= 5)
          ADD_FAILURE() << "case " << i << " (ior " << cases[i].ior << ", metallic "
                        << cases[i].metallic << ", roughness " << cases[i].roughness << ") output "
                        << k << ": GL " << g << ", C++ " << cpu[std::size_t(k)];
    }
  }
  EXPECT_EQ(failures, 0);
}

// F0 = ((n-1)/(n+1))^2 is symmetric in n and 1/n and reaches 1 at n = 0; the default 1.5 gives
// 0.04, n = 1 (no interface) 0.
TEST(GltfLectureParity, DielectricF0FollowsTheIorBelowOneToo) {
  const vec3 white(1.f);
  EXPECT_NEAR(gltfPbrToLecture(white, 0.f, 0.5f, 0.f, 1.5f).ks, 0.04f, 1e-7f);
  EXPECT_EQ(gltfPbrToLecture(white, 0.f, 0.5f, 0.f, 0.f).ks, 1.f);
  EXPECT_EQ(gltfPbrToLecture(white, 0.f, 0.5f, 0.f, 0.5f).ks,
            gltfPbrToLecture(white, 0.f, 0.5f, 0.f, 2.f).ks);
  EXPECT_EQ(gltfPbrToLecture(white, 0.f, 0.5f, 0.f, 1.f).ks, 0.f);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
