// GLSL vs C++ parity of the glTF model (shaders/common/pbr.glsl), with and without a
// KHR_materials_iridescence film: compiled as GLSL (a compute
// shader on OSMesa/llvmpipe) and as C++ (engine/shading/shading.h), evaluated through the shared
// dispatch points directResponse and secondaryWeights on random inputs, a share of them extreme:
// roughness exactly 0 and 1, metallic 0 and 1, grazing v and l (within 1e-3 rad of the tangent
// plane, either side), l at the mirror direction of v (the GGX peak), zero and huge vectors.
//
// Norm, per output vector g (GPU) and c (CPU): |g - c|_inf <= bound * max(|c|_inf, 1e-3).
// bound = 2e-5, plus the GGX peak's conditioning: D = a^2 / (pi d^2) with
// d = (n.h)^2 (a^2 - 1) + 1, and a few-ULP difference in n.h (GLSL allows 2.5 ULP per operation)
// moves d by ~4 eps, so D's relative error is ~8 eps / d; at roughness 0 (a = 1e-3, d >= 1e-6)
// that is up to ~1. The bound adds 64 eps / d for the direct term, and 16 eps / n.l + 16 eps / n.v
// for grazing directions (see the loop).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <iostream>
#include <random>

#include "engine/gl/debug.h"
#include "engine/gl/shader.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "parity_support.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using namespace shading;
constexpr int kInStride = 32, kOutStride = 16;

struct Case {
  ShadingMaterial m{};
  vec3 n{0.f}, v{0.f}, l{0.f};
  float filmCos = 0.f;  // cos(theta1) of the pbrFilmFresnel output

  void write(float* r) const {
    auto put3 = [&](int i, vec3 x) { r[i] = x.x, r[i + 1] = x.y, r[i + 2] = x.z; };
    r[0] = m.ior;
    put3(1, m.baseColor);
    r[4] = m.metallic, r[5] = m.roughness, r[6] = m.transmission, r[7] = m.specularWeight;
    put3(8, m.specularTint);
    put3(11, n);
    put3(14, v);
    put3(17, l);
    r[20] = m.iridescence, r[21] = m.iridescenceIor, r[22] = m.iridescenceThickness;
    r[23] = filmCos;
  }

  std::array<float, kOutStride> evaluate() const {
    const vec3 d = directResponse(m, n, v, l);
    const SecondaryWeights w = secondaryWeights(m, n, v);
    const vec2 ab = pbrEnvironmentBrdf(dot(safeNormalize(n), safeNormalize(v)), m.roughness);
    const vec3 f = pbrFilmFresnel(m.iridescenceIor, m.baseColor, m.iridescenceThickness, filmCos);
    return {d.x,
            d.y,
            d.z,
            w.reflection.x,
            w.reflection.y,
            w.reflection.z,
            w.transmission.x,
            w.transmission.y,
            w.transmission.z,
            ab.x,
            ab.y,
            0.f,
            f.x,
            f.y,
            f.z,
            0.f};
  }

  // The GGX denominator d at this case's half vector (see the header).
  float ggxDenominator() const {
    const vec3 N = safeNormalize(n), H = safeNormalize(safeNormalize(l) + safeNormalize(v));
    const float a = pbrAlpha(m.roughness), c = saturate01(dot(N, H));
    return c * c * (a * a - 1.f) + 1.f;
  }
};

class CaseGenerator : testing::RandomInputs {
 public:
  // film: KHR_materials_iridescence on every case (strength and thickness 0 among the extremes);
  // without it the film inputs stay 0 and the random sequence is the film-free one.
  CaseGenerator(unsigned seed, bool film) : RandomInputs(seed, 0.15f), film_(film) {}

  Case next() {
    Case c;
    ShadingMaterial& m = c.m;
    m.model = SHADING_MODEL_GLTF;
    m.alpha = 1.f;
    m.ior = pick({1.f, 3.f}, uniform(1.f, 2.5f));
    m.baseColor = vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1));
    m.metallic = pick({0.f, 1.f}, uniform(0, 1));
    m.roughness = chance(0.3f) ? (chance(0.5f) ? 0.f : 1.f) : uniform(0, 1);
    m.transmission = pick({0.f, 1.f}, uniform(0, 1));
    m.specularWeight = pick({0.f, 1.f}, uniform(0, 1));
    m.specularTint = chance(0.7f) ? vec3(1.f) : vec3(uniform(0, 2), uniform(0, 2), uniform(0, 2));
    c.n = vector();
    c.v = chance(0.2f) ? grazing(c.n) : vector();
    if (chance(0.2f)) {  // the mirror direction of v: the GGX peak
      const vec3 un = safeNormalize(c.n), uv = safeNormalize(c.v);
      c.l = 2.f * dot(un, uv) * un - uv;
    } else {
      c.l = chance(0.2f) ? grazing(c.n) : vector();
    }
    if (film_) {
      m.iridescence = pick({0.f, 1.f}, uniform(0, 1));
      m.iridescenceIor = pick({1.f, 2.5f}, uniform(1.f, 2.5f));
      m.iridescenceThickness = pick({0.f, 1200.f}, uniform(0.f, 1200.f));
      c.filmCos = pick({0.f, 1.f}, uniform(0, 1));
    }
    return c;
  }

 private:
  bool film_;
  vec3 vector() {
    return unit() * (chance(0.05f) ? (chance(0.5f) ? 0.f : 1e30f) : uniform(0.1f, 3.f));
  }
};

struct Group {
  const char* name;
  int first, count;
};
constexpr Group kGroups[] = {{"directResponse (pi f n.l)", 0, 3},
                             {"secondaryWeights.reflection", 3, 3},
                             {"secondaryWeights.transmission", 6, 3},
                             {"pbrEnvironmentBrdf", 9, 2},
                             {"pbrFilmFresnel", 12, 3}};

// The film's phases: cos(x) at x up to the largest Fourier frequency (2.2399e6, doubled for the
// second order) times 2 pi opd 1e-9, opd = 2 n d cos(theta2) <= 2 n d; a few-ULP difference in x
// is ~4 eps x absolute in cos. Added to every group the film reaches (all but the table's).
double filmPhaseBound(const ShadingMaterial& m) {
  if (!(m.iridescenceThickness > 0.f)) return 0.0;
  const double x = 2.0 * 2.2399e6 * 2.0 * 3.14159265 * 2.0 * std::max(m.iridescenceIor, 1.f) *
                   m.iridescenceThickness * 1e-9;
  return 4.0 * FLT_EPSILON * x;
}

void checkParity(bool film, unsigned seed) {
  gl::testing::osmesaContext();
  constexpr int kCases = 20000;
  CaseGenerator gen(seed, film);
  std::vector<Case> cases;
  for (int i = 0; i < kCases; ++i) cases.push_back(gen.next());
  const std::vector<float> gpu = testing::dispatchCases(
      cases, kInStride, kOutStride,
      std::filesystem::path(DIPTYCH_TESTS_DIR) / "unit/shaders/pbr_parity.comp");

  std::map<std::string, double> worst, worstConditioned;
  std::map<std::string, int> failures;
  int roughness0 = 0, roughness1 = 0, peaks = 0;
  for (int i = 0; i < kCases; ++i) {
    const Case& c = cases[i];
    roughness0 += c.m.roughness == 0.f;
    roughness1 += c.m.roughness == 1.f;
    const auto cpu = c.evaluate();
    const float* g = &gpu[std::size_t(i) * kOutStride];
    const float d = c.ggxDenominator();
    peaks += d < 1e-3f;
    for (const Group& grp : kGroups) {
      float diff = 0.f, scale = 1e-3f;
      for (int k = grp.first; k < grp.first + grp.count; ++k) {
        ASSERT_TRUE(std::isfinite(g[k])) << grp.name << " case " << i;
        ASSERT_TRUE(std::isfinite(cpu[k])) << grp.name << " case " << i;
        // Radiance factors are never negative; the fit's B term is (-0.0024 at roughness 1).
        if (grp.first < 9) {
          ASSERT_GE(cpu[k], 0.f) << grp.name << " case " << i;
        }
        diff = std::max(diff, std::abs(g[k] - cpu[k]));
        scale = std::max(scale, std::abs(cpu[k]));
      }
      const double rel = diff / scale;
      // Grazing: n.l and n.v are dot products of nearly perpendicular vectors, so a few-ULP
      // difference is relative to their size (16 eps / n.l, 16 eps / n.v, n.v floored at 1e-4
      // as the model floors it); 1 - F(n.v) cancels likewise in the transmission weight.
      const vec3 N = safeNormalize(c.n);
      const float nl = std::max(dot(N, safeNormalize(c.l)), 1e-9f);  // not floored by the model
      const float nv = std::max(dot(N, safeNormalize(c.v)), 1e-4f);
      double bound = 2e-5;
      if (grp.first == 0)
        bound += 64.0 * FLT_EPSILON / std::max(d, 1e-12f) + 16.0 * FLT_EPSILON * (1 / nl + 1 / nv);
      if (grp.first == 6) bound += 16.0 * FLT_EPSILON / nv;
      if (grp.first != 9) bound += filmPhaseBound(c.m);
      worst[grp.name] = std::max(worst[grp.name], rel);
      if (d > 0.1f && nl > 0.1f && nv > 0.1f)  // well conditioned: no peak, nothing grazing
        worstConditioned[grp.name] = std::max(worstConditioned[grp.name], rel);
      if (rel > bound && ++failures[grp.name] <= 3)
        ADD_FAILURE() << grp.name << " case " << i << ": relative difference " << rel << " bound "
                      << bound << " (roughness " << c.m.roughness << ", d " << d << ", n.l "
                      << dot(N, safeNormalize(c.l)) << ", n.v " << dot(N, safeNormalize(c.v))
                      << "; film " << c.m.iridescence << ", IOR " << c.m.iridescenceIor << ", "
                      << c.m.iridescenceThickness << " nm, cos " << c.filmCos << ", base "
                      << c.m.baseColor.x << " " << c.m.baseColor.y << " " << c.m.baseColor.z
                      << "; GPU " << g[grp.first] << " CPU " << cpu[grp.first] << ")";
    }
  }
  std::cout << "[ measured ] cases: " << kCases << ", roughness 0: " << roughness0
            << ", roughness 1: " << roughness1 << ", at the GGX peak (d < 1e-3): " << peaks << "\n";
  for (const Group& grp : kGroups)
    std::cout << "[ measured ] " << grp.name << ": worst relative difference " << worst[grp.name]
              << " (" << worstConditioned[grp.name]
              << " where d, n.l, n.v > 0.1), over the bound: " << failures[grp.name] << "\n";
  EXPECT_GT(roughness0, 1000);
  EXPECT_GT(roughness1, 1000);
  EXPECT_GT(peaks, 100);
}

TEST(PbrParity, GlslAndCppAgreeOnRandomGrazingAndExtremeRoughness) {
  checkParity(false, 20261128u);
}

// KHR_materials_iridescence: the same cases with a random film (strength, IOR 1 to 2.5,
// thickness 0 to 1200 nm), and pbrFilmFresnel itself at a random cos(theta1).
TEST(PbrParity, GlslAndCppAgreeWithAThinFilm) {
  checkParity(true, 20261130u);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
