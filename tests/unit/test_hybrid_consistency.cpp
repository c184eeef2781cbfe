// The hybrid frame's two halves must see the same world: every G-buffer texel rasterized by
// OpenGL (OSMesa) is compared with Embree's closest hit for the same pixel-centre ray
// (diptych::primaryRay), on the sample scenes, through the real frame graph.
//
// Ids: a pixel agrees when both name the same (instance, primitive), or both miss. Pixels where
// raster and ray tracing legitimately differ are the ones whose centre lies within rounding of
// a shared triangle edge (rasterization's top-left rule vs Embree's watertight test), so a tiny
// fraction may differ; the bound is 99.9 %.
//
// Positions: for agreeing pixels, the point rebuilt from the G-buffer's (u, v) with
// interpolatePosition is compared with the point rebuilt from Embree's (u, v). The G-buffer
// shader intersects the pixel-centre ray itself (docs/gl.md), so both are the same computation in
// float and must agree to 1e-5 relative. Norm (Euclidean):
//   |p_gl - p_rt| / max(|p_rt|, m) <= 1e-5,   m = max_i |p_i| over the triangle's vertices.
// Why not |p_rt| alone: p = (1-u-v) p0 + u p1 + v p2 is rounded at the scale of the vertices, not
// of p (the same reason engine/rt/ray_offset.h uses vertexMagnitude). Measured on whitted.json:
// a floor point at |p| = 0.024 on the 20 x 20 plane (vertices at |p_i| = 14) differs by 6e-5 |p|
// between GL and Embree, and Embree itself is 1.2e-5 |p| away from a double-precision
// intersection there; relative to m both are below 1e-7. Away from such points the two
// denominators differ by a small factor (Cornell: |p| ~ 300 .. 800, m <= 790).
// Embree's own ray point o + t d is checked too, scaled by max(|o + t d|, m, |o|), since
// o + t d is also rounded at the scale of the camera position o.
//
// Grazing hits: a ray meeting a triangle at angle theta to its plane (cos = |n . d|) fixes the
// point along the ray only to (rounding) / cos, in any float ray-triangle test. So the 1e-5
// bound applies as stated where cos >= 0.1, and below it grows as 0.1 / cos, i.e.
// err * cos <= 1e-6 (a few float ULPs before amplification). Measured on whitted.json at 640x480:
// 16 silhouette pixels of the spheres exceed 5e-6, the worst 3.3e-5 at cos = 0.017 (Embree vs a
// double-precision intersection: 4e-6 there); err * cos <= 5.5e-7 everywhere.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "passes/common/hits_texel.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

struct Agreement {
  long pixels = 0, covered = 0, idMismatches = 0, compared = 0;
  long notComputed = 0;  // texels whose (u, v) the G-buffer left NaN (a visibility buffer)
  long nanPoints = 0;    // compared points that came out NaN (must be none: max() drops NaN)
  double maxRelativeError = 0.0;     // G-buffer point vs Embree's barycentric point
  double maxRelativeErrorRay = 0.0;  // G-buffer point vs o + t d
  double maxRelativeToP = 0.0;       // G-buffer vs Embree point, divided by |p_rt| only
  double maxNonGrazing = 0.0;        // maxRelativeError over hits with |n . d| >= 0.1
  double maxConditioned = 0.0;       // max of relative error * |n . d|
  std::string worst;                 // where maxRelativeError occurred, for the message
  double agreement() const { return 1.0 - double(idMismatches) / double(pixels); }
};

// `outputs`: {"gbuffer.hits"} alone gives the exact G-buffer variant (GL writes (u, v)); with
// "shade.color" every reader of the hits is a CPU pass, so the frame's G-buffer is the
// visibility variant and (u, v) come from triangleTexel (alongRay, C++).
Agreement compareWithEmbree(const std::filesystem::path& file, int w, int h,
                            const std::vector<std::string>& outputs) {
  // Spheres as triangles in the visibility buffer too: the triangles are what this compares.
  auto frame = testing::renderHybridFrame(file, w, h, outputs,
                                          testing::withoutImpostors(defaultHybridRecipe()));
  const CpuImage& vis = frame->output("gbuffer.hits");
  EXPECT_EQ(vis.desc.width, w);
  EXPECT_EQ(vis.desc.height, h);
  const WorldGeometry& geometry = frame->world->geometry();
  // The rasterizer draws the tessellation of analytic shapes; compare it with Embree on the
  // same triangles (the exact side is checked in test_reference_consistency.cpp).
  RtDevice device;
  const RtScene rt(device, geometry, frame->scene, {.analytic = false});
  const Camera& camera = frame->graph.frame.camera;
  const PinholeFrame pinhole(camera, w, h);

  Agreement a;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      ++a.pixels;
      const Ray ray = primaryRay(camera, w, h, x + 0.5f, y + 0.5f);
      const auto raw = hitsTexel(vis, x, y);
      if (raw && std::isnan(raw->u)) ++a.notComputed;
      const auto gl = triangleTexel(vis, geometry, pinhole, x, y);
      const auto hit = rt.intersect(ray, 0.f, std::numeric_limits<float>::infinity());
      if (gl) ++a.covered;
      if (bool(gl) != bool(hit) ||
          (gl && (gl->instance != hit->instance || gl->primitive != hit->primitive))) {
        ++a.idMismatches;
        continue;
      }
      if (!gl) continue;
      ++a.compared;
      const WorldMesh& mesh = geometry.meshes.at(std::size_t(gl->instance));
      const vec3 pGl = interpolatePosition(mesh, gl->primitive, gl->u, gl->v);
      const vec3 pRt = interpolatePosition(mesh, hit->primitive, hit->u, hit->v);
      const vec3 pRay = ray.origin + hit->t * ray.direction;
      if (!std::isfinite(pGl.x + pGl.y + pGl.z)) {
        ++a.nanPoints;
        continue;
      }
      const std::uint32_t* tri = &mesh.indices.at(3 * std::size_t(gl->primitive));
      const double m = std::max({glm::length(glm::dvec3(mesh.positions[tri[0]])),
                                 glm::length(glm::dvec3(mesh.positions[tri[1]])),
                                 glm::length(glm::dvec3(mesh.positions[tri[2]]))});
      const double diff = glm::length(glm::dvec3(pGl) - glm::dvec3(pRt));
      const double err = diff / std::max(glm::length(glm::dvec3(pRt)), m);
      const double cosine =
          std::abs(double(glm::dot(geometricNormal(mesh, gl->primitive), ray.direction)));
      a.maxConditioned = std::max(a.maxConditioned, err * cosine);
      if (cosine >= 0.1) a.maxNonGrazing = std::max(a.maxNonGrazing, err);
      const double errRay =
          glm::length(glm::dvec3(pGl) - glm::dvec3(pRay)) /
          std::max({glm::length(glm::dvec3(pRay)), m, glm::length(glm::dvec3(ray.origin))});
      // The plain |p_rt| denominator, reported (not asserted), for comparison.
      a.maxRelativeToP = std::max(a.maxRelativeToP, diff / glm::length(glm::dvec3(pRt)));
      if (err > a.maxRelativeError) {
        a.maxRelativeError = err;
        char buf[160];
        std::snprintf(buf, sizeof buf, "pixel (%d, %d), instance %d, primitive %u", x, y,
                      gl->instance, gl->primitive);
        a.worst = buf;
      }
      a.maxRelativeErrorRay = std::max(a.maxRelativeErrorRay, errRay);
    }
  }
  return a;
}

void checkScene(const std::string& name, int w, int h, bool visibility = false) {
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / name;
  const Agreement a =
      compareWithEmbree(file, w, h,
                        visibility ? std::vector<std::string>{"shade.color", "gbuffer.hits"}
                                   : std::vector<std::string>{"gbuffer.hits"});
  // Which variant ran: the exact one writes every (u, v); the visibility one none (these scenes
  // have no alpha-tested mesh).
  if (visibility)
    EXPECT_EQ(a.notComputed, a.covered) << name;
  else
    EXPECT_EQ(a.notComputed, 0) << name;
  // std::max and `err > max` drop NaN: a NaN point would pass every bound below unseen.
  EXPECT_EQ(a.nanPoints, 0) << name;
  EXPECT_GE(a.compared, a.covered - a.idMismatches) << name;
  EXPECT_GE(double(a.compared), 0.999 * double(a.covered)) << name;
  std::printf(
      "[hybrid consistency] %s %dx%d: covered %ld/%ld, id agreement %.6f (%ld mismatches), "
      "max |p_gl - p_rt| / max(|p_rt|, m) = %.3g (vs o + t d: %.3g) at %s; "
      "max |p_gl - p_rt| / |p_rt| = %.3g; where |n.d| >= 0.1: %.3g; max err * |n.d| = %.3g\n",
      name.c_str(), w, h, a.covered, a.pixels, a.agreement(), a.idMismatches, a.maxRelativeError,
      a.maxRelativeErrorRay, a.worst.c_str(), a.maxRelativeToP, a.maxNonGrazing, a.maxConditioned);
  ::testing::Test::RecordProperty(name + ".agreement", std::to_string(a.agreement()));
  ::testing::Test::RecordProperty(name + ".max_relative_error", std::to_string(a.maxRelativeError));
  ::testing::Test::RecordProperty(name + ".max_relative_error_non_grazing",
                                  std::to_string(a.maxNonGrazing));
  // A scene that rendered nothing would agree trivially.
  EXPECT_GT(a.covered, a.pixels / 4) << name;
  EXPECT_GE(a.agreement(), 0.999) << name << ": " << a.idMismatches << " of " << a.pixels;
  EXPECT_LE(a.maxNonGrazing, 1e-5) << name;
  EXPECT_LE(a.maxConditioned, 1e-6) << name << " worst relative error at " << a.worst;
  EXPECT_LE(a.maxRelativeErrorRay, 1e-5) << name;
}

TEST(HybridConsistency, WhittedGBufferMatchesEmbreePrimaryRays) {
  checkScene("whitted.json", 640, 480);
}

TEST(HybridConsistency, CornellGBufferMatchesEmbreePrimaryRays) {
  checkScene("cornell.json", 640, 480);
}

// The hybrid's own G-buffer (shade reads the hits on the CPU: the visibility variant), with
// (u, v) computed in C++ along the same pixel ray: the same bounds hold.
TEST(HybridConsistency, WhittedVisibilityGBufferMatchesEmbreePrimaryRays) {
  checkScene("whitted.json", 640, 480, true);
}

TEST(HybridConsistency, CornellVisibilityGBufferMatchesEmbreePrimaryRays) {
  checkScene("cornell.json", 640, 480, true);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
