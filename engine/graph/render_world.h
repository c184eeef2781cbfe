#pragma once
// Per-scene state shared by the passes of a frame: the scene, its world-space triangles, and
// the Embree scene and GL buffers built from them on first use (so a frame that needs no ray
// tracing never builds a BVH, and a CPU-only frame never touches OpenGL).
#include <memory>

#include "engine/scene/scene.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

class RenderWorld {
 public:
  explicit RenderWorld(const Scene& scene) : scene_(scene), world_(flattenScene(scene)) {}
  const Scene& scene() const { return scene_; }
  const WorldGeometry& geometry() const { return world_; }

 private:
  const Scene& scene_;
  WorldGeometry world_;
};

}  // namespace diptych
