// The env_* lookups run only inside the window rectangle of the meshes whose material may
// reflect (passes/raster/env_reflection.cpp, screen_rect.h), env_dynamic_cube's resolve inside
// each mesh's own rectangle (env_dynamic_cube.cpp): no reflective pixel may fall outside, and the
// rectangle must leave the rest of the frame out. Checked against the G-buffer
// (env_scissor_check.h) from the scene's camera, from a camera whose view a mirror sphere is cut
// by the frame's edge, from one inside a sphere's bounds (the whole-viewport branch), and with a
// sphere wholly off screen (env_dynamic_cube renders no cube for it).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "engine/scene/load.h"
#include "tests/support/test_paths.h"
#include "tests/unit/env_scissor_check.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

using testing::checkEnvScissor;

constexpr int kW = 160, kH = 120;
const std::string kTypes[] = {"env_cube", "env_sphere", "env_equirect", "env_dynamic_cube"};

// whitted: a mirror sphere and a glass sphere (both reflect) over a checkered floor, sky.
Scene whitted() {
  return loadScene(std::filesystem::path(DIPTYCH_SAMPLES_DIR) / "scenes/whitted.json");
}

// The first mesh of `scene` whose material reflects (whitted: a sphere), and its bounds.
Aabb firstReflectiveBox(const Scene& scene) {
  const WorldGeometry geometry = flattenScene(scene);
  for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
    if (shading::materialHasReflection(scene.material(geometry.meshes[m].material)))
      return testing::meshBox(scene, m);
  ADD_FAILURE() << "no reflective mesh";
  return {};
}

// The scene's camera moved sideways (with its target) so that `centre` projects `halfWidths`
// half frame widths left of the frame's centre: 1 puts it on the left edge.
Camera shifted(const Camera& camera, const vec3& centre, float halfWidths) {
  Camera c = camera;
  c.target = centre;
  const vec3 forward = glm::normalize(c.target - c.position);
  const vec3 right = glm::normalize(glm::cross(forward, c.up));
  const float depth = glm::length(centre - c.position);
  const float half = depth * std::tan(0.5f * c.verticalFov) * float(kW) / float(kH);
  c.position += right * (halfWidths * half);
  c.target += right * (halfWidths * half);
  return c;
}

TEST(EnvScissor, EveryReflectivePixelIsInsideAndTheRestOfTheFrameOutside) {
  const Scene scene = whitted();
  for (const std::string& type : kTypes) {
    const auto run = checkEnvScissor(scene, scene.camera, type, false, kW, kH);
    EXPECT_GT(run.reflective, kW * kH / 20) << "the spheres are in view";
    if (type == "env_dynamic_cube") {
      EXPECT_EQ(run.counters.at("cube_face_renders"), 12.0) << "two spheres, six faces each";
    } else {
      const double scissor = run.counters.at("env_scissor_pixels");
      EXPECT_GE(scissor, run.reflective);
      EXPECT_LT(scissor, 0.5 * kW * kH) << type << ": the floor and sky are left out";
    }
  }
}

TEST(EnvScissor, AMirrorCutByTheFrameEdgeKeepsItsVisiblePart) {
  const Scene scene = whitted();
  const Aabb box = firstReflectiveBox(scene);
  const Camera camera = shifted(scene.camera, box.center(), 1.f);  // centre on the left edge
  const mat4 viewProj = reversedZProjection(camera, float(kW) / float(kH)) * viewMatrix(camera);
  EXPECT_EQ(windowRect(box, viewProj, kW, kH).lo.x, 0) << "the rectangle is clamped";
  for (const std::string& type : kTypes) {
    const auto run = checkEnvScissor(scene, camera, type, false, kW, kH);
    EXPECT_GT(run.reflective, 0) << type;
  }
}

TEST(EnvScissor, ACameraInsideAReflectiveBoxGetsTheWholeViewport) {
  const Scene scene = whitted();
  const Aabb box = firstReflectiveBox(scene);
  // Near a corner of the sphere's bounding box (outside the sphere), looking at its centre: the
  // box reaches behind the eye, so the scissor is the whole viewport.
  Camera camera = scene.camera;
  camera.position = glm::mix(box.hi, box.lo, 0.05f);
  camera.target = box.center();
  for (const std::string& type : kTypes) {
    const auto run = checkEnvScissor(scene, camera, type, false, kW, kH);
    EXPECT_GT(run.reflective, kW * kH / 4) << type << ": the sphere fills much of the view";
    if (type != "env_dynamic_cube") {
      EXPECT_EQ(run.counters.at("env_scissor_pixels"), double(kW * kH)) << type;
    }
  }
}

TEST(EnvScissor, DynamicCubeRendersNoCubeForAnOffScreenMirror) {
  const Scene scene = whitted();
  const Aabb box = firstReflectiveBox(scene);
  // The sphere's centre four half widths left of the frame's centre: wholly off screen.
  const Camera camera = shifted(scene.camera, box.center(), 4.f);
  const float aspect = float(kW) / float(kH);
  const PixelRect rect =
      windowRect(box, reversedZProjection(camera, aspect) * viewMatrix(camera), kW, kH);
  ASSERT_TRUE(rect.empty()) << "the sphere is off screen";
  const auto run = checkEnvScissor(scene, camera, "env_dynamic_cube", false, kW, kH);
  EXPECT_LE(run.counters.at("cube_face_renders"), 6.0) << "at most the other sphere's cube";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
