#pragma once
// Camera (primary) rays and single-sided materials. glTF 2.0, material.doubleSided: "When this
// value is false, back-face culling is enabled". A camera ray does not see the back face of a
// single-sided material (Material::doubleSided false): a hit with dot(Ng, direction) > 0, Ng the
// CCW face normal (Hit::Ng), or an analytic shape's outward normal. The G-buffer culls the same
// faces (GL_CULL_FACE, engine/gl/gbuffer_raster.h). Secondary and shadow rays see both sides, as
// in pbrt: a refracted ray inside a closed glass object must meet its far side.
//
// No Embree filter function does this (filter functions on ray streams once hung inside Embree
// under ASan): a camera ray is traced as before, alone or in a stream, and a culled hit is traced
// again from the next float past it, ray by ray (rare: only where a back face is in view).
#include <span>

#include "engine/rt/rt_scene.h"
#include "engine/scene/scene.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

// The scene and geometry `rt` was built from (hit.instance indexes world.meshes).
struct CameraRays {
  const RtScene& rt;
  const Scene& scene;
  const WorldGeometry& world;

  // Whether a camera ray along `direction` may not see `hit` (a single-sided back face).
  bool culled(const Hit& hit, const vec3& direction) const;
  // RtScene::intersect over [0, inf) without the culled hits; false on a miss.
  bool intersect(const Ray& ray, Hit& hit, bool wantNormal) const;
  // RtScene::intersectRays (the same streams), then each culled hit traced on past it.
  void intersectRays(std::span<const Ray> rays, std::span<Hit> hits, std::span<const Hit*> found,
                     bool wantNormal) const;

 private:
  // `hit`, culled, replaced by the first hit past it that is not; false when none.
  bool pastCulled(const Ray& ray, Hit& hit, bool wantNormal) const;
};

}  // namespace diptych
