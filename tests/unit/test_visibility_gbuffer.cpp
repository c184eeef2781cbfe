// The G-buffer's visibility variant (passes/raster/gbuffer.h): in a frame where every reader of
// gbuffer.hits is a CPU pass (the hybrid), the G-buffer writes (instance + 1, primitive, NaN, NaN)
// and the CPU passes compute (u, v) themselves along the pixel ray (exactTexel,
// passes/common/hits_texel.h). A frame with a GL reader, or with no reader at all, keeps the
// per-fragment exact (u, v), and its CPU passes use them as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "engine/graph/recipe.h"
#include "engine/rt/ray_triangle.h"
#include "passes/common/exact_hits.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
using namespace diptych::testing;

constexpr int kW = 160, kH = 120;

std::filesystem::path sample(const char* name) {
  return std::filesystem::path(samplesDir()) / "scenes" / name;
}

struct TexelCounts {
  int covered = 0, withBarycentrics = 0;  // (u, v) not NaN
};

TexelCounts countTexels(const CpuImage& hits) {
  TexelCounts n;
  for (int y = 0; y < hits.desc.height; ++y)
    for (int x = 0; x < hits.desc.width; ++x)
      if (const auto hit = hitsTexel(hits, x, y)) {
        ++n.covered;
        n.withBarycentrics += !std::isnan(hit->u) && !std::isnan(hit->v);
      }
  return n;
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

double relativeRmse(const CpuImage& a, const CpuImage& b) {
  double num = 0, den = 0;
  for (int y = 0; y < a.desc.height; ++y)
    for (int x = 0; x < a.desc.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = double(a.f(x, y, c)) - double(b.f(x, y, c));
        num += d * d;
        den += double(b.f(x, y, c)) * double(b.f(x, y, c));
      }
  return std::sqrt(num / den);
}

TEST(VisibilityGBuffer, TheHybridFrameRastersAVisibilityBuffer) {
  // Requesting the hits as an output beside the CPU readers (as compare does) changes nothing.
  auto f = renderHybridFrame(sample("whitted.json"), kW, kH, {"shade.color", "gbuffer.hits"});
  ASSERT_NE(f->pass("gbuffer"), nullptr);
  EXPECT_TRUE(startsWith(f->pass("gbuffer")->variant, "visibility buffer"))
      << f->pass("gbuffer")->variant;
  const TexelCounts n = countTexels(f->output("gbuffer.hits"));
  EXPECT_GT(n.covered, kW * kH / 2);
  EXPECT_EQ(n.withBarycentrics, 0);
}

TEST(VisibilityGBuffer, AFrameWithAGlReaderOrNoReaderKeepsThePerFragmentBarycentrics) {
  const Recipe raster = loadRecipe(std::filesystem::path(samplesDir()) / "graphs/raster.json");
  auto f =
      renderHybridFrame(sample("whitted.json"), kW, kH, {"shade.color", "gbuffer.hits"}, raster);
  EXPECT_TRUE(startsWith(f->pass("gbuffer")->variant, "exact hits"));
  EXPECT_NE(f->pass("gbuffer")->variant.find("a GL pass reads the hits"), std::string::npos)
      << f->pass("gbuffer")->variant;
  TexelCounts n = countTexels(f->output("gbuffer.hits"));
  EXPECT_GT(n.covered, kW * kH / 2);
  EXPECT_EQ(n.withBarycentrics, n.covered);
  // The G-buffer alone (being inspected): nobody computes (u, v) on the CPU, so GL does.
  auto alone = renderHybridFrame(sample("whitted.json"), kW, kH, {"gbuffer.hits"});
  EXPECT_NE(alone->pass("gbuffer")->variant.find("no CPU pass reads the hits"), std::string::npos)
      << alone->pass("gbuffer")->variant;
  n = countTexels(alone->output("gbuffer.hits"));
  EXPECT_EQ(n.withBarycentrics, n.covered);
}

// The same hybrid frame with a GL reader of the hits added (shade_gl), so that its G-buffer
// computes (u, v) per fragment and the CPU passes use them: the variant moves the CPU shade by
// rounding only (GL's (u, v) and the C++ twin's round differently, docs/gl.md).
// The spheres as triangles in both (impostors false): the exact G-buffer draws triangles.
TEST(VisibilityGBuffer, TheVariantMovesTheHybridImageByRoundingOnly) {
  for (const char* scene : {"whitted.json", "cornell.json", "textures.json"}) {
    auto visibility = renderHybridFrame(sample(scene), kW, kH, {"shade.color", "gbuffer.hits"},
                                        withoutImpostors(defaultHybridRecipe()));
    auto exact =
        renderHybridFrame(sample(scene), kW, kH, {}, withShadeInBothDomains(defaultHybridRecipe()));
    ASSERT_TRUE(startsWith(visibility->pass("gbuffer")->variant, "visibility")) << scene;
    ASSERT_TRUE(startsWith(exact->pass("gbuffer")->variant, "exact hits")) << scene;
    const double e =
        relativeRmse(visibility->output("shade.color"), exact->output("shade_cpu.color"));
    std::printf("%s: visibility against exact G-buffer, CPU shade relative RMSE %.3g\n", scene, e);
    // What proves the variant ran (a zero difference would not be wrong: llvmpipe may round as
    // the C++ twin does): GL left (u, v) NaN on every covered texel (no alpha-tested mesh here).
    const TexelCounts n = countTexels(visibility->output("gbuffer.hits"));
    EXPECT_GT(n.covered, 0) << scene;
    EXPECT_EQ(n.withBarycentrics, 0) << scene;
    EXPECT_LT(e, 1e-5) << scene;
  }
}

TEST(VisibilityGBuffer, ExactHitsAreThePixelRaysPointOnTheNamedTriangle) {
  for (const char* scene : {"whitted.json", "cornell.json", "techniques.json"}) {
    auto f = renderHybridFrame(sample(scene), kW, kH, {"shade.color", "gbuffer.hits"});
    const CpuImage& hits = f->output("gbuffer.hits");
    const Camera camera = cameraOf(f->scene);
    const WorldGeometry& geometry = f->world->geometry();
    const ExactHitBuffer& exact = exactHits(*f->world, hits, camera);
    int triangles = 0, sameAsEmbree = 0;
    double worst = 0;  // |p - p_embree| / t_embree
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const auto hit = exact.at(x, y);
        if (!hit || hit->analytic) continue;
        // A sphere impostor's texel that missed the sphere: the pixel's traced hit (Embree's
        // (u, v)), which ImpostorsGiveEverySpherePixelThePixelRaysOwnHit checks.
        if (hitsTexel(hits, x, y)->primitive == kImpostorPrimitive) continue;
        const WorldMesh& mesh = geometry.meshes[std::size_t(hit->instance)];
        if (mesh.analytic) continue;  // a lift that fell back to the tessellation
        ++triangles;
        const Ray ray = primaryRay(camera, kW, kH, x + 0.5f, y + 0.5f);
        const std::uint32_t* i = &mesh.indices[3 * std::size_t(hit->primitive)];
        vec2 uv;
        ASSERT_TRUE(rayTriangleBarycentrics(ray.origin, ray.direction, mesh.positions[i[0]],
                                            mesh.positions[i[1]], mesh.positions[i[2]], uv));
        ASSERT_EQ(hit->u, uv.x) << scene << " pixel " << x << "," << y;
        ASSERT_EQ(hit->v, uv.y) << scene << " pixel " << x << "," << y;
        const auto rt =
            f->world->rtScene().intersect(ray, 0.f, std::numeric_limits<float>::infinity());
        if (!rt || rt->analytic || rt->instance != hit->instance || rt->primitive != hit->primitive)
          continue;
        ++sameAsEmbree;
        const vec3 pe = interpolatePosition(mesh, rt->primitive, rt->u, rt->v);
        const vec3 p = interpolatePosition(mesh, hit->primitive, hit->u, hit->v);
        worst = std::max(worst, double(glm::length(p - pe)) / double(rt->t));
      }
    }
    std::printf("%s: %d triangle texels, %d on Embree's triangle, worst |p - p_embree| / t %.3g\n",
                scene, triangles, sameAsEmbree, worst);
    EXPECT_GT(triangles, kW * kH / 4) << scene;
    EXPECT_GT(sameAsEmbree, triangles * 99 / 100) << scene;
    EXPECT_LT(worst, 1e-4) << scene;
  }
}

// Analytic spheres as ray-cast impostors (engine/gl/gbuffer_raster.h): their texels name the
// sphere, not a triangle, and the exact-hit buffer built from them is the pixel rays' own
// closest hits, Embree's (whose sphere callback runs the same double-precision intersection)
// bit for bit on the spheres: no ring of pixels at the silhouette where a tessellation inscribed
// in the sphere misses it, and where the conservative test over-reports, the traced ray's hit.
TEST(VisibilityGBuffer, ImpostorsGiveEverySpherePixelThePixelRaysOwnHit) {
  for (const char* scene : {"whitted.json", "techniques.json"}) {
    auto f = renderHybridFrame(sample(scene), kW, kH, {"shade.color", "gbuffer.hits"});
    EXPECT_NE(f->pass("gbuffer")->variant.find("ray-cast impostors"), std::string::npos)
        << f->pass("gbuffer")->variant;
    const CpuImage& hits = f->output("gbuffer.hits");
    const Camera camera = cameraOf(f->scene);
    const ExactHitBuffer& exact = exactHits(*f->world, hits, camera);
    int impostors = 0, sphere = 0;
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const auto texel = hitsTexel(hits, x, y);
        impostors += texel && texel->primitive == kImpostorPrimitive;
        const Ray ray = primaryRay(camera, kW, kH, x + 0.5f, y + 0.5f);
        const auto rt =
            f->world->rtScene().intersect(ray, 0.f, std::numeric_limits<float>::infinity());
        const auto hit = exact.at(x, y);
        const bool onSphere = rt && rt->analytic;
        ASSERT_EQ(hit && hit->analytic, onSphere) << scene << " pixel " << x << "," << y;
        if (!onSphere) continue;
        ++sphere;
        ASSERT_EQ(hit->instance, rt->instance) << scene << " pixel " << x << "," << y;
        ASSERT_EQ(hit->primitive, rt->primitive) << scene << " pixel " << x << "," << y;
        ASSERT_EQ(hit->u, rt->u) << scene << " pixel " << x << "," << y;
        ASSERT_EQ(hit->v, rt->v) << scene << " pixel " << x << "," << y;
      }
    }
    std::printf("%s: %d impostor texels, %d sphere pixels\n", scene, impostors, sphere);
    EXPECT_GT(sphere, 500) << scene;
    EXPECT_GE(impostors, sphere) << scene << ": every sphere pixel from an impostor";
  }
}

// A reader that needs the triangles (wag_shadows: its lit pieces are the tessellation's) keeps
// them, as does the "impostors" parameter set false.
TEST(VisibilityGBuffer, ImpostorsOnlyWhereNoReaderNeedsTheTriangles) {
  Recipe wag = defaultHybridRecipe();
  for (RecipePass& p : wag.passes)
    if (p.name == "shadows") p.type = "wag_shadows";
  for (const Recipe& recipe : {wag, withoutImpostors(defaultHybridRecipe())}) {
    auto f =
        renderHybridFrame(sample("whitted.json"), kW, kH, {"shade.color", "gbuffer.hits"}, recipe);
    const std::string& variant = f->pass("gbuffer")->variant;
    EXPECT_TRUE(startsWith(variant, "visibility buffer")) << variant;
    EXPECT_NE(variant.find("analytic spheres as triangles"), std::string::npos) << variant;
    const CpuImage& hits = f->output("gbuffer.hits");
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        if (const auto texel = hitsTexel(hits, x, y)) {
          ASSERT_NE(texel->primitive, kImpostorPrimitive) << variant;
        }
      }
    }
  }
}
}  // namespace DIPTYCH_UNITY_ID
