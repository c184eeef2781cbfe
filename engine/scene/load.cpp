#include "engine/scene/load.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cctype>

#include "engine/core/error.h"
#include "engine/scene/camera_math.h"
#include "engine/scene/mip_chain.h"
#include "engine/scene/scene_transform.h"
#include "engine/scene/validate.h"

namespace diptych {

namespace {
std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}
}  // namespace

bool isGltfPath(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  return ext == ".gltf" || ext == ".glb";
}

Scene loadScene(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  Scene scene;
  if (isGltfPath(path))
    scene = loadGltfUnvalidated(path);
  else if (ext == ".json")
    scene = loadJsonSceneUnvalidated(path);
  else
    throw InputError(path.string(), "",
                     "unknown scene format '" + ext + "' (expected .gltf, .glb or .json)");
  scene.sourcePath = path.string();
  // Frame the geometry before validating so that the automatic camera is checked too.
  if (!scene.hasCamera) {
    const Aabb box = scene.bounds();
    if (!box.empty() && allFinite(box.lo) && allFinite(box.hi)) scene.camera = frameBounds(box);
  }
  if (scene.camera.znear == 0.f && scene.camera.zfar == 0.f) {  // not given: fit to the bounds
    scene.camera.znear = Camera{}.znear;
    scene.camera.zfar = Camera{}.zfar;
    const Aabb box = scene.bounds();
    if (!box.empty() && allFinite(box.lo) && allFinite(box.hi)) fitNearFar(scene.camera, box);
  }
  validateScene(scene);
  // Once, for CPU and GL; each chain depends only on its own image, so they build in parallel.
  tbb::parallel_for(std::size_t(0), scene.textures.size(), [&scene](std::size_t i) {
    scene.textures[i].mips = buildMipChain(scene.textures[i].image);
  });
  // Far from the origin, float world coordinates would spend their bits on the offset:
  // move the world so the camera sits at the origin (docs/numerics.md).
  rebaseIfFar(scene);
  return scene;
}

}  // namespace diptych
