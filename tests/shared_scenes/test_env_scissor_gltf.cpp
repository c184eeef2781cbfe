// env_* scissor with rough glTF materials (passes/raster/env_reflection.cpp): with prefiltered
// levels the lookup serves the GGX lobe of every glTF material, rough ones included
// (materialHasReflection(m, lobe = true)), so the scissor must cover them too, not only the
// mirror-like ones. MetalRoughSpheres: a grid of spheres from smooth to rough, metal to
// dielectric; a uniform sky makes every lobe lookup non-zero (env_scissor_check.h).
#include <gtest/gtest.h>

#include <string>

#include "engine/scene/load.h"
#include "tests/support/test_paths.h"
#include "tests/unit/env_scissor_check.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

TEST(EnvScissorGltf, RoughMaterialsWithPrefilterAreInsideTheScissor) {
  Scene scene = loadScene(DIPTYCH_SHARED_SCENES +
                          "/metal-rough-spheres-no-textures/MetalRoughSpheresNoTextures.glb");
  // A uniform lat-long sky: a texture, so the maps get prefiltered levels (a constant colour
  // keeps one level, and then no lobe).
  scene.environment = Environment{};
  scene.environment.type = EnvironmentType::Equirect;
  scene.environment.equirect = Image(64, 32, 3, 0.5f);
  int mirrorOnly = 0;  // meshes whose material reflects without the lobe (smooth ones)
  {
    const WorldGeometry geometry = flattenScene(scene);
    for (const WorldMesh& mesh : geometry.meshes)
      mirrorOnly += shading::materialHasReflection(scene.material(mesh.material)) ? 1 : 0;
  }
  for (const std::string type : {"env_cube", "env_sphere"}) {
    const auto run = testing::checkEnvScissor(scene, scene.camera, type, /*lobe=*/true, 160, 120,
                                              {{"resolution", 32}, {"prefilter", true}});
    EXPECT_GT(run.reflective, 160 * 120 / 10) << type << ": the spheres are in view";
    EXPECT_EQ(run.counters.at("prefilter_builds"), 1.0) << type << ": levels, so the lobe";
    EXPECT_GE(run.counters.at("env_scissor_pixels"), run.reflective) << type;
  }
  // The lobe matters here: fewer meshes reflect without it (else this test shows nothing).
  EXPECT_LT(mirrorOnly, int(flattenScene(scene).meshes.size()));
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
