// The lecture's bump mapping as a JSON material key ("bump", docs/materials.md), through the
// loader and the shading point every ray-traced pass uses (makeSurfacePoint).
//
// A plane of size L x L (P = ((u - 1/2) L, 0, (v - 1/2) L), n = +y) displaced by k f_h(u, v)
// along n, f_h = A sin(2 pi u) cos(2 pi v), is Q = P + k f_h n; its exact normal is
// Q_u x Q_v = (k f_u L, -L^2, L k f_v) turned to n's side: normalize(-k f_u L, L^2, -k f_v L).
// Rays straight down at random points must find a shading normal within 1e-3 rad of it, for
// the procedural sinusoid and for the same height stored in a 256^2 EXR (points at least a tenth
// of a texel from a texel edge, where bilinear interpolation of the texture is smooth).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "engine/core/error.h"
#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/load.h"
#include "tests/support/test_paths.h"
#include "tests/unit/bump_sinusoid.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using namespace testing::bump;

vec3 exactNormal(float u, float v) {
  const vec2 f = heightGradient(u, v);
  return glm::normalize(vec3(-kK * f.x * kL, kL * kL, -kK * f.y * kL));
}

std::filesystem::path scratch() {
  const auto dir = ::diptych::testing::scratchDir("diptych_bump_material");
  std::filesystem::create_directories(dir);
  return dir;
}

Scene planeWithBump(const std::string& bump) {
  const auto file = scratch() / "bump.json";
  std::ofstream(file) << R"({"materials": {"bumpy": {"color": [1, 1, 1], "bump": )" << bump
                      << R"(}}, "objects": [{"type": "plane", "size": [)" << kL << ", " << kL
                      << R"(], "material": "bumpy"}]})";
  return loadScene(file);
}

// Worst angle (rad) to the closed form over `count` random points; `edgeMargin` > 0 keeps the
// points that far (in texels) from the height texture's texel edges.
double worstAngle(const Scene& scene, int count, float edgeMargin) {
  RenderWorld world(scene);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> uniform(0.02f, 0.98f);
  double worst = 0;
  for (int tested = 0; tested < count;) {
    const float u = uniform(rng), v = uniform(rng);
    const float fx = u * kN - std::floor(u * kN), fy = v * kN - std::floor(v * kN);
    if (edgeMargin > 0.f && std::min({fx, 1.f - fx, fy, 1.f - fy}) < edgeMargin) continue;
    const Ray ray{vec3((u - 0.5f) * kL, 1.f, (v - 0.5f) * kL), vec3(0.f, -1.f, 0.f)};
    const auto hit = world.rtScene().intersect(ray, 0.f, std::numeric_limits<float>::infinity());
    EXPECT_TRUE(hit.has_value());
    if (!hit) return 1e9;
    const SurfacePoint p = makeSurfacePoint(
        scene, world.geometry(), {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
        ray.direction);
    // atan2(|a x b|, a.b) in double: acos of a float dot cannot resolve angles below ~3e-4.
    const glm::dvec3 a(glm::normalize(p.shadingNormal)), b(exactNormal(p.uv.x, p.uv.y));
    worst = std::max(worst, std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
    ++tested;
  }
  return worst;
}

TEST(BumpMaterial, ProceduralSinusoidGivesTheClosedFormNormalWithin1e3Rad) {
  const Scene scene = planeWithBump(R"({"amplitude": 0.05, "frequency": [1, 1], "k": 1.5,
                                        "delta": 0.0009765625})");
  const double worst = worstAngle(scene, 2000, 0.f);
  std::printf("[ measured ] procedural bump: worst angle %.3g rad over 2000 points\n", worst);
  EXPECT_LT(worst, 1e-3);
  // And the relief is really there: the flat normal is far from the bumped one somewhere.
  EXPECT_GT(std::acos(double(exactNormal(0.f, 0.f).y)), 0.2);
}

TEST(BumpMaterial, HeightTextureGivesTheClosedFormNormalWithin1e3Rad) {
  Image img(kN, kN, 4, 1.f);
  for (int j = 0; j < kN; ++j)
    for (int i = 0; i < kN; ++i)
      img.at(i, j, 0) = height((float(i) + 0.5f) / kN, (float(j) + 0.5f) / kN);
  writeImage(scratch() / "height.exr", img);
  const Scene scene = planeWithBump(R"({"texture": "height.exr", "k": 1.5, "delta": 0.00390625})");
  const double worst = worstAngle(scene, 2000, 0.1f);
  std::printf("[ measured ] texture bump: worst angle %.3g rad over 2000 points\n", worst);
  EXPECT_LT(worst, 1e-3);
}

TEST(BumpMaterial, BadBumpKeysNameTheirPlace) {
  for (const char* bad :
       {R"({"texture": "missing.exr"})", R"({"amplitude": 1, "delta": 0})",
        R"({"amplitude": 1, "shape": "saw"})", R"({"texture": "height.exr", "amplitude": 1})"}) {
    try {
      planeWithBump(bad);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("materials.bumpy.bump"), std::string::npos) << e.what();
    }
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
