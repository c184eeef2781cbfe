#include "engine/rt/ray_probe.h"

#include <tbb/parallel_for.h>

#include <atomic>
#include <limits>

#include "engine/core/error.h"
#include "engine/rt/camera_rays.h"
#include "engine/rt/ray_offset.h"
#include "engine/rt/shadow_rays.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/shading.h"

namespace diptych {
namespace {

// A ray re-hitting the surface it left. A triangle is flat, so any hit on the same triangle is
// one. Analytic objects are curved: a refraction ray legitimately meets the same quadric or SDF
// again on the far side, so there only a hit on the same instance within a few of the origin's
// error bounds (ray_offset.h) counts (an SDF hit's primitive id encodes its point, not a part).
// `direction` is the ray's (unit for shadow and spawned rays).
bool selfHit(const std::optional<Hit>& h, const SurfacePoint& p, const vec3& direction) {
  if (!h || h->instance != p.hit.instance) return false;
  if (!h->analytic) return h->primitive == p.hit.primitive;
  const float bound = glm::length(positionErrorBound(p.position, p.positionMagnitude));
  return h->t * glm::length(direction) <= 64.f * bound;
}

}  // namespace

RayProbe probeSecondaryRays(const Scene& scene, const WorldGeometry& world, const RtScene& rt,
                            const Camera& camera, int width, int height) {
  RayProbe probe;
  probe.width = width;
  probe.height = height;
  probe.lights = int(scene.lights.size());
  const std::size_t lights = scene.lights.size();
  probe.occluded.assign(std::size_t(width) * height * lights, 2);
  std::atomic<long> primary{0}, secondary{0}, self{0};
  const float inf = std::numeric_limits<float>::infinity();
  tbb::parallel_for(0, height, [&](int y) {
    long nPrimary = 0, nSecondary = 0, nSelf = 0;
    for (int x = 0; x < width; ++x) {
      const Ray ray = primaryRay(camera, width, height, x + 0.5f, y + 0.5f);
      Hit cameraHit;  // back faces of single-sided materials culled, as the G-buffer does
      if (!CameraRays{rt, scene, world}.intersect(ray, cameraHit, true)) continue;
      const Hit* hit = &cameraHit;
      ++nPrimary;
      const SurfacePoint p = makeSurfacePoint(
          scene, world, {hit->instance, hit->primitive, hit->u, hit->v, hit->analytic},
          ray.direction);
      const ShadowReceiver receiver{p.position, p.faceNormal, p.positionMagnitude, p.time};
      for (std::size_t l = 0; l < lights; ++l) {
        const OcclusionRay s = makeShadowRay(scene.lights[l], receiver);
        if (s.tnear > s.tfar) continue;
        ++nSecondary;
        const auto h = rt.intersect(Ray{s.origin, s.direction, s.time}, s.tnear, s.tfar);
        nSelf += selfHit(h, p, s.direction) ? 1 : 0;
        probe.occluded[(std::size_t(y) * width + x) * lights + l] = h ? 1 : 0;
      }
      const vec3 v = -ray.direction;
      const Material& m = scene.material(p.material);
      if (shading::hasReflection(p.resolved, false)) {
        const vec3 r = glm::normalize(shading::reflectAbout(v, p.shadingNormal));
        ++nSecondary;
        const Ray reflected = spawnRay(p, r);
        nSelf += selfHit(rt.intersect(reflected, 0.f, inf), p, reflected.direction) ? 1 : 0;
      }
      if (shading::hasTransmission(p.resolved)) {
        const float eta = p.frontFacing ? 1.f / m.ior : m.ior;
        const shading::Refraction t = shading::refractLecture(v, p.shadingNormal, eta);
        ++nSecondary;
        const Ray refracted = spawnRay(p, t.t);
        nSelf += selfHit(rt.intersect(refracted, 0.f, inf), p, refracted.direction) ? 1 : 0;
      }
    }
    primary += nPrimary;
    secondary += nSecondary;
    self += nSelf;
  });
  probe.primaryHits = primary;
  probe.secondaryRays = secondary;
  probe.selfHits = self;
  return probe;
}

ShadowDifference compareShadows(const RayProbe& test, const RayProbe& reference) {
  if (test.width != reference.width || test.height != reference.height ||
      test.lights != reference.lights)
    throw Error("compareShadows: probes differ in size or light count");
  ShadowDifference d;
  for (std::size_t i = 0; i < test.occluded.size(); ++i) {
    const std::uint8_t a = test.occluded[i], b = reference.occluded[i];
    if (a == 2 || b == 2) continue;
    ++d.compared;
    d.lost += (b == 1 && a == 0) ? 1 : 0;
    d.gained += (b == 0 && a == 1) ? 1 : 0;
  }
  return d;
}

}  // namespace diptych
