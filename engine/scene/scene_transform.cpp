#include "engine/scene/scene_transform.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/scene/camera_math.h"

namespace diptych {
namespace {

using glm::dvec3;

vec3 moved(const vec3& p, double scale, const dvec3& translation) {
  return vec3(dvec3(p) * scale + translation);
}

}  // namespace

Scene similarityTransformed(const Scene& input, double scale, const dvec3& translation) {
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw Error("similarityTransformed: scale must be finite and positive, got " +
                std::to_string(scale));
  Scene s = input;
  const glm::dmat4 similarity = glm::dmat4(scale, 0, 0, 0, 0, scale, 0, 0, 0, 0, scale, 0,
                                           translation.x, translation.y, translation.z, 1);
  for (Instance& inst : s.instances) {
    inst.transform = mat4(similarity * glm::dmat4(inst.transform));
    inst.motion = vec3(dvec3(inst.motion) * scale);  // a displacement: scaled, not translated
  }
  Camera& c = s.camera;
  c.position = moved(c.position, scale, translation);
  c.target = moved(c.target, scale, translation);
  c.znear = float(c.znear * scale);
  c.zfar = float(c.zfar * scale);
  c.focusDistance = float(c.focusDistance * scale);
  c.aperture = float(c.aperture * scale);
  for (Light& l : s.lights) {
    l.position = moved(l.position, scale, translation);
    l.edgeU = vec3(dvec3(l.edgeU) * scale);
    l.edgeV = vec3(dvec3(l.edgeV) * scale);
    l.radius = float(l.radius * scale);
    l.range = float(l.range * scale);
    if (l.type == LightType::Point || l.type == LightType::Spot)
      l.intensity = float(double(l.intensity) * scale * scale);
  }
  for (Material& m : s.materials) m.attenuationDistance = float(m.attenuationDistance * scale);
  return s;
}

Scene sceneAtTime(const Scene& input, float time) {
  Scene s = input;
  for (Instance& inst : s.instances) {
    if (inst.motion == vec3(0.f)) continue;
    inst.transform = glm::translate(mat4(1.f), (time - kFrameTime) * inst.motion) * inst.transform;
    inst.motion = vec3(0.f);
  }
  return s;
}

void rebaseScene(Scene& s, const dvec3& origin) {
  for (Instance& inst : s.instances)
    inst.transform[3] = vec4(vec3(dvec3(inst.transform[3]) - origin), inst.transform[3].w);
  s.camera.position = vec3(dvec3(s.camera.position) - origin);
  s.camera.target = vec3(dvec3(s.camera.target) - origin);
  for (Light& l : s.lights) l.position = vec3(dvec3(l.position) - origin);
  s.worldOrigin += origin;
}

dvec3 rebaseIfFar(Scene& s) {
  const Aabb box = s.bounds();
  if (box.empty()) return dvec3(0.0);
  const dvec3 lo(box.lo), hi(box.hi);
  const dvec3 side = hi - lo, centre = 0.5 * (lo + hi);
  const double extent = std::max({side.x, side.y, side.z});
  auto maxAbs = [](const dvec3& v) {
    return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  };
  if (!(maxAbs(centre) > kRebaseRatio * extent)) return dvec3(0.0);
  const dvec3 camera(s.camera.position);
  const dvec3 origin = maxAbs(camera - centre) <= kRebaseRatio * extent ? camera : centre;
  rebaseScene(s, origin);
  return origin;
}

}  // namespace diptych
