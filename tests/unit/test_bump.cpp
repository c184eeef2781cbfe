// The lecture's bump mapping (shaders/common/bump.glsl, engine/shading/bump.h) against a closed
// form.
//
// A plane P(u, v) = (L u, L v, 0) displaced by k f_h(u, v) along n = +z, with
// f_h = A sin(2 pi u) cos(2 pi v), is the surface Q = (L u, L v, k f_h); its exact normal is
// normalize(-L k f_u, -L k f_v, L^2) with the analytic partial derivatives. The lecture's
// finite differences on a height texture (256^2 texels, bilinear, D = 1 / 256) must give it
// within 1e-3 rad at random points that are not within a tenth of a texel of a texel edge.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/shading/bump.h"
#include "tests/unit/bump_sinusoid.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using namespace testing::bump;

vec3 exactNormal(float u, float v) {
  const vec2 f = heightGradient(u, v);
  return glm::normalize(vec3(-kL * kK * f.x, -kL * kK * f.y, kL * kL));
}

Texture heightTexture() {
  Texture t;
  t.image = Image(kN, kN, 4, 1.f);
  // Texel (i, j) holds f_h at its centre ((i + 0.5) / n, (j + 0.5) / n); row j is v (row 0 top).
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i)
      t.image.at(i, j, 0) = height((float(i) + 0.5f) / kN, (float(j) + 0.5f) / kN);
  return t;
}

TEST(Bump, SinusoidHeightTextureGivesTheClosedFormNormalWithin1e3Rad) {
  const Texture tex = heightTexture();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> uniform(0.f, 1.f);
  double worst = 0;
  int tested = 0;
  while (tested < 2000) {
    const float u = uniform(rng), v = uniform(rng);
    // Distance to the nearest texel edge, in texels, for the point and its four neighbours
    // (they lie a whole texel away, so the same fractional position).
    const float fx = u * kN - std::floor(u * kN), fy = v * kN - std::floor(v * kN);
    if (std::min({fx, 1.f - fx, fy, 1.f - fy}) < 0.1f) continue;
    const vec3 n = bumpNormalFromTexture(tex, vec2(u, v), kK, 1.f / kN, vec3(kL, 0.f, 0.f),
                                         vec3(0.f, kL, 0.f), vec3(0.f, 0.f, 1.f));
    const double angle = std::acos(std::clamp(double(glm::dot(n, exactNormal(u, v))), -1.0, 1.0));
    worst = std::max(worst, angle);
    ++tested;
  }
  std::printf("[bump] worst angle to the closed form over %d points: %.3g rad\n", tested, worst);
  EXPECT_LT(worst, 1e-3);
  // The relief is not negligible: the normals tilt by up to atan(k A 2 pi / L) = 13 degrees.
  EXPECT_GT(std::acos(exactNormal(0.f, 0.f).z), 0.2);
}

TEST(Bump, SlopeAndNormalFollowTheLectureFormulas) {
  EXPECT_FLOAT_EQ(shading::bumpSlope(0.3f, 0.1f, 2.f, 0.05f), 2.f * 0.2f / 0.1f);
  EXPECT_EQ(shading::bumpSlope(0.3f, 0.1f, 2.f, 0.f), 0.f);  // no step, no slope
  // t'_u = (1,0,0) + 0.5 (0,0,1), t'_v = (0,1,0): n' = normalize(t'_u x t'_v) = (-0.5,0,1)/|.|
  const vec3 n = shading::bumpNormal(vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1), 0.5f, 0.f);
  EXPECT_NEAR(glm::distance(n, glm::normalize(vec3(-0.5f, 0.f, 1.f))), 0.f, 1e-6f);
  // uv running the other way (t_u x t_v = -n): n' stays on n's side.
  const vec3 flipped = shading::bumpNormal(vec3(1, 0, 0), vec3(0, -1, 0), vec3(0, 0, 1), 0.5f, 0.f);
  EXPECT_GT(flipped.z, 0.f);
  // Degenerate tangents: the unit n.
  EXPECT_EQ(shading::bumpNormal(vec3(0.f), vec3(0.f), vec3(0, 0, 2), 1.f, 1.f), vec3(0, 0, 1));
}

TEST(Bump, TriangleTangentsAreTheUvDerivatives) {
  const SurfaceTangents t = triangleTangents(vec3(0, 0, 0), vec3(2, 0, 0), vec3(0, 3, 0),
                                             vec2(0, 0), vec2(1, 0), vec2(0, 1));
  EXPECT_EQ(t.tu, vec3(2, 0, 0));
  EXPECT_EQ(t.tv, vec3(0, 3, 0));
  const SurfaceTangents none =
      triangleTangents(vec3(0), vec3(1, 0, 0), vec3(0, 1, 0), vec2(0), vec2(0), vec2(0));
  EXPECT_EQ(none.tu, vec3(0.f));
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
