// glTF's material.doubleSided false (issue 9): primary visibility culls back faces, on both
// sides of the engine (G-buffer, every reference's camera rays), while reflected rays still see
// both sides. A red quad turned away from the camera in front of a green quad facing it: single
// sided, every producer sees green at the centre; double sided, red.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "engine/graph/recipe.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/rt_device.h"
#include "engine/rt/rt_scene.h"
#include "engine/scene/world_geometry.h"
#include "tests/support/hybrid_frame.h"
#include "tests/support/rt_test_geometry.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 32, kH = 24;

Material emissive(const std::string& name, vec3 emission, bool doubleSided) {
  Material m;
  m.name = name;
  m.color = vec3(0.f);
  m.kd = 0.f;
  m.emission = emission;
  m.doubleSided = doubleSided;
  return m;
}

// Turns a mesh's faces over (winding and normals).
Mesh flipped(Mesh m) {
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3)
    std::swap(m.indices[t + 1], m.indices[t + 2]);
  for (vec3& n : m.normals) n = -n;
  return m;
}

// Looking down -y: green floor at y = 0 facing up, red quad at y = 1 facing down (its back
// toward the camera), both emissive.
Scene backFacingQuad(bool redDoubleSided) {
  Mesh green = testgeo::groundPlane(2.f, 0.f);
  green.material = 0;
  Mesh red = flipped(testgeo::groundPlane(1.f, 1.f));
  red.material = 1;
  Scene s = testgeo::sceneOf({green, red});
  s.materials = {emissive("green", vec3(0.f, 1.f, 0.f), false),
                 emissive("red", vec3(1.f, 0.f, 0.f), redDoubleSided)};
  s.camera.position = vec3(0.f, 4.f, 0.f);
  s.camera.target = vec3(0.f);
  s.camera.up = vec3(0.f, 0.f, -1.f);
  s.hasCamera = true;
  return s;
}

Recipe sampleRecipe(const std::string& name) {
  return loadRecipe(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "graphs" / (name + ".json"));
}

// One spp, shallow: the centre pixel is one emissive hit either way.
Recipe cheap(Recipe r) {
  for (RecipePass& p : r.passes)
    if (p.params.contains("spp")) p.params["spp"] = 1;
  return r;
}

struct Producer {
  std::string name;
  Recipe recipe;
  std::string output;
};

std::vector<Producer> producers() {
  return {{"hybrid", defaultHybridRecipe(), "shade.color"},
          {"raster", sampleRecipe("raster"), "shade.color"},
          {"whitted", sampleRecipe("whitted"), "reference.color"},
          {"distributed", cheap(sampleRecipe("distributed")), "distributed.color"},
          {"path", cheap(sampleRecipe("path")), "path.color"}};
}

vec3 centre(const CpuImage& image) {
  return vec3(image.f(kW / 2, kH / 2, 0), image.f(kW / 2, kH / 2, 1), image.f(kW / 2, kH / 2, 2));
}

TEST(SingleSided, EveryProducerSeesThroughABackFacingSingleSidedQuad) {
  for (const Producer& p : producers()) {
    auto f = testing::renderHybridFrame(backFacingQuad(false), kW, kH, {p.output}, p.recipe);
    const vec3 c = centre(f->output(p.output));
    EXPECT_GT(c.y, 0.5f) << p.name;
    EXPECT_LT(c.x, 0.1f) << p.name;
  }
}

TEST(SingleSided, EveryProducerSeesTheBackOfADoubleSidedQuad) {
  for (const Producer& p : producers()) {
    auto f = testing::renderHybridFrame(backFacingQuad(true), kW, kH, {p.output}, p.recipe);
    const vec3 c = centre(f->output(p.output));
    EXPECT_GT(c.x, 0.5f) << p.name;
    EXPECT_LT(c.y, 0.1f) << p.name;
  }
}

// The rule is for camera rays only: RtScene::intersect (secondary rays) still meets the back.
TEST(SingleSided, OnlyCameraRaysCullBackFaces) {
  const Scene scene = backFacingQuad(false);
  const WorldGeometry world = flattenScene(scene);
  const RtDevice device;
  const RtScene rt(device, world, scene);
  const CameraRays camera{rt, scene, world};
  const Ray down{vec3(0.f, 4.f, 0.f), vec3(0.f, -1.f, 0.f)};
  const auto any = rt.intersect(down, 0.f, 100.f);
  ASSERT_TRUE(any);
  EXPECT_EQ(any->instance, 1);
  EXPECT_TRUE(camera.culled(*any, down.direction));
  Hit hit;
  ASSERT_TRUE(camera.intersect(down, hit, false));
  EXPECT_EQ(hit.instance, 0);
  EXPECT_FLOAT_EQ(hit.t, 4.f);
  // The streamed variant agrees, and an upward ray from below (the red quad's front) keeps it.
  const Ray rays[2] = {down, Ray{vec3(0.f, 0.5f, 0.f), vec3(0.f, 1.f, 0.f)}};
  Hit hits[2];
  const Hit* found[2];
  camera.intersectRays(rays, hits, found, false);
  ASSERT_NE(found[0], nullptr);
  EXPECT_EQ(found[0]->instance, 0);
  ASSERT_NE(found[1], nullptr);
  EXPECT_EQ(found[1]->instance, 1);
  // Double-sided, the camera sees the red quad's back.
  const Scene both = backFacingQuad(true);
  const RtScene rtBoth(device, world, both);
  ASSERT_TRUE((CameraRays{rtBoth, both, world}.intersect(down, hit, false)));
  EXPECT_EQ(hit.instance, 1);
}

// A single-sided mirror facing the camera reflects a single-sided red quad above the camera
// whose back faces the mirror: the reflected ray (secondary) sees it.
TEST(SingleSided, ReflectedRaysSeeBackFaces) {
  Mesh mirror = testgeo::groundPlane(2.f, 0.f);
  mirror.material = 0;
  Mesh red = testgeo::groundPlane(4.f, 6.f);  // facing up, away from the mirror below
  red.material = 1;
  Scene s = testgeo::sceneOf({mirror, red});
  Material m;
  m.name = "mirror";
  m.color = vec3(0.f);
  m.kd = 0.f;
  m.kps = 1.f;
  m.doubleSided = false;
  s.materials = {m, emissive("red", vec3(1.f, 0.f, 0.f), false)};
  s.camera.position = vec3(0.f, 4.f, 0.f);
  s.camera.target = vec3(0.f);
  s.camera.up = vec3(0.f, 0.f, -1.f);
  s.hasCamera = true;
  for (const Producer& p : {producers()[0], producers()[2]}) {  // hybrid, whitted
    auto f = testing::renderHybridFrame(s, kW, kH, {p.output}, p.recipe);
    EXPECT_GT(centre(f->output(p.output)).x, 0.5f) << p.name;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych

namespace diptych {
namespace DIPTYCH_UNITY_ID {

// whitted.json seen from outside: its glass and mirror spheres are analytic (Embree user
// geometry, culled by their outward normal) and closed. Made single-sided, nothing the camera
// sees is a back face and the refracted rays inside the glass still meet its far side (secondary
// rays see both sides): the Whitted reference and the hybrid keep their images bit for bit.
TEST(SingleSided, ClosedSingleSidedGlassKeepsItsImage) {
  const auto file = std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "whitted.json";
  const Scene both = loadScene(file);
  Scene single = both;
  for (Material& m : single.materials) m.doubleSided = false;
  for (const Producer& p : {producers()[0], producers()[2]}) {  // hybrid, whitted
    auto a = testing::renderHybridFrame(both, 64, 48, {p.output}, p.recipe);
    auto b = testing::renderHybridFrame(single, 64, 48, {p.output}, p.recipe);
    EXPECT_GT(b->world->rtScene().analyticGeometries(), 0) << p.name;
    EXPECT_EQ(a->output(p.output).words, b->output(p.output).words) << p.name;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
