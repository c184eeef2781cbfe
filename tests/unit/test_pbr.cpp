// The glTF 2.0 metallic-roughness model (shaders/common/pbr.glsl) compiled as C++: closed-form
// cases, reciprocity, energy bounds by quadrature, the dispatch by ShadingMaterial::model, the
// KHR_materials_iridescence film (PbrFilm), and the scene side (loader defaults, the JSON keys,
// --shading's forceShadingModel).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/scene/load.h"
#include "engine/shading/shading.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using namespace shading;
constexpr float kPi = 3.14159265358979f;

ShadingMaterial pbr(vec3 base, float metallic, float roughness, float transmission = 0.f,
                    float specular = 1.f) {
  ShadingMaterial m{};
  m.model = SHADING_MODEL_GLTF;
  m.ior = 1.5f;
  m.alpha = 1.f;
  m.baseColor = base;
  m.metallic = metallic;
  m.roughness = roughness;
  m.transmission = transmission;
  m.specularWeight = specular;
  m.specularTint = vec3(1.f);
  return m;
}

vec3 dirAt(float theta, float phi = 0.f) {
  return vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
}

// Directional albedo: the integral over the hemisphere of f cos = pbrDirect / pi, by a midpoint
// rule in (cos theta, phi) (dw = dcos dphi), fine enough for roughness >= 0.2.
vec3 albedo(const ShadingMaterial& m, const vec3& v, int n = 400) {
  vec3 sum(0.f);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 2 * n; ++j) {
      const float c = (float(i) + 0.5f) / float(n);
      const float phi = 2.f * kPi * (float(j) + 0.5f) / float(2 * n);
      const vec3 l = dirAt(std::acos(c), phi);
      sum += pbrDirect(m, vec3(0, 0, 1), v, l) / kPi;
    }
  return sum * (2.f * kPi / (float(n) * float(2 * n)));
}

TEST(Pbr, WhiteDiffuseDielectricWithoutSpecularIsTheLecturesLambert) {
  // specular 0 (KHR_materials_specular) leaves c_diff / pi: pi f n.l = n.l, the lecture's
  // k_d C (n.l) for k_d C = 1, so the two models agree on a white matte surface.
  const ShadingMaterial m = pbr(vec3(1.f), 0.f, 0.7f, 0.f, 0.f);
  for (float t : {0.f, 0.5f, 1.2f})
    EXPECT_NEAR(pbrDirect(m, vec3(0, 0, 1), dirAt(0.3f), dirAt(t, 2.f)).x, std::cos(t), 1e-6f);
  EXPECT_EQ(pbrDirect(m, vec3(0, 0, 1), dirAt(0.3f), dirAt(1.7f)), vec3(0.f));  // below
}

TEST(Pbr, MetalAtNormalIncidenceIsBaseColourTimesDV) {
  // l = v = n: h = n, F = base, D = 1 / (pi a^2), V = 1 / 4 (n.l = n.v = 1):
  // pi f n.l = base / (4 a^2).
  const float r = 0.5f, a = r * r;
  const vec3 got =
      pbrDirect(pbr(vec3(0.9f, 0.6f, 0.3f), 1.f, r), vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 0, 1));
  const vec3 want = vec3(0.9f, 0.6f, 0.3f) / (4.f * a * a);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-5f * want[c]);
}

TEST(Pbr, BrdfIsReciprocal) {
  // f(l, v) = f(v, l): pbrDirect / n.l is symmetric in l and v (every factor is).
  for (float metallic : {0.f, 0.5f, 1.f})
    for (float r : {0.1f, 0.5f, 1.f}) {
      const ShadingMaterial m = pbr(vec3(0.8f, 0.5f, 0.2f), metallic, r);
      const vec3 a = dirAt(0.4f, 0.3f), b = dirAt(1.1f, 2.5f), n(0, 0, 1);
      const vec3 fab = pbrDirect(m, n, a, b) / b.z, fba = pbrDirect(m, n, b, a) / a.z;
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(fab[c], fba[c], 1e-5f * fab[c]) << metallic << r;
    }
}

TEST(Pbr, WhiteMetalNeverReflectsMoreThanArrives) {
  // White furnace by quadrature (the path-traced one is in test_pbr_furnace.cpp). A white metal
  // is single-scattering GGX with F = 1: its directional albedo is at most 1 for every view and
  // roughness; at roughness 1 (a = 1, D = 1/pi, V = 1/(2 (n.l + n.v))) it is 1 - ln 2 at normal
  // view, in closed form.
  for (float r : {0.2f, 0.5f, 1.f})
    for (float t : {0.f, 0.8f, 1.4f}) {
      const vec3 e = albedo(pbr(vec3(1.f), 1.f, r), dirAt(t));
      EXPECT_LE(e.x, 1.f + 2e-3f) << "roughness " << r << " theta " << t;
    }
  const float e = albedo(pbr(vec3(1.f), 1.f, 1.f), vec3(0, 0, 1)).x;
  std::printf("[ measured ] white metal, roughness 1, normal view: albedo %.4f (1 - ln 2 = %.4f)\n",
              e, 1.f - std::log(2.f));
  EXPECT_NEAR(e, 1.f - std::log(2.f), 2e-3f);
}

TEST(Pbr, WhiteDielectricGainsEnergyAtGrazingViewsAsTheSpecifiedLayeringDoes) {
  // The specification's dielectric, (1 - F(v.h)) c_diff / pi + F(v.h) D V, weights the diffuse
  // base per light direction: at a grazing view the specular lobe reflects ~F(n.v), close to 1,
  // while the diffuse base keeps most of its albedo (its v.h are far from grazing). So a white
  // dielectric's albedo exceeds 1 there; at normal view it does not. Measured and pinned here
  // (docs/materials.md, "White furnace").
  for (float r : {0.2f, 0.5f, 1.f}) {
    const float head = albedo(pbr(vec3(1.f), 0.f, r), vec3(0, 0, 1)).x;
    const float grazing = albedo(pbr(vec3(1.f), 0.f, r), dirAt(1.4f)).x;
    std::printf(
        "[ measured ] white dielectric, roughness %.1f: albedo %.4f at normal view, "
        "%.4f at 80 deg\n",
        r, head, grazing);
    EXPECT_LE(head, 1.f + 2e-3f) << r;
    EXPECT_LT(grazing, 1.4f) << r;
  }
}

TEST(Pbr, SecondaryWeightsAreFresnelWeightedAndFadeWithRoughness) {
  const vec3 n(0, 0, 1);
  // A smooth white metal reflects nearly everything: A + B = 1 at roughness 0 (the split-sum
  // table of env_brdf_table.glsl, a near-mirror GGX lobe with Smith masking ~1 head-on).
  EXPECT_NEAR(secondaryWeights(pbr(vec3(1.f), 1.f, 0.f), n, n).reflection.x, 1.f, 1e-2f);
  // A smooth dielectric reflects F0 = 0.04 head-on and more at grazing (Schlick).
  const float head = secondaryWeights(pbr(vec3(0.5f), 0.f, 0.f), n, n).reflection.x;
  const float grazing = secondaryWeights(pbr(vec3(0.5f), 0.f, 0.f), n, dirAt(1.5f)).reflection.x;
  EXPECT_NEAR(head, 0.04f, 1e-4f);  // the table's A = 1, B = 0 at n.v = 1, roughness 0
  EXPECT_GT(grazing, 0.3f);
  // Fully rough: no mirror signal (the lobe is left to the lights and the path tracer).
  EXPECT_EQ(secondaryWeights(pbr(vec3(1.f), 1.f, 1.f), n, n).reflection, vec3(0.f));
  // Transmission: what the Fresnel layer lets through, tinted; none for metals.
  const SecondaryWeights glass = secondaryWeights(pbr(vec3(1.f, 0.5f, 1.f), 0.f, 0.f, 1.f), n, n);
  EXPECT_NEAR(glass.transmission.x, 0.96f, 1e-4f);
  EXPECT_NEAR(glass.transmission.y, 0.48f, 1e-4f);
  EXPECT_EQ(secondaryWeights(pbr(vec3(1.f), 1.f, 0.f, 1.f), n, n).transmission, vec3(0.f));
  // secondaryTerms is the weighted sum.
  const ShadingMaterial m = pbr(vec3(0.7f), 0.3f, 0.2f, 0.5f);
  const SecondaryWeights w = secondaryWeights(m, n, dirAt(0.6f));
  const vec3 t = secondaryTerms(m, n, dirAt(0.6f), vec3(2.f), vec3(3.f));
  EXPECT_NEAR(t.y, 2.f * w.reflection.y + 3.f * w.transmission.y, 1e-6f);
}

TEST(Pbr, TheLectureModelIsUnchangedByTheDispatch) {
  ShadingMaterial m{};
  m.color = vec3(0.5f);
  m.kd = 1.f;
  m.kps = 0.25f;
  m.mirrorColor = vec3(1.f);
  m.kt = 0.5f;
  m.transmitColor = vec3(1.f, 0.f, 0.f);
  const vec3 n(0, 0, 1), v = dirAt(0.7f), l = dirAt(0.3f, 1.f);
  EXPECT_EQ(directResponse(m, n, v, l), directTerm(m, n, v, l));
  EXPECT_EQ(secondaryTerms(m, n, v, vec3(4.f), vec3(2.f)), vec3(2.f, 1.f, 1.f));
}

// ---- KHR_materials_iridescence: the thin-film Fresnel (pbrFilmFresnel) and its mix ----

ShadingMaterial filmed(ShadingMaterial m, float strength, float ior, float thickness) {
  m.iridescence = strength;
  m.iridescenceIor = ior;
  m.iridescenceThickness = thickness;
  return m;
}

TEST(PbrFilm, StrengthZeroLeavesTheModelExactlyUnchanged) {
  const vec3 n(0, 0, 1), v = dirAt(0.6f), l = dirAt(0.9f, 2.f);
  for (float metallic : {0.f, 0.4f, 1.f}) {
    const ShadingMaterial plain = pbr(vec3(0.8f, 0.5f, 0.2f), metallic, 0.3f, 0.5f);
    const ShadingMaterial off = filmed(plain, 0.f, 1.8f, 350.f);
    EXPECT_EQ(pbrDirect(off, n, v, l), pbrDirect(plain, n, v, l)) << metallic;
    const SecondaryWeights a = pbrSecondaryWeights(off, n, v), b = pbrSecondaryWeights(plain, n, v);
    EXPECT_EQ(a.reflection, b.reflection) << metallic;
    EXPECT_EQ(a.transmission, b.transmission) << metallic;
    // The same film at full strength does change the colour: the term is wired in.
    const vec3 on = pbrDirect(filmed(plain, 1.f, 1.8f, 350.f), n, v, l);
    EXPECT_GT(glm::length(on - pbrDirect(plain, n, v, l)), 1e-3f) << metallic;
  }
}

TEST(PbrFilm, ZeroThicknessIsThePlainFresnelOfTheBase) {
  for (float c : {0.f, 0.2f, 0.7f, 1.f}) {
    for (vec3 f0 : {vec3(0.04f), vec3(0.9f, 0.6f, 0.3f), vec3(1.f)}) {
      const vec3 schlick = f0 + (vec3(1.f) - f0) * pbrSchlickWeight(c);
      EXPECT_EQ(pbrFilmFresnel(1.8f, f0, 0.f, c), schlick) << c;
    }
  }
  // Through the BRDF: a film of strength 1 but no thickness shades as no film.
  const vec3 n(0, 0, 1), v = dirAt(0.4f), l = dirAt(1.1f, 0.5f);
  const ShadingMaterial plain = pbr(vec3(0.3f, 0.6f, 0.9f), 0.5f, 0.2f);
  EXPECT_EQ(pbrDirect(filmed(plain, 1.f, 1.5f, 0.f), n, v, l), pbrDirect(plain, n, v, l));
}

// Thicknesses and IORs the schema allows but no film has (1e38 nm, IOR 1e36): the optical path
// difference overflowed to inf and cos(inf) exp(-inf) made F NaN. Beyond ~2.5e4 nm every
// interference term is 0 in float, so such a film is the thick-film limit, finite and in [0, 1].
TEST(PbrFilm, AbsurdThicknessOrIorStaysFiniteAtTheThickFilmLimit) {
  const vec3 f0(0.9f, 0.6f, 0.3f);
  for (float c : {0.1f, 0.6f, 1.f}) {
    const vec3 limit = pbrFilmFresnel(1.5f, f0, 1.0e5f, c);
    for (const auto& [ior, thickness] :
         {std::pair{1.5f, 1.0e38f}, std::pair{1.0e36f, 400.f}, std::pair{3.0e38f, 3.0e38f}}) {
      const vec3 f = pbrFilmFresnel(ior, f0, thickness, c);
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(std::isfinite(f[k]) && f[k] >= 0.f && f[k] <= 1.f)
            << "ior " << ior << " thickness " << thickness << " cos " << c << ": " << f[k];
      }
      if (ior == 1.5f) {
        EXPECT_EQ(f, limit) << c;
      }
    }
  }
}

TEST(PbrFilm, MatchesThePythonReference) {
  // From tests/tools/iridescence_reference.py: the spec's formulas in double precision, written
  // separately from pbr.glsl (film IOR, base F0, thickness nm, cos theta1, expected linear sRGB).
  struct Reference {
    float ior;
    vec3 f0;
    float thickness, cosTheta;
    vec3 rgb;
  };
  const Reference cases[] = {
      {1.8f, vec3(0.04f, 0.04f, 0.04f), 300.0f, 0.8f, vec3(0.1433912f, 0.05119359f, 0.09259215f)},
      {1.33f, vec3(0.9f, 0.6f, 0.3f), 400.0f, 1.0f, vec3(0.8612996f, 0.6000648f, 0.151301f)},
      {1.33f, vec3(0.9f, 0.6f, 0.3f), 250.0f, 0.35f, vec3(0.9121609f, 0.7001597f, 0.4591795f)},
  };
  for (const Reference& r : cases) {
    const vec3 got = pbrFilmFresnel(r.ior, r.f0, r.thickness, r.cosTheta);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(got[k], r.rgb[k], 2e-5f) << r.ior << " " << r.thickness << " channel " << k;
  }
  // The hue really moves with the thickness: 300 and 400 nm films on the same base differ.
  const vec3 a = pbrFilmFresnel(1.33f, vec3(0.04f), 300.f, 1.f);
  const vec3 b = pbrFilmFresnel(1.33f, vec3(0.04f), 400.f, 1.f);
  EXPECT_GT(glm::length(a - b), 0.01f);
}

TEST(PbrFilm, FullStrengthReplacesBothLobesFresnel) {
  // A smooth metal at normal incidence: pi f n.l = F D V pi, so the ratio of the filmed to the
  // plain response is F_film(base, v.h = 1) / base, per channel.
  const vec3 n(0, 0, 1), v(0, 0, 1), l(0, 0, 1);
  const vec3 base(0.9f, 0.6f, 0.3f);
  const ShadingMaterial metal = pbr(base, 1.f, 0.5f);
  const vec3 ratio =
      pbrDirect(filmed(metal, 1.f, 1.33f, 400.f), n, v, l) / pbrDirect(metal, n, v, l);
  const vec3 expected = pbrFilmFresnel(1.33f, base, 400.f, 1.f) / base;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(ratio[k], expected[k], 1e-5f) << k;
}

std::filesystem::path writeScene(const std::string& name, const std::string& text) {
  const auto dir = ::diptych::testing::scratchDir("diptych_pbr");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(Pbr, JsonMaterialsChooseTheirModelAndForceShadingOverridesIt) {
  const Scene scene = loadScene(writeScene("models.json", R"({
    "materials": {
      "matte": {"color": [0.2, 0.4, 0.6], "kd": 1},
      "gold": {"model": "gltf", "base_color": [1, 0.8, 0.3], "metallic": 1, "roughness": 0.3}},
    "objects": [{"type": "sphere", "material": "matte"},
                {"type": "sphere", "material": "gold", "transform": {"translate": [3, 0, 0]}}]
  })"));
  // Materials are stored in key order: gold, matte.
  ASSERT_EQ(scene.materials[0].name, "gold");
  const int gold = 0, matte = 1;
  EXPECT_EQ(scene.materials[matte].model, ShadingModel::Lecture);
  EXPECT_EQ(scene.materials[gold].model, ShadingModel::Gltf);
  EXPECT_EQ(shading::toShadingMaterial(scene.materials[gold]).metallic, 1.f);
  // Its lecture coefficients come from the glTF mapping (metal: no diffuse, a mirror part).
  EXPECT_EQ(scene.materials[gold].color, vec3(0.f));
  EXPECT_GT(scene.materials[gold].kps, 0.f);
  Scene forced = scene;
  forceShadingModel(forced, ShadingModel::Gltf);
  // The lecture's Lambertian maps to a fully rough dielectric of the same colour.
  EXPECT_EQ(forced.materials[matte].model, ShadingModel::Gltf);
  EXPECT_EQ(vec3(forced.materials[matte].baseColorFactor), vec3(0.2f, 0.4f, 0.6f));
  EXPECT_EQ(forced.materials[matte].metallicFactor, 0.f);
  EXPECT_EQ(forced.materials[matte].roughnessFactor, 1.f);
  forceShadingModel(forced, ShadingModel::Lecture);
  EXPECT_EQ(forced.materials[gold].model, ShadingModel::Lecture);
  EXPECT_FALSE(parseShadingModel("phong"));
}

TEST(Pbr, BadModelKeyNamesTheFileAndPlace) {
  const auto file = writeScene("bad-model.json", R"({
    "materials": {"m": {"model": "phong"}},
    "objects": [{"type": "sphere", "material": "m"}]})");
  try {
    loadScene(file);
    FAIL() << "accepted model 'phong'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bad-model.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("materials.m.model"), std::string::npos) << e.what();
  }
}

TEST(Pbr, GltfMaterialsUseTheGltfModelByDefault) {
  const Scene scene =
      loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/blender-point-light.gltf");
  ASSERT_FALSE(scene.materials.empty());
  for (const Material& m : scene.materials) EXPECT_EQ(m.model, ShadingModel::Gltf) << m.name;
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
