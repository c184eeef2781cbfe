// G-buffer raster against an analytic reference: each pixel-centre ray of diptych::primaryRay is
// intersected with every triangle in double precision (what Embree computes), and the G-buffer's
// ids, barycentrics, normals, materials and reversed-Z depth are checked against the nearest hit.
#include <gtest/gtest.h>

#include <bit>
#include <optional>

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/transfer.h"
#include "engine/scene/camera_math.h"
#include "gl_test_context.h"

namespace diptych::gl {
namespace DIPTYCH_UNITY_ID {

using glm::dvec3;

WorldMesh quad(int instance, int material, std::vector<vec3> corners, std::vector<vec3> normals) {
  WorldMesh m;
  m.instance = instance;
  m.material = material;
  m.positions = std::move(corners);
  m.normals = std::move(normals);
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

// A near quad drawn FIRST, clockwise as seen from the camera (culling must be off), in front of
// a tilted far quad (z = 0.3 x) with per-vertex normals that differ, so interpolation shows.
WorldGeometry twoQuads() {
  WorldGeometry g;
  const vec3 towards(0.f, 0.f, 1.f);
  g.meshes.push_back(
      quad(0, -1, {{-0.5f, -0.5f, 1.f}, {-0.5f, 0.6f, 1.f}, {1.f, 0.6f, 1.f}, {1.f, -0.5f, 1.f}},
           {towards, towards, towards, towards}));
  const vec3 n = glm::normalize(vec3(-0.3f, 0.f, 1.f));
  g.meshes.push_back(
      quad(1, 3, {{-2.f, -2.f, -0.6f}, {2.f, -2.f, 0.6f}, {2.f, 2.f, 0.6f}, {-2.f, 2.f, -0.6f}},
           {glm::normalize(n + vec3(0.2f, 0.f, 0.f)), glm::normalize(n + vec3(0.f, 0.3f, 0.f)), n,
            glm::normalize(n - vec3(0.f, 0.2f, 0.1f))}));
  return g;
}

struct ReferenceHit {
  int mesh;
  std::uint32_t primitive;
  double t, u, v;
  dvec3 point;
};

// Moller-Trumbore in double: the exact hit a ray tracer would find, and its barycentrics.
std::optional<ReferenceHit> traceReference(const WorldGeometry& g, const Ray& ray) {
  std::optional<ReferenceHit> best;
  const dvec3 o(ray.origin), d(ray.direction);
  for (std::size_t m = 0; m < g.meshes.size(); ++m) {
    const WorldMesh& mesh = g.meshes[m];
    for (std::uint32_t p = 0; p < mesh.indices.size() / 3; ++p) {
      const dvec3 p0(mesh.positions[mesh.indices[3 * p]]),
          p1(mesh.positions[mesh.indices[3 * p + 1]]), p2(mesh.positions[mesh.indices[3 * p + 2]]);
      const dvec3 e1 = p1 - p0, e2 = p2 - p0, pv = glm::cross(d, e2), s = o - p0;
      const double det = glm::dot(e1, pv);
      if (det == 0.0) continue;
      const double u = glm::dot(s, pv) / det, v = glm::dot(d, glm::cross(s, e1)) / det;
      const double t = glm::dot(e2, glm::cross(s, e1)) / det;
      if (u < 0 || v < 0 || u + v > 1 || t <= 0) continue;
      if (!best || t < best->t) best = ReferenceHit{int(m), p, t, u, v, o + t * d};
    }
  }
  return best;
}

// Distance in barycentric units to the nearest triangle edge: a pixel centre this close to an
// edge may fall to either neighbour in a rasterizer and in a ray tracer alike.
double edgeMargin(const ReferenceHit& h) {
  return std::min({h.u, h.v, 1.0 - h.u - h.v});
}

TEST(GBufferRaster, MatchesAnalyticPrimaryRays) {
  testing::osmesaContext();
  const std::uint64_t errors = glDebugErrorCount();
  const WorldGeometry geometry = twoQuads();
  const GlSceneBuffers scene = uploadScene(geometry);
  ASSERT_EQ(scene.triangleCount, 4u);
  Camera camera;
  camera.position = vec3(0.3f, 0.2f, 5.f);
  camera.target = vec3(0.f, 0.f, 0.f);
  camera.znear = 0.1f;
  const int w = 96, h = 64;
  GBufferTextures targets;
  rasterizeGBuffer(scene, camera, w, h, targets);
  const std::vector<std::uint32_t> vis = readTexture(targets.hits);
  const std::vector<float> nrm = readTextureFloats(targets.normal);
  const std::vector<float> depth = readTextureFloats(targets.depth);
  EXPECT_EQ(glDebugErrorCount(), errors);

  const vec3 forward = glm::normalize(camera.target - camera.position);
  int background = 0, hits = 0, nearHits = 0, idMismatches = 0, edgeSkips = 0;
  double worstPosition = 0, worstNormal = 0, worstDepth = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      const Ray ray = primaryRay(camera, w, h, x + 0.5f, y + 0.5f);
      const std::optional<ReferenceHit> ref = traceReference(geometry, ray);
      SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
      if (ref && edgeMargin(*ref) < 1e-4) {
        ++edgeSkips;
        continue;
      }
      if (!ref) {
        ++background;
        EXPECT_EQ(vis[4 * i], 0u);
        EXPECT_EQ(depth[i], 0.f);
        EXPECT_EQ(nrm[4 * i + 3], 0.f);
        continue;
      }
      ++hits;
      const WorldMesh& mesh = geometry.meshes[std::size_t(ref->mesh)];
      if (vis[4 * i] != std::uint32_t(mesh.instance + 1) || vis[4 * i + 1] != ref->primitive) {
        ++idMismatches;
        continue;
      }
      nearHits += ref->mesh == 0;
      const float u = std::bit_cast<float>(vis[4 * i + 2]),
                  v = std::bit_cast<float>(vis[4 * i + 3]);
      const dvec3 p(interpolatePosition(mesh, ref->primitive, u, v));
      worstPosition =
          std::max(worstPosition, glm::length(p - ref->point) / glm::length(ref->point));
      const vec3 expectedNormal =
          interpolateNormal(mesh, ref->primitive, float(ref->u), float(ref->v));
      worstNormal = std::max(
          worstNormal,
          double(glm::length(vec3(nrm[4 * i], nrm[4 * i + 1], nrm[4 * i + 2]) - expectedNormal)));
      EXPECT_EQ(nrm[4 * i + 3], float(mesh.material));
      // Reversed-Z: depth = near / -z_view, -z_view being the distance along the view axis.
      const double zView = glm::dot(ref->point - dvec3(camera.position), dvec3(forward));
      const double expectedDepth = camera.znear / zView;
      worstDepth = std::max(worstDepth, std::abs(depth[i] - expectedDepth) / expectedDepth);
    }
  }
  EXPECT_EQ(idMismatches, 0);
  EXPECT_LE(edgeSkips, w * h / 50) << "too many pixels near edges for a meaningful test";
  EXPECT_GT(background, 0);
  EXPECT_GT(nearHits, 100) << "the near quad must win over the far one";
  EXPECT_GT(hits - nearHits, 100);
  EXPECT_LE(worstPosition, 1e-5);
  EXPECT_LE(worstNormal, 1e-5);
  EXPECT_LE(worstDepth, 1e-5);
  RecordProperty("worst_position_relative_error", std::to_string(worstPosition));
}

TEST(GBufferRaster, ReusedRasterizerHandlesResizeAndEmptyScenes) {
  testing::osmesaContext();
  GBufferRasterizer rasterizer;
  const GlSceneBuffers empty = uploadScene(WorldGeometry{});
  GBufferTextures targets = GBufferTextures::allocate(8, 4);
  rasterizer.render(empty, Camera{}, targets);
  for (std::uint32_t word : readTexture(targets.hits)) EXPECT_EQ(word, 0u);

  const GlSceneBuffers scene = uploadScene(twoQuads());
  targets = GBufferTextures::allocate(5, 7);
  rasterizer.render(scene, Camera{}, targets);
  // The middle of the image sees the near quad (instance 0, default material -1).
  const std::vector<std::uint32_t> vis = readTexture(targets.hits);
  const std::vector<float> nrm = readTextureFloats(targets.normal);
  const std::size_t centre = 3 * 5 + 2;
  EXPECT_EQ(vis[4 * centre], 1u);
  EXPECT_EQ(nrm[4 * centre + 3], -1.f);

  GBufferTextures wrong;
  wrong.hits = Texture::create2D(TextureFormat::RGBA32F, 5, 7);
  wrong.normal = Texture::create2D(TextureFormat::RGBA32F, 5, 7);
  wrong.depth = Texture::create2D(TextureFormat::D32F, 5, 7);
  EXPECT_THROW(rasterizer.render(scene, Camera{}, wrong), Error);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych::gl
