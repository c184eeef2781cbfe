// Back-face culling of closed meshes in the G-buffer (engine/gl/closed_mesh.h,
// GBufferRasterizer::cullClosed):
//  - isClosedOutward accepts a closed, outward-wound solid (a cube, the samples' UV spheres with
//    their degenerate pole triangles) and refuses a reversed, open, doubled or mis-wound one;
//  - the G-buffer with culling is the G-buffer without, bit for bit, from the scene camera, from
//    a camera near a sphere, from one inside a sphere and from one nearer a sphere than the near
//    plane, where culling is off (the eye is inside its bounds, or the near plane could clip its
//    front faces) and the view shows the sphere's inside.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "engine/gl/closed_mesh.h"
#include "engine/gl/gbuffer_raster.h"
#include "engine/gl/transfer.h"
#include "engine/graph/render_world.h"
#include "engine/scene/load.h"
#include "gl_test_context.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// The unit cube, counter-clockwise seen from outside.
std::vector<vec3> cubeCorners() {
  std::vector<vec3> p;
  for (int i = 0; i < 8; ++i) p.push_back(vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  return p;
}
std::vector<std::uint32_t> cubeTriangles() {
  return {0, 2, 3, 0, 3, 1,   // z = 0, normal -z
          4, 5, 7, 4, 7, 6,   // z = 1, +z
          0, 1, 5, 0, 5, 4,   // y = 0, -y
          2, 6, 7, 2, 7, 3,   // y = 1, +y
          0, 4, 6, 0, 6, 2,   // x = 0, -x
          1, 3, 7, 1, 7, 5};  // x = 1, +x
}

TEST(ClosedMesh, ACubeIsClosedOutwardItsVariantsAreNot) {
  const std::vector<vec3> p = cubeCorners();
  std::vector<std::uint32_t> t = cubeTriangles();
  EXPECT_TRUE(gl::isClosedOutward(p, t));

  std::vector<std::uint32_t> reversed = t;
  for (std::size_t i = 0; i < reversed.size(); i += 3) std::swap(reversed[i + 1], reversed[i + 2]);
  EXPECT_FALSE(gl::isClosedOutward(p, reversed)) << "inward faces";

  std::vector<std::uint32_t> open(t.begin(), t.end() - 3);
  EXPECT_FALSE(gl::isClosedOutward(p, open)) << "a missing triangle leaves a border";

  std::vector<std::uint32_t> doubled = t;
  doubled.insert(doubled.end(), t.begin(), t.begin() + 3);
  EXPECT_FALSE(gl::isClosedOutward(p, doubled)) << "an edge used twice in one direction";

  std::vector<std::uint32_t> misWound = t;
  std::swap(misWound[1], misWound[2]);
  EXPECT_FALSE(gl::isClosedOutward(p, misWound)) << "one triangle wound the other way";

  // The same corners as separate vertices per face (split normals) are still one solid; a
  // degenerate triangle (two equal corners) is left out.
  std::vector<vec3> split;
  std::vector<std::uint32_t> splitTriangles;
  for (std::uint32_t i : t) {
    splitTriangles.push_back(std::uint32_t(split.size()));
    split.push_back(p[i]);
  }
  split.push_back(p[0]);
  splitTriangles.insert(splitTriangles.end(), {std::uint32_t(split.size() - 1), 0u, 1u});
  EXPECT_TRUE(gl::isClosedOutward(split, splitTriangles));

  std::vector<vec3> nan = p;
  nan[7].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(gl::isClosedOutward(nan, t));
  EXPECT_FALSE(gl::isClosedOutward(p, {}));
}

// Each connected piece must be outward: a cube with a separate inside-out cube within passes the
// total-volume test (1 - 1/8 > 0) but culling would remove the near side of the inverted one.
// Far from the origin the weld grid and the volumes stay exact (cells from the mesh's own box).
TEST(ClosedMesh, EveryPieceMustBeOutwardAndFarMeshesAreJudgedAlike) {
  const std::vector<vec3> p = cubeCorners();
  const std::vector<std::uint32_t> t = cubeTriangles();
  std::vector<vec3> shell = p;
  std::vector<std::uint32_t> shellTriangles = t;
  for (const vec3& c : p) shell.push_back(0.25f + 0.5f * c);
  for (std::size_t i = 0; i < t.size(); i += 3)  // the inner cube, wound inward
    shellTriangles.insert(shellTriangles.end(), {t[i] + 8, t[i + 2] + 8, t[i + 1] + 8});
  EXPECT_FALSE(gl::isClosedOutward(shell, shellTriangles)) << "an inside-out piece";
  std::vector<std::uint32_t> twoOutward = t;
  for (std::uint32_t i : t) twoOutward.push_back(i + 8);
  std::vector<vec3> apart = p;
  for (const vec3& c : p) apart.push_back(c + vec3(3.f));
  EXPECT_TRUE(gl::isClosedOutward(apart, twoOutward)) << "two outward pieces";

  std::vector<vec3> far;
  for (const vec3& c : p) far.push_back(vec3(1e5f) + 0.3f * c);
  EXPECT_TRUE(gl::isClosedOutward(far, t));
  std::vector<vec3> unusedFar = p;
  unusedFar.push_back(vec3(3e38f));  // a vertex no triangle uses
  EXPECT_TRUE(gl::isClosedOutward(unusedFar, t));
}

TEST(ClosedMesh, EyeOutsideBoundsIsStrictAndKeepsTheNearPlaneClear) {
  EXPECT_TRUE(gl::outsideBounds(vec3(2.f, 0.5f, 0.5f), vec3(0.f), vec3(1.f)));
  EXPECT_FALSE(gl::outsideBounds(vec3(0.5f), vec3(0.f), vec3(1.f)));
  EXPECT_FALSE(gl::outsideBounds(vec3(1.f, 0.5f, 0.5f), vec3(0.f), vec3(1.f))) << "on the box";
  EXPECT_FALSE(gl::outsideBounds(vec3(1.01f, 0.5f, 0.5f), vec3(0.f), vec3(1.f), 0.05f))
      << "the near plane could clip the front faces";
  EXPECT_TRUE(gl::outsideBounds(vec3(1.1f, 0.5f, 0.5f), vec3(0.f), vec3(1.f), 0.05f));
  // 90 degrees, square: the corners of the near rectangle are znear sqrt(3) away.
  EXPECT_FLOAT_EQ(gl::nearPlaneReach(0.1f, 1.5707964f, 1.f), 0.1f * std::sqrt(3.f));
}

Scene whitted() {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
}

TEST(ClosedMesh, TheSampleSpheresAreClosedThePlaneIsNot) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  int closed = 0;
  for (const gl::GlMeshRange& m : world.glScene().meshes) closed += m.closedOutward ? 1 : 0;
  EXPECT_EQ(closed, 2);  // the two 128 x 64 spheres; the floor is one open quad
}

// G-buffer hits of `camera`, with and without culling; `culled`: meshes drawn culled.
std::vector<std::uint32_t> hitsOf(RenderWorld& world, const Camera& camera, bool cull,
                                  int& culled) {
  auto& raster = world.glCached<gl::GBufferRasterizer>();
  raster.cullClosed = cull;
  gl::GBufferTextures t = gl::GBufferTextures::allocate(160, 120);
  raster.render(world.glScene(), camera, gl::GBufferTargets{.hits = &t.hits, .depth = &t.depth},
                &world.glShading());
  culled = raster.culledMeshes();
  return gl::readTexture(t.hits);
}

// Fragments that passed the depth test over one G-buffer render (GL_SAMPLES_PASSED).
std::uint64_t samplesPassed(RenderWorld& world, const Camera& camera, bool cull) {
  auto& raster = world.glCached<gl::GBufferRasterizer>();
  raster.cullClosed = cull;
  gl::GBufferTextures t = gl::GBufferTextures::allocate(160, 120);
  GLuint query = 0;
  gl::glCreateQueries(GL_SAMPLES_PASSED, 1, &query);
  gl::glBeginQuery(GL_SAMPLES_PASSED, query);
  raster.render(world.glScene(), camera, gl::GBufferTargets{.hits = &t.hits, .depth = &t.depth},
                &world.glShading());
  gl::glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 samples = 0;
  gl::glGetQueryObjectui64v(query, GL_QUERY_RESULT, &samples);
  gl::glDeleteQueries(1, &query);
  return samples;
}

// Culling is really on (the hits alone would be equal with it never enabled): back faces drawn
// before the front faces that hide them pass the depth test, and culled they are never drawn.
TEST(GBufferCulling, CulledBackFacesDrawFewerFragments) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const std::uint64_t culled = samplesPassed(world, scene.camera, true);
  const std::uint64_t all = samplesPassed(world, scene.camera, false);
  EXPECT_GT(culled, 0u);
  EXPECT_LT(culled, all);
}

TEST(GBufferCulling, TheHitsAreTheSameWithAndWithoutCulling) {
  const Scene scene = whitted();
  RenderWorld world(scene, &gl::testing::osmesaContext());
  const int glass = 2;  // the glass sphere's instance, centre (-0.5, 1, 1), radius 0.8
  Camera near = scene.camera;
  near.position = vec3(-0.5f, 1.2f, 2.3f);  // 1.3 from the centre: outside its bounds
  near.target = vec3(-0.5f, 1.f, 1.f);
  Camera inside = near;
  inside.position = vec3(-0.5f, 1.1f, 1.2f);  // inside the sphere
  inside.target = vec3(-0.5f, 1.f, 0.f);
  // 0.01 outside the glass sphere's box (z = 1.8), nearer than the near plane (0.05): the
  // front faces are clipped and the back faces are what the G-buffer sees; culling must be off.
  Camera clipped = near;
  clipped.position = vec3(-0.5f, 1.f, 1.81f);
  clipped.target = vec3(-0.5f, 1.f, 0.f);
  clipped.znear = 0.05f;
  struct Case {
    const char* name;
    Camera camera;
    int culled;
  };
  for (const Case& c : {Case{"scene", scene.camera, 2}, Case{"near", near, 2},
                        Case{"inside", inside, 1}, Case{"near plane", clipped, 1}}) {
    SCOPED_TRACE(c.name);
    int culled = -1, notCulled = -1;
    const std::vector<std::uint32_t> with = hitsOf(world, c.camera, true, culled);
    const std::vector<std::uint32_t> without = hitsOf(world, c.camera, false, notCulled);
    EXPECT_EQ(culled, c.culled);
    EXPECT_EQ(notCulled, 0);
    EXPECT_EQ(with, without);
    long glassPixels = 0;
    for (std::size_t i = 0; i < with.size(); i += 4) glassPixels += with[i] == glass + 1 ? 1 : 0;
    // Inside, or with the front faces clipped by the near plane, every pixel sees the sphere's
    // inside (back faces): culling there would lose them.
    if (std::string(c.name) == "inside" || std::string(c.name) == "near plane")
      EXPECT_EQ(glassPixels, long(with.size() / 4));
    else
      EXPECT_GT(glassPixels, 500);
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
