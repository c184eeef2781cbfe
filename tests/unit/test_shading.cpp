// The shared shading model (shaders/common/shading.glsl compiled as C++): hand-computed values,
// refraction truths (Snell, critical angle, slab shift), and finiteness on any input.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

#include "engine/shading/shading.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
using namespace diptych::shading;

ShadingMaterial material(float ka, float kd, float ks, float e) {
  Material m;
  m.color = vec3(0.5f, 0.25f, 1.f);
  m.ka = ka;
  m.kd = kd;
  m.ks = ks;
  m.exponent = e;
  m.specularColor = vec3(1.f, 0.5f, 0.25f);
  m.emission = vec3(0.f);
  return toShadingMaterial(m);
}

ShadingLight pointLight(vec3 position, float intensity) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = intensity;
  l.color = vec3(1.f);
  return toShadingLight(l);
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;

vec3 dirAt(double thetaFromNormal) {  // unit vector in the xz plane, angle from +z
  return vec3(float(std::sin(thetaFromNormal)), 0.f, float(std::cos(thetaFromNormal)));
}

bool finite(vec3 v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

TEST(Shading, DiffuseUnderPointLightIsKdCCosOverDistanceSquared) {
  const ShadingMaterial m = material(0.f, 0.8f, 0.f, 1.f);
  const vec3 p(0.f), n(0, 0, 1);
  // Light at distance 2 at 45 degrees: S = 10 / 4, n.l = cos 45.
  const ShadingLight light = pointLight(vec3(std::sqrt(2.f), 0.f, std::sqrt(2.f)), 10.f);
  const LightSample s = sampleLight(light, p);
  EXPECT_NEAR(s.distance, 2.f, 1e-6f);
  EXPECT_NEAR(s.radiance.x, 2.5f, 1e-6f);
  const vec3 L = lightContribution(m, n, vec3(0, 0, 1), s, 1.f);
  const float expected = 2.5f * 0.8f * 0.70710678f;
  EXPECT_NEAR(L.x, expected * 0.5f, 1e-6f);
  EXPECT_NEAR(L.y, expected * 0.25f, 1e-6f);
  EXPECT_NEAR(L.z, expected * 1.f, 1e-6f);
  // Invisible: nothing.
  EXPECT_EQ(lightContribution(m, n, vec3(0, 0, 1), s, 0.f), vec3(0.f));
}

// directTerm's precondition (unit n, v, l, or zero) is checked in debug builds: a forgotten
// normalisation aborts there instead of shading with a scaled dot product. The check is an
// assert, so the test exists only where asserts do (the ASan/UBSan suite runs it); the release
// suite has no test to report as skipped.
#ifndef NDEBUG
TEST(Shading, DirectTermChecksUnitInputsInDebugBuilds) {
  const ShadingMaterial m = material(0.1f, 0.5f, 0.5f, 10.f);
  const vec3 n(0, 0, 1), l = dirAt(45 * kDeg);
  EXPECT_EQ(directTerm(m, n, n, vec3(0.f)), m.ka * m.color);  // zero l: allowed, no direction
  EXPECT_DEATH(directTerm(m, 2.f * n, n, l), "");
  EXPECT_DEATH(directTerm(m, n, 0.5f * n, l), "");
  EXPECT_DEATH(directTerm(m, n, n, 3.f * l), "");
}
#endif

// safePow's integer path (repeated squaring): within (e - 1) 2^-24 of the exact power, results
// below the smallest normal float are 0 (as a GPU's flush to zero gives), and the edge cases.
TEST(Shading, SafePowIntegerExponentsAreExactPowersWithinTheirRoundingBound) {
  for (const float e : {1.f, 2.f, 3.f, 10.f, 64.f, 255.f, 1000.f, 1024.f}) {
    for (const float b : {0.3f, 0.5f, 0.9f, 0.999f, 1.f, 1.001f, 1.5f}) {
      const double exact = std::pow(double(b), double(e));
      if (exact < double(FLT_MIN) || exact > double(FLT_MAX)) continue;
      EXPECT_NEAR(safePow(b, e) / exact, 1.0, double(e) * 0x1p-24) << b << "^" << e;
    }
  }
  EXPECT_EQ(safePow(0.f, 0.f), 1.f);         // 0^0 := 1
  EXPECT_EQ(safePow(0.f, 10.f), 0.f);        // base 0
  EXPECT_EQ(safePow(-0.5f, 3.f), 0.f);       // negative bases count as 0
  EXPECT_EQ(safePow(0.5f, -2.f), 1.f);       // negative exponents count as 0
  EXPECT_EQ(safePow(1e-4f, 10.f), 0.f);      // 1e-40: below FLT_MIN, 0 (not a subnormal)
  EXPECT_EQ(safePow(0.01f, 20.f), 0.f);      // likewise, via a factor p in [2^-63, 1.084e-19]
  EXPECT_EQ(safePow(2.f, 1000.f), FLT_MAX);  // clamped, not inf
  // 1025 is past the integer path: pow, the same value within a float's rounding.
  EXPECT_NEAR(safePow(0.999f, 1025.f) / std::pow(double(0.999f), 1025.0), 1.0, 1e-5);
}

TEST(Shading, GlossyUsesTheMirrorDirectionOfL) {
  const ShadingMaterial m = material(0.f, 0.f, 0.5f, 10.f);
  const vec3 n(0, 0, 1), l = dirAt(45 * kDeg);
  // Viewer in the mirror direction: r.v = 1, term = ks d_i.
  const vec3 atMirror = directTerm(m, n, dirAt(-45 * kDeg), l);
  EXPECT_NEAR(atMirror.x, 0.5f, 1e-6f);
  EXPECT_NEAR(atMirror.y, 0.25f, 1e-6f);
  // Viewer along n: r.v = cos 45, term = 0.5 * cos(45)^10 = 0.5 / 32.
  const vec3 along = directTerm(m, n, n, l);
  EXPECT_NEAR(along.x, 0.5f / 32.f, 1e-6f);
  // Light below the horizon: no glossy term (documented deviation), and no diffuse.
  EXPECT_EQ(directTerm(m, n, dirAt(-95 * kDeg), dirAt(95 * kDeg)), vec3(0.f));
  // 0^0 := 1: exponent 0 gives the constant ks d_i whenever n.l > 0, even for r.v <= 0.
  EXPECT_NEAR(directTerm(material(0, 0, 0.5f, 0.f), n, dirAt(60 * kDeg), l).x, 0.5f, 1e-6f);
}

TEST(Shading, AmbientIsScaledByTheLightAndEmissionAndGlobalAmbientAreAdded) {
  ShadingMaterial m = material(0.1f, 0.f, 0.f, 1.f);
  // k_a C is inside the lecture's L_dir: it is multiplied by S_i even for a light behind.
  const ShadingLight light = pointLight(vec3(0.f, 0.f, -2.f), 8.f);  // behind, S = 2
  const LightSample s = sampleLight(light, vec3(0.f));
  const vec3 L = lightContribution(m, vec3(0, 0, 1), vec3(0, 0, 1), s, 1.f);
  EXPECT_NEAR(L.x, 2.f * 0.1f * 0.5f, 1e-6f);
  EXPECT_NEAR(L.z, 2.f * 0.1f * 1.f, 1e-6f);
  m.emission = vec3(1.f, 2.f, 3.f);
  EXPECT_EQ(emittedAndAmbient(m, vec3(0.5f)), vec3(1.5f, 2.5f, 3.5f));
  m.kps = 0.5f;
  m.mirrorColor = vec3(1.f, 0.f, 0.f);
  m.kt = 0.25f;
  m.transmitColor = vec3(0.f, 0.f, 1.f);
  EXPECT_EQ(secondaryTerms(m, vec3(0, 0, 1), vec3(0, 0, 1), vec3(2.f), vec3(4.f)),
            vec3(1.f, 0.f, 1.f));
}

TEST(Shading, LightUnitsAndSpotCone) {
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = vec3(0.f, -2.f, 0.f);
  sun.intensity = 3.f;
  const LightSample ds = sampleLight(toShadingLight(sun), vec3(100.f));
  EXPECT_EQ(ds.l, vec3(0.f, 1.f, 0.f));
  EXPECT_EQ(ds.radiance, vec3(3.f));  // lux, no falloff

  Light spot;
  spot.type = LightType::Spot;
  spot.position = vec3(0.f, 4.f, 0.f);
  spot.direction = vec3(0.f, -1.f, 0.f);
  spot.intensity = 16.f;
  spot.innerConeAngle = float(20 * kDeg);
  spot.outerConeAngle = float(40 * kDeg);
  const ShadingLight sl = toShadingLight(spot);
  EXPECT_NEAR(sampleLight(sl, vec3(0.f)).radiance.x, 1.f, 1e-6f);  // on axis: 16 / 4^2
  const auto at = [&](double angle) {
    const vec3 p(float(4 * std::tan(angle)), 0.f, 0.f);
    return sampleLight(sl, p).radiance.x * glm::dot(p - spot.position, p - spot.position) / 16.f;
  };
  EXPECT_NEAR(at(10 * kDeg), 1.f, 1e-5f);  // inside the inner cone
  EXPECT_NEAR(at(45 * kDeg), 0.f, 1e-6f);  // outside the outer cone
  const double c30 = std::cos(30 * kDeg), ci = std::cos(20 * kDeg), co = std::cos(40 * kDeg);
  const double a = (c30 - co) / (ci - co);
  EXPECT_NEAR(at(30 * kDeg), a * a, 1e-5f);  // KHR_lights_punctual smooth falloff

  Light ranged;
  ranged.position = vec3(0.f, 5.f, 0.f);
  ranged.range = 4.f;
  EXPECT_EQ(sampleLight(toShadingLight(ranged), vec3(0.f)).radiance, vec3(0.f));
}

TEST(Refraction, SnellAt45DegreesIntoGlass) {
  // Light arriving at 45 degrees from the air side (i points back toward it), into n = 1.5.
  const vec3 n(0, 0, 1);
  const Refraction r = refractLecture(dirAt(45 * kDeg), n, 1.f / 1.5f);
  ASSERT_FALSE(r.totalInternalReflection);
  const double sinT = std::sin(45 * kDeg) / 1.5;
  EXPECT_NEAR(glm::length(r.t), 1.f, 1e-6f);
  EXPECT_NEAR(r.t.z, -std::sqrt(1 - sinT * sinT), 1e-6);
  EXPECT_NEAR(r.t.x, -sinT, 1e-6);  // continues to the other side, bent toward the normal
}

TEST(Refraction, CriticalAngleFlipsTotalInternalReflectionWithoutNaN) {
  const double critical = std::asin(1.0 / 1.5);
  EXPECT_NEAR(critical / kDeg, 41.8103149, 1e-6);
  const vec3 n(0, 0, 1);
  const Refraction below = refractLecture(dirAt(critical - 1e-6), n, 1.5f);
  const Refraction above = refractLecture(dirAt(critical + 1e-6), n, 1.5f);
  EXPECT_FALSE(below.totalInternalReflection);
  EXPECT_TRUE(above.totalInternalReflection);
  EXPECT_TRUE(finite(below.t));
  EXPECT_TRUE(finite(above.t));
  EXPECT_NEAR(below.t.z, -0.f, 2e-3f);  // grazing exit
  EXPECT_NEAR(glm::length(below.t), 1.f, 1e-5f);
  // On TIR the mirror direction comes back.
  EXPECT_NEAR(above.t.z, std::cos(critical), 1e-5);
}

TEST(Refraction, EtaOnePassesStraightThrough) {
  for (double a : {0.0, 10.0, 45.0, 89.9}) {
    const vec3 i = dirAt(a * kDeg);
    const Refraction r = refractLecture(i, vec3(0, 0, 1), 1.f);
    EXPECT_FALSE(r.totalInternalReflection);
    EXPECT_EQ(r.t, -i);
  }
}

TEST(Refraction, LateralShiftThroughASlab) {
  // Slab 0 >= z >= -1, n = 1.5, ray at 45 degrees entering at the origin.
  const vec3 nTop(0, 0, 1);
  const vec3 d0 = -dirAt(45 * kDeg);  // travelling down and to -x
  const Refraction in = refractLecture(-d0, nTop, 1.f / 1.5f);
  ASSERT_FALSE(in.totalInternalReflection);
  const float s = -1.f / in.t.z;  // reach z = -1
  const vec3 exitPoint = s * in.t;
  const Refraction out = refractLecture(-in.t, nTop, 1.5f);  // leave through the bottom
  ASSERT_FALSE(out.totalInternalReflection);
  EXPECT_NEAR(glm::dot(out.t, d0), 1.f, 1e-6f);  // parallel to the incoming ray
  // Distance between the incoming line (through the origin along d0) and the outgoing one.
  const vec3 w = exitPoint - glm::dot(exitPoint, d0) * d0;
  EXPECT_NEAR(glm::length(w), 0.329142f, 1e-4f);
}

TEST(Fresnel, SchlickValues) {
  EXPECT_NEAR(fresnelSchlick(1.f, 1.f, 1.5f), 0.04f, 1e-6f);  // normal incidence
  EXPECT_NEAR(fresnelSchlick(0.f, 1.f, 1.5f), 1.f, 1e-6f);    // grazing
  EXPECT_NEAR(fresnelSchlick(0.5f, 1.f, 1.5f), 0.04f + 0.96f / 32.f, 1e-6f);
  EXPECT_NEAR(fresnelSchlick(1.f, 1.f, 1.f), 0.f, 1e-7f);
}

TEST(Shading, NoNaNOrInfOverRandomAndExtremeInputs) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<float> U(-1.f, 1.f);
  std::uniform_int_distribution<int> pick(0, 9);
  const float specials[] = {0.f, 1e-30f, -1e-30f, 1e30f, -1e30f, 1e-45f, 3e38f, 1.f, -1.f, 0.5f};
  const auto randomVec = [&]() {
    switch (pick(rng)) {
      case 0:
        return vec3(0.f);
      case 1:
        return vec3(U(rng), U(rng), U(rng)) * 1e30f;
      case 2:
        return vec3(U(rng), U(rng), U(rng)) * 1e-30f;
      case 3:
        return vec3(specials[pick(rng)], specials[pick(rng)], specials[pick(rng)]);
      default:
        return vec3(U(rng), U(rng), U(rng));
    }
  };
  for (int i = 0; i < 100000; ++i) {
    vec3 n = randomVec(), v = randomVec(), p = randomVec();
    if (i % 3 == 0) {  // grazing: v and l (below) almost in the tangent plane
      n = vec3(0, 0, 1);
      v = vec3(1.f, 0.f, specials[pick(rng)] * 1e-7f);
    }
    ShadingMaterial m =
        material(std::abs(U(rng)), std::abs(U(rng)), std::abs(U(rng)), specials[pick(rng)] * 1e4f);
    Light light;
    light.type = LightType(pick(rng) % 6);
    light.position = i % 7 == 0 ? p : randomVec();
    light.direction = randomVec();
    light.intensity = std::abs(specials[pick(rng)]);
    light.innerConeAngle = std::abs(U(rng));
    light.outerConeAngle = i % 5 == 0 ? light.innerConeAngle : std::abs(U(rng)) * 1.5f;
    light.edgeU = randomVec();
    light.edgeV = randomVec();
    light.radius = std::abs(specials[pick(rng)]);
    const ShadingLight sl = toShadingLight(light);
    const LightSample s = sampleLight(sl, p);
    ASSERT_TRUE(finite(s.l) && std::isfinite(s.distance) && finite(s.radiance))
        << i << " type " << sl.type << " l " << s.l.x << "," << s.l.y << "," << s.l.z << " d "
        << s.distance << " S " << s.radiance.x << " p " << p.x << "," << p.y << "," << p.z
        << " light " << sl.position.x << "," << sl.position.y << "," << sl.position.z;
    // lightContribution takes unit n, v (directTerm's precondition); refractLecture below gets
    // the raw ones.
    const vec3 L = lightContribution(m, safeNormalize(n), safeNormalize(v), s, U(rng) * 2.f) +
                   emittedAndAmbient(m, vec3(0.1f));
    ASSERT_TRUE(finite(L)) << i;
    ASSERT_GE(std::min(L.x, std::min(L.y, L.z)), 0.f) << i;
    const Refraction r = refractLecture(v, n, std::abs(specials[pick(rng)]) + U(rng));
    ASSERT_TRUE(finite(r.t)) << i;
    ASSERT_TRUE(std::isfinite(fresnelSchlick(U(rng) * 2.f, std::abs(U(rng)), std::abs(U(rng)))));
    ASSERT_TRUE(finite(safeNormalize(randomVec())));
  }
}
}  // namespace DIPTYCH_UNITY_ID
