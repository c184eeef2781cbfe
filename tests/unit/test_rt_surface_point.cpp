// CPU texture sampling (wrap modes, nearest/bilinear, checker) and shading points of hits.
#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/texture_sampling.h"
#include "tests/support/rt_test_geometry.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

// 2x2 RGBA: red, green / blue, white (row 0 is the top row, v = 0).
Image quadImage() {
  Image img(2, 2, 4, 1.f);
  const vec3 colors[4] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = colors[y * 2 + x][c];
  return img;
}

void expectNear(vec4 a, vec4 b) {
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(a[k], b[k], 1e-6f) << "channel " << k;
}

TEST(TextureSampling, WrapModesOnTexelIndices) {
  EXPECT_EQ(wrapTexel(5, 4, WrapMode::Repeat), 1);
  EXPECT_EQ(wrapTexel(-1, 4, WrapMode::Repeat), 3);
  EXPECT_EQ(wrapTexel(-1, 4, WrapMode::ClampToEdge), 0);
  EXPECT_EQ(wrapTexel(9, 4, WrapMode::ClampToEdge), 3);
  EXPECT_EQ(wrapTexel(4, 4, WrapMode::MirroredRepeat), 3);  // mirror image starts at the edge
  EXPECT_EQ(wrapTexel(7, 4, WrapMode::MirroredRepeat), 0);
  EXPECT_EQ(wrapTexel(-1, 4, WrapMode::MirroredRepeat), 0);
  EXPECT_EQ(wrapTexel(8, 4, WrapMode::MirroredRepeat), 0);
}

TEST(TextureSampling, BilinearHitsTexelCentresAndAveragesBetweenThem) {
  const Image img = quadImage();
  const WrapMode c = WrapMode::ClampToEdge, r = WrapMode::Repeat, m = WrapMode::MirroredRepeat;
  expectNear(sampleBilinear(img, {0.25f, 0.25f}, c, c), {1, 0, 0, 1});  // texel (0,0) centre
  expectNear(sampleBilinear(img, {0.75f, 0.75f}, c, c), {1, 1, 1, 1});
  expectNear(sampleBilinear(img, {0.5f, 0.25f}, c, c), {0.5f, 0.5f, 0, 1});
  expectNear(sampleBilinear(img, {0.5f, 0.5f}, c, c), {0.5f, 0.5f, 0.5f, 1});
  // Clamp: beyond the edge is the edge texel; repeat: the left column wraps to the right one.
  expectNear(sampleBilinear(img, {-3.f, 0.25f}, c, c), {1, 0, 0, 1});
  expectNear(sampleBilinear(img, {0.f, 0.25f}, r, r), {0.5f, 0.5f, 0, 1});
  expectNear(sampleBilinear(img, {1.25f, 0.25f}, r, r), sampleBilinear(img, {0.25f, 0.25f}, r, r));
  // Mirrored repeat: u = 1.25 reads u = 0.75.
  expectNear(sampleBilinear(img, {1.25f, 0.25f}, m, m), sampleBilinear(img, {0.75f, 0.25f}, m, m));
  expectNear(sampleBilinear(img, {-0.25f, 0.25f}, m, m), sampleBilinear(img, {0.25f, 0.25f}, m, m));
  // Huge and non-finite uv stay finite.
  const vec4 far = sampleBilinear(img, {1e20f, -1e20f}, r, m);
  EXPECT_TRUE(std::isfinite(far.x) && std::isfinite(far.w));
  const vec4 nan = sampleBilinear(img, {NAN, INFINITY}, r, c);
  EXPECT_TRUE(std::isfinite(nan.x));
}

TEST(TextureSampling, NearestWhenTheFilterSaysSo) {
  Texture t;
  t.image = quadImage();
  t.magFilter = FilterMode::Nearest;
  t.minFilter = FilterMode::LinearMipmapLinear;
  expectNear(sampleTexture(t, {0.49f, 0.2f}), {1, 0, 0, 1});
  expectNear(sampleTexture(t, {0.51f, 0.2f}), {0, 1, 0, 1});
  expectNear(sampleTexture(t, {0.5f, 0.25f}, /*minifying=*/true), {0.5f, 0.5f, 0, 1});
  expectNear(sampleTexture(Texture{}, {0.3f, 0.3f}), vec4(1.f));  // empty image: neutral
}

TEST(TextureSampling, CheckerAlternatesEveryOneOverScale) {
  const Checker c{vec3(1.f), vec3(0.f), 4.f};
  EXPECT_EQ(checkerColor(c, {0.1f, 0.1f}), vec3(1.f));
  EXPECT_EQ(checkerColor(c, {0.3f, 0.1f}), vec3(0.f));
  EXPECT_EQ(checkerColor(c, {0.3f, 0.3f}), vec3(1.f));
  EXPECT_EQ(checkerColor(c, {-0.1f, 0.1f}), vec3(0.f));  // floor(-0.4) = -1: odd
  EXPECT_EQ(checkerColor(c, {-0.1f, -0.1f}), vec3(1.f));
}

TEST(Surface, HitFromBehindFlipsNormalsAndResolvesTexturesAndChecker) {
  Scene scene = testgeo::sceneOf({testgeo::groundPlane(1.f), testgeo::groundPlane(1.f, 2.f)});
  Texture tex;
  tex.image = quadImage();
  tex.magFilter = FilterMode::Nearest;
  scene.textures.push_back(tex);
  Material textured;
  textured.color = vec3(0.5f);
  textured.colorTexture = 0;
  textured.emission = vec3(2.f);
  textured.emissionTexture = 0;
  Material checkered;
  checkered.checker = Checker{vec3(0.25f), vec3(0.75f), 2.f};
  scene.materials = {textured, checkered};
  scene.meshes[0].material = 0;
  scene.meshes[1].material = 1;
  const WorldGeometry world = flattenScene(scene);
  RtDevice device;
  RtScene rt(device, world);

  // Plane y = 0 (uv = ((x + 1) / 2, (z + 1) / 2)) seen from below at x = -0.5, z = 0.5.
  const Ray up{vec3(-0.5f, -1.f, 0.5f), vec3(0, 1, 0)};
  const auto hit = rt.intersect(up, 0.f, 1.5f);
  ASSERT_TRUE(hit);
  const SurfacePoint s =
      makeSurfacePoint(scene, world, {hit->instance, hit->primitive, hit->u, hit->v}, up.direction);
  EXPECT_EQ(s.hit.instance, 0);
  EXPECT_FALSE(s.frontFacing);
  EXPECT_EQ(s.faceNormal, vec3(0, 1, 0));
  EXPECT_EQ(s.geometricNormal, vec3(0, -1, 0));
  EXPECT_EQ(s.shadingNormal, vec3(0, -1, 0));
  EXPECT_NEAR(s.position.x, -0.5f, 1e-6f);
  EXPECT_NEAR(s.uv.x, 0.25f, 1e-6f);
  EXPECT_NEAR(s.uv.y, 0.75f, 1e-6f);
  // uv (0.25, 0.75): texel (0, 1), blue.
  EXPECT_EQ(s.resolved.color, vec3(0.f, 0.f, 0.5f));
  EXPECT_EQ(s.resolved.emission, vec3(0.f, 0.f, 2.f));
  EXPECT_EQ(s.positionMagnitude, vec3(1.f, 0.f, 1.f));

  // Plane y = 2 from above: front facing, checker replaces C (scale 2: cells of 0.5 in uv).
  const Ray down{vec3(0.6f, 5.f, -0.6f), vec3(0, -1, 0)};  // uv (0.8, 0.2): cells (1, 0), odd
  const auto top = rt.intersect(down, 0.f, 100.f);
  ASSERT_TRUE(top);
  const SurfacePoint t = makeSurfacePoint(
      scene, world, {top->instance, top->primitive, top->u, top->v}, down.direction);
  EXPECT_EQ(t.hit.instance, 1);
  EXPECT_TRUE(t.frontFacing);
  EXPECT_EQ(t.geometricNormal, vec3(0, 1, 0));
  EXPECT_EQ(t.resolved.color, vec3(0.75f));

  EXPECT_THROW(makeSurfacePoint(scene, world, {5, 0, 0.f, 0.f}, down.direction), Error);
  EXPECT_THROW(makeSurfacePoint(scene, world, {0, 9, 0.f, 0.f}, down.direction), Error);
}
}  // namespace DIPTYCH_UNITY_ID
