// The two Monte Carlo references through the real graph and Embree: distributed ray tracing
// (rt_distributed) and the path tracer (rt_path). Analytic answers where they exist (furnace,
// disc and sphere irradiance, thin-lens blur width); Monte Carlo bounds stated with n and sigma.
// Every render is deterministic (fixed seeds), so a bound that holds holds every run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <string>

#include "engine/graph/executor.h"
#include "engine/graph/render_world.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/path_tracer.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

std::filesystem::path writeScene(const std::string& name, const std::string& json) {
  const auto dir = ::diptych::testing::scratchDir("diptych_references");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << json;
  return dir / name;
}

Scene sample(const char* file) {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / file);
}

// A CPU-only frame of the given passes; outputs copied out, counters of every pass kept.
struct Frame {
  std::map<std::string, CpuImage> outputs;
  std::map<std::string, std::map<std::string, double>> counters;  // pass -> counter -> value
};

Frame render(const Scene& scene, std::vector<RecipePass> passes,
             const std::vector<std::string>& outputs, int w, int h) {
  Recipe recipe;
  recipe.file = "test";
  for (std::size_t i = 0; i < passes.size(); ++i)
    passes[i].place = "passes[" + std::to_string(i) + "]";
  recipe.passes = std::move(passes);
  recipe.outputs = outputs;
  const CompiledGraph g = compileGraph(recipe, builtinPasses(), scene, {w, h, scene.camera});
  RenderWorld world(scene);
  GraphExecutor ex(g, world);
  ex.runFrame();
  Frame f;
  for (const std::string& o : outputs) f.outputs.emplace(o, ex.output(o));
  for (std::size_t i = 0; i < g.nodes.size(); ++i)
    f.counters[g.nodes[i].name] = ex.timings()[i].counters;
  return f;
}

RecipePass pass(const std::string& name, const std::string& type, nlohmann::json params) {
  return {.name = name, .type = type, .params = std::move(params)};
}

bool allFinite(const CpuImage& s) {
  for (int y = 0; y < s.desc.height; ++y)
    for (int x = 0; x < s.desc.width; ++x)
      for (int c = 0; c < 4; ++c)
        if (!std::isfinite(s.f(x, y, c))) return false;
  return true;
}

// An emissive half-plane (x < 0, z = 0) seen head-on from z = 5 on a 65 x 49 image: the edge
// x = 0 projects onto the centre line x = 32.5 of column 32. Radiance 1 on the quad, 0 beside.
std::string edgeScene(float aperture, float focus) {
  return R"({"camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov": 45, "aperture": )" +
         std::to_string(aperture) + R"(, "focus_distance": )" + std::to_string(focus) + R"(},
    "materials": {"glow": {"color": [0, 0, 0], "kd": 0, "emission": [1, 1, 1]}},
    "objects": [{"type": "quad", "material": "glow",
                 "corners": [[-40, -40, 0], [0, -40, 0], [0, 40, 0], [-40, 40, 0]]}]})";
}
constexpr int kEdgeW = 65, kEdgeH = 49;

// Where the falling profile of row y crosses `level`, interpolating between pixel centres.
double crossing(const CpuImage& s, int y, float level) {
  for (int x = 0; x + 1 < s.desc.width; ++x) {
    const float a = s.f(x, y, 0), b = s.f(x + 1, y, 0);
    if (a >= level && b < level) return x + 0.5 + (a - level) / (a - b);
  }
  return -1;
}

// The white furnace: the camera inside a closed box whose inner walls emit M_E = 0.5 and
// reflect diffusely with albedo k_d C = 0.5. Every path sees L = 0.5 + 0.5 L, so L = 1 at every
// pixel. A box, not a tessellated sphere: its shading normals are its face normals, so no
// cosine sample is lost below a facet (which would bias a sphere low by ~1e-3).
const char* kFurnace = R"({
  "camera": {"position": [0.1, 0.2, 0.3], "target": [0, 0, -1], "fov": 90},
  "materials": {"wall": {"color": [1, 1, 1], "kd": 0.5, "emission": [0.5, 0.5, 0.5]}},
  "objects": [{"type": "box", "size": [2, 2, 2], "material": "wall"}]
})";

// rt_distributed with one sample per pixel and a pinhole is the Whitted reference itself: the
// pixel-centre ray, seeded with the pixel index, through the same WhittedTracer. Equality is
// asserted bit for bit (point lights: no sampling at all; quad light: the same stratified
// shadow rays, since the seeds agree).
TEST(RtDistributed, OneSamplePinholeEqualsWhittedBitForBit) {
  // The reference is the lecture's recursion evaluated here, straight from primaryRay through
  // the pixel centre with the pixel index as seed: rt_whitted and rt_distributed share one code
  // path, so comparing the two passes with each other could not fail.
  for (const char* file : {"whitted.json", "cornell.json"}) {
    const Scene scene = sample(file);
    ASSERT_EQ(scene.camera.aperture, 0.f);
    const int w = 48, h = 36;
    const nlohmann::json p = {{"spp", 1}, {"depth", 5}, {"area_samples", 4}};
    const Frame f = render(scene, {pass("w", "rt_whitted", p), pass("d", "rt_distributed", p)},
                           {"w.color", "d.color"}, w, h);
    RenderWorld world(scene);
    const WhittedTracer tracer(scene, world.geometry(), world.rtScene(), {5, 4});
    int differing = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Ray ray = primaryRay(scene.camera, w, h, float(x) + 0.5f, float(y) + 0.5f);
        const vec3 expected = tracer.radiance(ray, 1, std::uint32_t(y * w + x));
        for (const char* name : {"w.color", "d.color"})
          for (int c = 0; c < 3; ++c) differing += f.outputs.at(name).f(x, y, c) != expected[c];
      }
    EXPECT_EQ(differing, 0) << file;
  }
}

// Antialiasing: with 16 samples (4 x 4 strata) the edge through the centre of column 32 splits
// the strata 8 : 8, so that pixel is 1/2 and its neighbours stay 1 and 0. A sample can land
// within Embree's float precision of the edge (2.6e-6 world units beyond it, for an edge of an
// 80-unit quad, was counted inside in one row), so a row may read 7/16 or 9/16; the average
// over the 49 rows must be 1/2 within 1/64.
TEST(RtDistributed, SixteenSamplesMakeTheEdgePixelFractional) {
  const Scene scene = loadScene(writeScene("edge.json", edgeScene(0.f, 5.f)));
  const Frame f =
      render(scene, {pass("d", "rt_distributed", {{"spp", 16}})}, {"d.color"}, kEdgeW, kEdgeH);
  const CpuImage& s = f.outputs.at("d.color");
  double sum = 0;
  int exactHalf = 0;
  for (int y = 0; y < kEdgeH; ++y) {
    EXPECT_EQ(s.f(31, y, 0), 1.f);
    EXPECT_NEAR(s.f(32, y, 0), 0.5f, 1.f / 16.f + 1e-6f) << "row " << y;
    EXPECT_EQ(s.f(33, y, 0), 0.f);
    sum += s.f(32, y, 0);
    exactHalf += s.f(32, y, 0) == 0.5f;
  }
  std::printf("edge pixel: mean %.5f over %d rows, %d rows exactly 1/2\n", sum / kEdgeH, kEdgeH,
              exactHalf);
  EXPECT_NEAR(sum / kEdgeH, 0.5, 1.0 / 64.0);
}

// Thin lens: a disc of radius a (aperture) focused at F blurs a point at depth D into a disc
// of radius a |D - F| / F in the plane at D; here a = 0.4, D = 5, F = 2.5: 0.4 world units,
// r = 0.4 * 49 / (2 * 5 * tan 22.5 deg) = 4.73 pixels. An edge convolved with a uniform disc
// rises from 10% to 90% over 2 * 0.6871 r = 6.50 pixels (0.6871 solves
// (acos a - a sqrt(1 - a^2)) / pi = 0.1). Focused at D = 5 the same lens leaves the edge sharp:
// only the pixel it crosses is fractional (10-90% width 1.6 pixels between pixel centres).
TEST(RtDistributed, ThinLensBlursAnEdgeOffFocusByTheCircleOfConfusion) {
  const nlohmann::json p = {{"spp", 256}, {"depth", 1}};
  const Scene sharp = loadScene(writeScene("edge-focused.json", edgeScene(0.4f, 5.f)));
  const Scene blurred = loadScene(writeScene("edge-blurred.json", edgeScene(0.4f, 2.5f)));
  const CpuImage inFocus =
      render(sharp, {pass("d", "rt_distributed", p)}, {"d.color"}, kEdgeW, kEdgeH)
          .outputs.at("d.color");
  const CpuImage outOfFocus =
      render(blurred, {pass("d", "rt_distributed", p)}, {"d.color"}, kEdgeW, kEdgeH)
          .outputs.at("d.color");
  const int y = kEdgeH / 2;
  const double sharpWidth = crossing(inFocus, y, 0.1f) - crossing(inFocus, y, 0.9f);
  const double blurWidth = crossing(outOfFocus, y, 0.1f) - crossing(outOfFocus, y, 0.9f);
  const double r = 0.4 * kEdgeH / (2.0 * 5.0 * std::tan(glm::radians(22.5)));
  std::printf("edge 10-90%% width: in focus %.3f px, out of focus %.3f px (disc model %.3f)\n",
              sharpWidth, blurWidth, 2 * 0.6871 * r);
  EXPECT_LE(sharpWidth, 1.61);
  EXPECT_EQ(inFocus.f(31, y, 0), 1.f);
  EXPECT_EQ(inFocus.f(33, y, 0), 0.f);
  EXPECT_NEAR(blurWidth, 2 * 0.6871 * r, 0.5);
  EXPECT_NEAR(outOfFocus.f(32, y, 0), 0.5f, 0.03f);  // the disc is symmetric about the edge
}

// White furnace: n = 256 samples per pixel, 32 x 24 pixels, Russian roulette from the third
// hit (max_depth 64 makes truncation negligible: the chance of reaching it is 2^-61 per path).
// A sample is 0.875 + B T, B ~ Bernoulli(1/8) (surviving roulette at q = 1/8) and T = G / 2
// with G geometric on {1, 2, ...} of parameter 1/2 (each later hit survives with q = 1/2 at
// throughput 1/2), so the exact per-sample variance is 1/8 * 3/2 - 1/64 = 0.171875 and sigma of
// a pixel mean 0.0259. Asserted: no NaN; every pixel within 5 sigma of 1, sigma from the
// variance output pooled over the image (a pixel's own variance estimate is unreliable for
// this skewed distribution: a pixel that drew few long paths reads both low and with a small
// variance, e.g. 0.934 with its own sigma 0.013); the image mean within 4 sigma_image; the
// pooled variance output within 5% of 0.171875 / n.
TEST(RtPath, WhiteFurnaceConvergesToOneEverywhere) {
  const Scene scene = loadScene(writeScene("furnace.json", kFurnace));
  const int w = 32, h = 24, n = 256;
  const Frame f =
      render(scene, {pass("p", "rt_path", {{"spp", n}, {"max_depth", 64}, {"rr_depth", 3}})},
             {"p.color", "p.variance"}, w, h);
  const CpuImage &color = f.outputs.at("p.color"), &variance = f.outputs.at("p.variance");
  ASSERT_TRUE(allFinite(color));
  ASSERT_TRUE(allFinite(variance));
  EXPECT_EQ(f.counters.at("p").at("invalid_samples"), 0.0);
  double sum = 0, sumVar = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      sum += color.f(x, y, 0);
      sumVar += variance.f(x, y, 0);
      EXPECT_EQ(variance.f(x, y, 3), float(n));
    }
  const double sigmaPixel = std::sqrt(sumVar / (w * h));
  double worst = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const double deviation = std::abs(color.f(x, y, c) - 1.0);
        EXPECT_LT(deviation, 5 * sigmaPixel) << x << "," << y;
        worst = std::max(worst, deviation / sigmaPixel);
      }
  const double pixels = w * h;
  const double mean = sum / pixels, sigmaImage = std::sqrt(sumVar) / pixels;
  const double meanVariance = sumVar / pixels * n;
  std::printf(
      "furnace: image mean %.5f, sigma_image %.5f, worst pixel %.2f sigma, per-sample "
      "variance %.5f (exact 0.171875)\n",
      mean, sigmaImage, worst, meanVariance);
  RecordProperty("furnace_mean", std::to_string(mean));
  EXPECT_LT(std::abs(mean - 1.0), 4 * sigmaImage);
  EXPECT_NEAR(meanVariance, 0.171875, 0.05 * 0.171875);
}

// The variance output predicts the spread of the mean across independent seeds: 8 seeds x
// 64 samples, 24 x 16 pixels. Summed over pixels, the empirical variance of the 8 means
// (unbiased, 7 degrees of freedom per pixel, 2688 in all) over the mean reported variance must
// be 1 within 0.2 (its standard deviation here is about 0.05).
TEST(RtPath, VarianceOutputMatchesTheSpreadAcrossSeeds) {
  const Scene scene = loadScene(writeScene("furnace.json", kFurnace));
  const int w = 24, h = 16, seeds = 8;
  std::vector<double> sum(w * h, 0.0), sumSq(w * h, 0.0);
  double reported = 0;
  for (int s = 0; s < seeds; ++s) {
    const Frame f = render(scene, {pass("p", "rt_path", {{"spp", 64}, {"seed", 1000 + s}})},
                           {"p.color", "p.variance"}, w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const double m = f.outputs.at("p.color").f(x, y, 1);
        sum[y * w + x] += m;
        sumSq[y * w + x] += m * m;
        reported += f.outputs.at("p.variance").f(x, y, 1);
      }
  }
  double empirical = 0;
  for (int i = 0; i < w * h; ++i) empirical += (sumSq[i] - sum[i] * sum[i] / seeds) / (seeds - 1);
  const double ratio = empirical / (reported / seeds);
  std::printf("empirical / reported variance of the mean: %.3f\n", ratio);
  EXPECT_NEAR(ratio, 1.0, 0.2);
}

// Russian roulette only reweights paths, so the expectation is unchanged: the Cornell box
// (24 x 24, n = 64 per pixel) with roulette from the third hit and without roulette (both cut
// at 64 hits) agree on the image mean of each channel within 4 sigma of the difference,
// sigma^2 = sum of both images' variance outputs / pixels^2. Roulette must also trace fewer rays.
TEST(RtPath, RussianRouletteIsUnbiased) {
  const Scene scene = sample("cornell.json");
  const int w = 24, h = 24;
  const Frame f =
      render(scene,
             {pass("rr", "rt_path", {{"spp", 64}, {"max_depth", 64}, {"russian_roulette", true}}),
              pass("full", "rt_path",
                   {{"spp", 64}, {"max_depth", 64}, {"russian_roulette", false}, {"seed", 7}})},
             {"rr.color", "rr.variance", "full.color", "full.variance"}, w, h);
  for (int c = 0; c < 3; ++c) {
    double a = 0, b = 0, va = 0, vb = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        a += f.outputs.at("rr.color").f(x, y, c);
        b += f.outputs.at("full.color").f(x, y, c);
        va += f.outputs.at("rr.variance").f(x, y, c);
        vb += f.outputs.at("full.variance").f(x, y, c);
      }
    const double pixels = w * h, sigma = std::sqrt(va + vb) / pixels;
    std::printf("channel %d: roulette %.5f, no roulette %.5f, sigma of difference %.5f\n", c,
                a / pixels, b / pixels, sigma);
    EXPECT_LT(std::abs(a - b) / pixels, 4 * sigma);
  }
  EXPECT_LT(f.counters.at("rr").at("rays"), f.counters.at("full").at("rays"));
}

// Next-event estimation against closed forms, one hit (max_depth 1), centre pixel of a
// diffuse plane (k_d C = 0.8) seen from straight above. Direct light is in the lecture's units
// (DIRECTA: k_d C max(0, n.l) S, no 1/pi), so that the path tracer equals rt_whitted where
// there is no indirect light:
//   point light I = 4 at height 2: S = I / 4 = 1, L = 0.8 (exactly rt_whitted's value);
//   disc light of radiance 1, radius 1, facing down at height 2: S = pi R^2 / (h^2 + R^2), so
//     L = 0.8 pi / 5;
//   sphere light of radiance 1, radius 1, centre at height 3: S = pi (R/d)^2, L = 0.8 pi / 9.
// Monte Carlo bound: 5 sigma of the pixel's variance output, n = 1024 (plus 1e-3 relative for
// the jitter over the pixel footprint).
TEST(RtPath, NextEventEstimationMatchesClosedForms) {
  struct Case {
    const char* light;
    double expected;
  };
  const Case cases[] = {
      {R"({"type": "point", "position": [0, 2, 0], "intensity": 4})", 0.8},
      {R"({"type": "disc", "position": [0, 2, 0], "normal": [0, -1, 0], "radius": 1})",
       0.8 * std::numbers::pi / 5},
      {R"({"type": "sphere", "position": [0, 3, 0], "radius": 1})", 0.8 * std::numbers::pi / 9},
  };
  for (const Case& k : cases) {
    const Scene scene = loadScene(writeScene("nee.json", std::string(R"({
      "camera": {"position": [0, 6, 0], "target": [0, 0, 0], "up": [0, 0, -1], "fov": 10},
      "materials": {"white": {"color": [0.8, 0.8, 0.8], "kd": 1}},
      "lights": [)") + k.light + R"(],
      "objects": [{"type": "plane", "size": [100, 100], "material": "white"}]})"));
    const Frame f = render(scene, {pass("p", "rt_path", {{"spp", 1024}, {"max_depth", 1}})},
                           {"p.color", "p.variance"}, 33, 33);
    const double m = f.outputs.at("p.color").f(16, 16, 0);
    const double sigma = std::sqrt(f.outputs.at("p.variance").f(16, 16, 0));
    std::printf("%s: L = %.5f +- %.5f, exact %.5f\n", k.light, m, sigma, k.expected);
    EXPECT_NEAR(m, k.expected, 5 * sigma + 1e-3 * k.expected) << k.light;
  }
}

// Progressive rendering: an unreachable spp with a 1 ms budget stops after whole passes, at
// least one, and records how many (counters and the variance alpha). No timing is asserted
// beyond "fewer than 2^20 passes of 256 paths fit into the time a test takes".
TEST(RtPath, TimeBudgetStopsEarlyAfterWholePasses) {
  const Scene scene = loadScene(writeScene("furnace.json", kFurnace));
  const Frame f = render(scene, {pass("p", "rt_path", {{"spp", 1 << 20}, {"time_budget_ms", 1}})},
                         {"p.color", "p.variance"}, 16, 16);
  const double passes = f.counters.at("p").at("passes");
  EXPECT_GE(passes, 1.0);
  EXPECT_LT(passes, double(1 << 20));
  EXPECT_EQ(f.counters.at("p").at("samples"), passes * 256);
  EXPECT_EQ(f.outputs.at("p.variance").f(7, 9, 3), float(passes));
  EXPECT_TRUE(allFinite(f.outputs.at("p.color")));

  const Frame full = render(scene, {pass("p", "rt_path", {{"spp", 3}})}, {"p.color"}, 16, 16);
  EXPECT_EQ(full.counters.at("p").at("passes"), 3.0);
  EXPECT_EQ(full.counters.at("p").at("samples"), 3.0 * 256);
}

// Without a time budget a pixel's paths run one after another; with one, pass by pass over the
// image. Both take the same samples per pixel (the same random sequences, in the same order for
// the running mean), so the images agree up to the last bits in which Embree's stream kernels
// may round a camera ray's hit differently in the two orders' chunks. A sample taken from
// another pixel's or pass's sequence would differ by the noise of 3 paths, far above that.
TEST(RtPath, PixelByPixelEqualsPassByPass) {
  const Scene scene = sample("cornell.json");
  auto once = [&](double budgetMs) {
    return render(scene, {pass("p", "rt_path", {{"spp", 3}, {"time_budget_ms", budgetMs}})},
                  {"p.color", "p.variance"}, 24, 18);
  };
  const Frame pixelMajor = once(0.0), passMajor = once(1e9);
  ASSERT_EQ(passMajor.counters.at("p").at("passes"), 3.0);
  EXPECT_EQ(pixelMajor.counters.at("p").at("samples"), passMajor.counters.at("p").at("samples"));
  for (const char* out : {"p.color", "p.variance"}) {
    const CpuImage &a = pixelMajor.outputs.at(out), &b = passMajor.outputs.at(out);
    int apart = 0;
    for (int y = 0; y < 18; ++y)
      for (int x = 0; x < 24; ++x)
        for (int ch = 0; ch < 4; ++ch)
          apart +=
              std::abs(a.f(x, y, ch) - b.f(x, y, ch)) > 1e-5f * (1.f + std::abs(b.f(x, y, ch)));
    // A last-bit difference may flip a Russian roulette draw: a pixel or two, not a pattern.
    EXPECT_LE(apart, 4) << out;
  }
}

// The wavefront (PathTracer::radiance over a chunk: each level's hits and shadow rays as Embree
// streams) against one path at a time, given the same camera hits: the same samples bit for bit
// on the samples that have area, point, spot and directional lights, glass, mirrors, volumes and
// textures (ray cones on). Bounce rays go to Embree's incoherent streams and shadow rays only
// answer "occluded"; should a future Embree round a stream's hit differently, this test says
// where (a chunk that mixed up its paths' slots, random numbers or terms differs everywhere).
TEST(RtPath, WavefrontEqualsPathByPath) {
  for (const char* file : {"cornell.json", "techniques.json", "whitted.json", "textures.json"}) {
    const Scene scene = sample(file);
    RenderWorld world(scene);
    const PathTracer tracer(scene, world.geometry(), world.rtScene(), {16, 3, true, true});
    const CameraRays camera{world.rtScene(), scene, world.geometry()};
    constexpr int kW = 24, kH = 18;
    const ThinLensFrame lens(scene.camera, kW, kH);
    std::vector<Ray> rays;
    std::vector<PathRng> rngs;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        PathRng rng{std::uint32_t(y * kW + x), 0u, 7u};
        const vec2 jitter = rng.next2(), lensPoint = rng.next2();
        rays.push_back(lens.ray(float(x) + jitter.x, float(y) + jitter.y, lensPoint));
        rngs.push_back(rng);
      }
    for (std::size_t begin = 0; begin < rays.size(); begin += PathTracer::kMaxPaths) {
      const std::size_t n = std::min(PathTracer::kMaxPaths, rays.size() - begin);
      std::vector<Hit> hits(n);
      std::vector<const Hit*> found(n);
      for (std::size_t i = 0; i < n; ++i)
        found[i] = camera.intersect(rays[begin + i], hits[i], false) ? &hits[i] : nullptr;
      std::vector<PathRng> chunkRngs(rngs.begin() + std::ptrdiff_t(begin),
                                     rngs.begin() + std::ptrdiff_t(begin + n));
      std::vector<PathSample> chunk(n);
      tracer.radiance({rays.data() + begin, n}, found, chunkRngs, 0.002f, chunk);
      for (std::size_t i = 0; i < n; ++i) {
        PathRng rng = rngs[begin + i];
        const PathSample one = tracer.radiance(rays[begin + i], rng, 0.002f);
        ASSERT_EQ(one.rays, chunk[i].rays) << file << " path " << begin + i;
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(one.radiance[c], chunk[i].radiance[c]) << file << " path " << begin + i;
        ASSERT_EQ(one.valid, chunk[i].valid);
      }
    }
  }
}

// Same seed, same image: the per-pixel sequences do not depend on the thread schedule.
TEST(RtPath, IsReproducible) {
  const Scene scene = sample("cornell.json");
  auto once = [&] {
    return render(scene, {pass("p", "rt_path", {{"spp", 2}})}, {"p.color"}, 20, 20)
        .outputs.at("p.color");
  };
  const CpuImage a = once(), b = once();
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) ASSERT_EQ(a.f(x, y, 0), b.f(x, y, 0));
}
}  // namespace DIPTYCH_UNITY_ID
