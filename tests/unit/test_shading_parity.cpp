// GLSL vs C++ shading parity: shaders/common/shading.glsl compiled as GLSL (a compute shader on
// OSMesa/llvmpipe) and as C++ (engine/shading/shading.h) must give the same values on the same
// inputs, including grazing and extreme ones; and scene_shading.glsl's surfaceFromHits must
// reconstruct the same surface point as makeSurfacePoint (engine/rt/surface_point.h) from a
// G-buffer.
//
// Norm: for each output vector (or scalar) g (GPU) and c (CPU),
//   |g - c|_inf <= 1e-5 * max(|c|_inf, floor)
// i.e. 1e-5 relative to the vector's largest component, and 1e-5 * floor absolute when the
// whole vector is near 0 (floor = 1e-3 for radiance-like outputs, 1 for unit vectors).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <iostream>
#include <random>

#include <glm/gtx/string_cast.hpp>

#include "engine/gl/debug.h"
#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/shader.h"
#include "engine/gl/shading_buffers.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/rt/surface_point.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "gl_test_context.h"
#include "parity_support.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using namespace shading;
constexpr int kInStride = 64, kOutStride = 24;  // floats per record (shading_parity.comp)

const std::filesystem::path kShader =
    std::filesystem::path(DIPTYCH_TESTS_DIR) / "unit/shaders/shading_parity.comp";

// One case: every function's inputs. Layout = the shader's at() indices.
struct Case {
  ShadingLight light{};
  ShadingMaterial material{};
  vec3 p{0.f}, n{0.f}, v{0.f}, d{0.f};
  float visibility = 1.f, eta = 1.f, cosTheta = 0.f, n1 = 1.f, n2 = 1.f;

  void write(float* r) const {
    auto put3 = [&](int i, vec3 x) { r[i] = x.x, r[i + 1] = x.y, r[i + 2] = x.z; };
    r[0] = float(light.type);
    put3(1, light.color);
    r[4] = light.intensity;
    put3(5, light.position);
    put3(8, light.direction);
    r[11] = light.range, r[12] = light.cosInner, r[13] = light.cosOuter, r[14] = light.area;
    const ShadingMaterial& m = material;
    put3(15, m.color);
    r[18] = m.ka, r[19] = m.kd, r[20] = m.ks, r[21] = m.exponent;
    put3(22, m.specularColor);
    r[25] = m.kps;
    put3(26, m.mirrorColor);
    r[29] = m.kt;
    put3(30, m.transmitColor);
    put3(33, m.emission);
    r[36] = m.ior, r[37] = m.alpha;
    put3(38, p);
    put3(41, n);
    put3(44, v);
    r[47] = visibility, r[48] = eta, r[49] = cosTheta, r[50] = n1;
    put3(51, d);
    r[54] = n2;
  }

  // The C++ evaluation, in the shader's output order.
  std::array<float, kOutStride> evaluate() const {
    const LightSample s = sampleLight(light, p);
    // directTerm's precondition: unit n, v (normalised as the shader does).
    const vec3 un = safeNormalize(n), uv = safeNormalize(v);
    const vec3 direct = directTerm(material, un, uv, s.l);
    const vec3 contribution = lightContribution(material, un, uv, s, visibility);
    const Refraction t = refractLecture(d, n, eta);
    const vec3 r = reflectAbout(d, n);
    const float f = fresnelSchlick(cosTheta, n1, n2);
    return {s.l.x,
            s.l.y,
            s.l.z,
            s.distance,
            s.radiance.x,
            s.radiance.y,
            s.radiance.z,
            direct.x,
            direct.y,
            direct.z,
            contribution.x,
            contribution.y,
            contribution.z,
            t.t.x,
            t.t.y,
            t.t.z,
            t.totalInternalReflection ? 1.f : 0.f,
            r.x,
            r.y,
            r.z,
            f,
            0.f,
            0.f,
            0.f};
  }
};

// Random inputs, a share of them extreme: zero, tiny (1e-30) and huge (1e30) vectors, points on
// the light, grazing n.l and n.v, exponent 0 and 1e4, intensities up to FLT_MAX, eta = 1 and
// near-critical refraction, cosines outside [0, 1].
class CaseGenerator : testing::RandomInputs {
 public:
  explicit CaseGenerator(unsigned seed) : RandomInputs(seed, 0.1f) {}

  Case next() {
    Case c;
    ShadingLight& l = c.light;
    l.type = int(uniform(0.f, 6.f)) % 6;
    l.color = vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1));
    l.intensity = pick({0.f, 1e-20f, 3e38f, 1e30f}, std::pow(10.f, uniform(-3.f, 4.f)));
    l.position = point();
    l.direction = vector();
    l.range = chance(0.3f) ? uniform(0.5f, 20.f) : 0.f;
    l.cosOuter = uniform(0.f, 1.f);
    l.cosInner = chance(0.1f) ? l.cosOuter : uniform(l.cosOuter, 1.f);
    l.area = pick({0.f, 1e30f}, uniform(0.f, 5.f));

    ShadingMaterial& m = c.material;
    m.color = vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1));
    m.ka = uniform(0, 1), m.kd = uniform(0, 1), m.ks = uniform(0, 1);
    // Integer exponents take safePow's repeated squaring (up to 1024), others pow. The same
    // number of draws as before, so every other field's cases stay what they were.
    float usual = uniform(1.f, 200.f);
    if (usual - std::floor(usual) < 0.5f) usual = std::floor(usual);
    m.exponent = pick({0.f, 1e4f, 0.5f, 1024.f, 1025.f}, usual);
    m.specularColor = vec3(uniform(0, 1), uniform(0, 1), uniform(0, 1));
    m.kps = uniform(0, 1), m.kt = uniform(0, 1), m.ior = uniform(1, 2.5f), m.alpha = 1.f;
    m.mirrorColor = m.transmitColor = m.emission = vec3(uniform(0, 1));

    c.p = chance(0.05f) ? l.position : point();
    c.n = vector();
    c.v = chance(0.2f) ? grazing(c.n) : vector();
    c.d = chance(0.2f) ? grazing(c.n) : vector();
    c.visibility = pick({0.f, 1.f, 1.5f}, uniform(0, 1));
    c.eta = pick({1.f, 1e-20f, 1e20f}, uniform(0.3f, 3.f));
    c.cosTheta = uniform(-0.5f, 1.5f);
    c.n1 = uniform(1, 3), c.n2 = uniform(1, 3);
    return c;
  }

 private:
  vec3 vector() { return unit() * pick({0.f, 1e-30f, 1e30f}, uniform(0.1f, 3.f)); }
  vec3 point() { return unit() * pick({0.f, 1e-20f, 1e30f}, uniform(0.f, 10.f)); }
};

// The spot cone factor a = saturate((cd - cosOuter) / (cosInner - cosOuter)) loses relative
// accuracy where cd - cosOuter cancels (a small) or the cone is narrow.
bool spotStiff(const Case& c) {
  const float width = c.light.cosInner - c.light.cosOuter;
  const vec3 l = safeNormalize(c.light.position - c.p);
  const float cd = dot(safeNormalize(c.light.direction), -l);
  return width < 0.05f || (cd - c.light.cosOuter) / std::max(width, 1e-3f) < 0.1f;
}

struct Group {
  const char* name;
  int first, count;
  float floor;  // magnitude below which the tolerance is absolute
};
constexpr Group kGroups[] = {
    {"sampleLight.l", 0, 3, 1.f},          {"sampleLight.distance", 3, 1, 1e-3f},
    {"sampleLight.radiance", 4, 3, 1e-3f}, {"directTerm", 7, 3, 1e-3f},
    {"lightContribution", 10, 3, 1e-3f},   {"refractLecture.t", 13, 3, 1.f},
    {"refractLecture.tir", 16, 1, 1.f},    {"reflectAbout", 17, 3, 1.f},
    {"fresnelSchlick", 20, 1, 1e-3f}};

TEST(ShadingParity, GlslAndCppAgreeOnRandomAndExtremeInputs) {
  gl::testing::osmesaContext();
  constexpr int kCases = 20000;
  CaseGenerator gen(20240611u);
  std::vector<Case> cases;
  for (int i = 0; i < kCases; ++i) cases.push_back(gen.next());
  const std::vector<float> gpu =
      testing::dispatchCases(cases, kInStride, kOutStride, kShader, {{"SHADING_CASES", ""}});

  std::map<std::string, double> worst;
  std::map<std::string, int> failures;
  int reflectOverflows = 0;
  for (int i = 0; i < kCases; ++i) {
    const auto cpu = cases[i].evaluate();
    const float* g = &gpu[std::size_t(i) * kOutStride];
    for (const Group& grp : kGroups) {
      // reflectAbout(d, n) = 2 (n.d) n - d has no overflow guard (it is meant for unit vectors):
      // with |n|^2 |d| beyond FLT_MAX both sides overflow. Counted and reported, not compared.
      const Case& c = cases[i];
      if (grp.first == 17 &&
          double(glm::length(c.n)) * glm::length(c.n) * glm::length(c.d) > 1e37) {
        ++reflectOverflows;
        continue;
      }
      float diff = 0.f, scale = grp.floor;
      for (int k = grp.first; k < grp.first + grp.count; ++k) {
        ASSERT_TRUE(std::isfinite(g[k]))
            << grp.name << " case " << i << " n " << glm::to_string(c.n) << " d "
            << glm::to_string(c.d) << " cpu " << cpu[k];
        ASSERT_TRUE(std::isfinite(cpu[k])) << grp.name << " case " << i;
        diff = std::max(diff, std::abs(g[k] - cpu[k]));
        scale = std::max(scale, std::abs(cpu[k]));
      }
      const double rel = diff / scale;
      // Ill-conditioned cases amplify the last-bit differences of the inputs to pow and to the
      // spot cone (GLSL allows a few ULP on dot, sqrt, inversesqrt, pow): d(x^e)/x^e = e dx/x,
      // and the cone factor's slope is 2 / (cosInner - cosOuter). Those get 1e-4.
      const bool stiff = c.material.exponent > 50.f || (c.light.type == LIGHT_SPOT && spotStiff(c));
      const bool lit = grp.first >= 4 && grp.first < 13;  // radiance, directTerm, contribution
      // Radiance chains ~10 rounded operations after the direction (each <= 2.5 ULP in GLSL 4.50
      // section 4.7.1), so 2e-5 there; 1e-5 for directions, distances, Fresnel.
      const double bound = lit ? (stiff ? 1e-4 : 2e-5) : 1e-5;
      worst[grp.name] = std::max(worst[grp.name], rel);
      if (rel > bound) {
        if (++failures[grp.name] <= 3)
          ADD_FAILURE() << grp.name << " case " << i << ": relative difference " << rel << " (type "
                        << c.light.type << ", exponent " << c.material.exponent << ", cone "
                        << c.light.cosInner - c.light.cosOuter << ")";
      }
    }
  }
  std::cout << "[ measured ] reflectAbout with |n|^2 |d| > 1e37 (not compared): "
            << reflectOverflows << " of " << kCases << "\n";
  for (const Group& grp : kGroups)
    std::cout << "[ measured ] " << grp.name << ": worst relative difference " << worst[grp.name]
              << ", cases over the bound: " << failures[grp.name] << " of " << kCases << "\n";
}

// surfaceFromHits (GLSL) vs makeSurfacePoint (C++) on every texel of a rasterized G-buffer of
// the Whitted sample: position, face normal, shading normal (unflipped), uv and material.
TEST(ShadingParity, SurfaceFromVisibilityMatchesMakeSurfacePoint) {
  gl::testing::osmesaContext();
  const int errorsBefore = gl::glDebugErrorCount();
  const Scene scene = loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
  constexpr int kW = 160, kH = 120, kStride = 12;
  RenderWorld world(scene, &gl::testing::osmesaContext());
  gl::GBufferTextures targets;
  gl::rasterizeGBuffer(world.glScene(), scene.camera, kW, kH, targets);
  const gl::Buffer out = gl::Buffer::create(std::size_t(kW) * kH * kStride * 4);
  const gl::Program program = gl::loadProgram({kShader}, {{"SURFACE_CASES", ""}});
  world.glScene().bind();
  world.glShading().bind();
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 7);
  program.use();
  program.set("uLightCount", world.glShading().lightCount);
  gl::glBindTextureUnit(0, targets.hits.id());
  gl::glDispatchCompute(GLuint((kW * kH + 63) / 64), 1, 1);
  gl::glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> gpu(std::size_t(kW) * kH * kStride);
  out.download(0, gpu.size() * 4, gpu.data());
  const std::vector<std::uint32_t> ids = gl::readTexture(targets.hits);
  EXPECT_EQ(gl::glDebugErrorCount(), errorsBefore);

  double worst[4] = {0, 0, 0, 0};  // position, face normal, shading normal, uv
  int hits = 0;
  for (int i = 0; i < kW * kH; ++i) {
    const std::uint32_t* t = &ids[std::size_t(i) * 4];
    if (t[0] == 0) continue;
    ++hits;
    const SurfaceHit hit{int(t[0]) - 1, t[1], std::bit_cast<float>(t[2]),
                         std::bit_cast<float>(t[3])};
    const SurfacePoint sp = makeSurfacePoint(scene, world.geometry(), hit, vec3(0.f));
    const float* g = &gpu[std::size_t(i) * kStride];
    auto rel = [](vec3 a, vec3 b) {  // |a - b|_inf / max(|b|_inf, 1)
      const vec3 d = glm::abs(a - b);
      return double(std::max({d.x, d.y, d.z})) /
             std::max({1.f, std::abs(b.x), std::abs(b.y), std::abs(b.z)});
    };
    const double e[4] = {rel(vec3(g[0], g[1], g[2]), sp.position),
                         rel(vec3(g[3], g[4], g[5]), sp.faceNormal),
                         rel(vec3(g[6], g[7], g[8]), sp.shadingNormal),
                         rel(vec3(g[9], g[10], 0.f), vec3(sp.uv, 0.f))};
    for (int k = 0; k < 4; ++k) {
      worst[k] = std::max(worst[k], e[k]);
      ASSERT_LE(e[k], 1e-5) << "texel " << i << " quantity " << k;
    }
    ASSERT_EQ(int(g[11]), sp.material) << "texel " << i;
  }
  EXPECT_GT(hits, kW * kH / 4);
  std::cout << "[ measured ] surfaceFromHits vs makeSurfacePoint over " << hits
            << " texels: worst relative position " << worst[0] << ", face normal " << worst[1]
            << ", shading normal " << worst[2] << ", uv " << worst[3] << "\n";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
