// The G-buffer's visibility variant (passes/raster/gbuffer.h): in a frame where no GL pass reads
// gbuffer.hits (the hybrid), the G-buffer writes (instance + 1, primitive, 0, 0) and the CPU
// passes compute (u, v) themselves along the pixel ray (exactTexel, passes/common/hits_texel.h).
// A frame with a GL reader keeps the per-fragment exact (u, v). The CPU passes' images do not
// depend on which variant ran, and their hits are the pixel ray's point of the named triangle.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "engine/graph/recipe.h"
#include "engine/rt/ray_triangle.h"
#include "passes/common/exact_hits.h"
#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

using namespace diptych;
using namespace diptych::testing;

namespace {

constexpr int kW = 160, kH = 120;

std::filesystem::path sample(const char* name) {
  return std::filesystem::path(samplesDir()) / "scenes" / name;
}

// Texels whose (u, v) channels are not both 0.
int texelsWithBarycentrics(const CpuImage& hits) {
  int n = 0;
  for (int y = 0; y < hits.desc.height; ++y)
    for (int x = 0; x < hits.desc.width; ++x)
      n += hits.u(x, y, 0) != 0u && (hits.u(x, y, 2) != 0u || hits.u(x, y, 3) != 0u);
  return n;
}

int covered(const CpuImage& hits) {
  int n = 0;
  for (int y = 0; y < hits.desc.height; ++y)
    for (int x = 0; x < hits.desc.width; ++x) n += hits.u(x, y, 0) != 0u;
  return n;
}

}  // namespace

TEST(VisibilityGBuffer, TheHybridFrameRastersAVisibilityBuffer) {
  auto f = renderHybridFrame(sample("whitted.json"), kW, kH, {"shade.color", "gbuffer.hits"});
  ASSERT_NE(f->pass("gbuffer"), nullptr);
  // Requesting the hits as an output does not make the G-buffer compute (u, v).
  EXPECT_EQ(f->pass("gbuffer")->variant.rfind("visibility buffer", 0), 0u)
      << f->pass("gbuffer")->variant;
  const CpuImage& hits = f->output("gbuffer.hits");
  EXPECT_GT(covered(hits), kW * kH / 2);
  EXPECT_EQ(texelsWithBarycentrics(hits), 0);
}

TEST(VisibilityGBuffer, ARasterFrameKeepsThePerFragmentBarycentrics) {
  const Recipe raster = loadRecipe(std::filesystem::path(samplesDir()) / "graphs/raster.json");
  auto f = renderHybridFrame(sample("whitted.json"), kW, kH, {"shade.color", "gbuffer.hits"},
                             raster);
  EXPECT_EQ(f->pass("gbuffer")->variant.rfind("exact hits: a GL pass reads the hits", 0), 0u)
      << f->pass("gbuffer")->variant;
  const CpuImage& hits = f->output("gbuffer.hits");
  // Almost every covered texel: a vertex hit exactly has (u, v) = (0, 0).
  EXPECT_GT(texelsWithBarycentrics(hits), covered(hits) * 99 / 100);
}

// The same hybrid frame with a GL reader of the hits added (shade_gl), so that its G-buffer
// computes (u, v) per fragment: the CPU passes ignore them, and shade_cpu is bit-identical to
// the visibility-buffer frame's shade.
TEST(VisibilityGBuffer, TheCpuPassesImagesDoNotDependOnTheVariant) {
  for (const char* scene : {"whitted.json", "cornell.json", "textures.json"}) {
    auto visibility = renderHybridFrame(sample(scene), kW, kH, {"shade.color"});
    auto exact = renderHybridFrame(sample(scene), kW, kH, {},
                                   withShadeInBothDomains(defaultHybridRecipe()));
    ASSERT_EQ(visibility->pass("gbuffer")->variant.rfind("visibility", 0), 0u) << scene;
    ASSERT_EQ(exact->pass("gbuffer")->variant.rfind("exact hits", 0), 0u) << scene;
    ASSERT_GT(texelsWithBarycentrics(exact->output("gbuffer.hits")), 0) << scene;
    const CpuImage& a = visibility->output("shade.color");
    const CpuImage& b = exact->output("shade_cpu.color");
    ASSERT_EQ(a.words.size(), b.words.size());
    EXPECT_TRUE(a.words == b.words) << scene << ": the CPU shade differs between the variants";
  }
}

// Every triangle texel's exact hit has the barycentrics of the pixel-centre ray (the ray the
// Whitted reference traces) through the named triangle, computed by the C++ twin of the GLSL;
// where Embree's primary ray hits the same triangle, the two points agree to float rounding.
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
        if (!rt || rt->analytic || rt->instance != hit->instance ||
            rt->primitive != hit->primitive)
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
