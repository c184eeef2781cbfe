#include "samples/diptych/check/cases.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "engine/scene/scene_transform.h"
#include "engine/scene/world_geometry.h"
#include "passes/raster/shadow_map_frusta.h"

namespace diptych::cli {

std::vector<CheckCase> checkCases(const std::vector<double>& scales,
                                  const std::vector<double>& offsets) {
  std::vector<CheckCase> cases{{"as given"}, {"grazing", 1.0, 0.0, true}};
  for (double s : scales) cases.push_back({fmt::format("scale {:g}", s), s, 0.0, false});
  for (double o : offsets) cases.push_back({fmt::format("offset {:+g} x", o), 1.0, o, false});
  double lo = 1.0, hi = 1.0, far = 0.0;
  for (double s : scales) lo = std::min(lo, s), hi = std::max(hi, s);
  for (double o : offsets) far = std::max(far, o);
  if (lo < 1.0) cases.push_back({fmt::format("grazing scale {:g}", lo), lo, 0.0, true});
  if (hi > 1.0) cases.push_back({fmt::format("grazing scale {:g}", hi), hi, 0.0, true});
  if (far > 0.0) cases.push_back({fmt::format("grazing offset {:+g} x", far), 1.0, far, true});
  return cases;
}

Camera grazingCamera(const Scene& scene) {
  Camera c = scene.camera;
  const Aabb box = scene.bounds();
  if (box.empty()) return c;
  const vec3 foot(c.target.x, box.lo.y, c.target.z);
  const vec3 horizontal(c.position.x - c.target.x, 0.f, c.position.z - c.target.z);
  const float distance =
      glm::length(horizontal) > 0.f ? glm::length(horizontal) : glm::length(c.position - c.target);
  const vec3 away =
      glm::length(horizontal) > 0.f ? horizontal / glm::length(horizontal) : vec3(0.f, 0.f, 1.f);
  c.position = foot + distance * away + vec3(0.f, 0.01f * distance, 0.f);
  c.target = foot;
  c.up = vec3(0.f, 1.f, 0.f);
  return c;
}

Scene caseScene(const Scene& base, const CheckCase& c, bool rebase, glm::dvec3& rebasedTo) {
  Scene s = base;
  s.hasCamera = true;
  if (c.grazing) s.camera = grazingCamera(base);
  s = similarityTransformed(s, c.scale, glm::dvec3(c.offset, 0.0, 0.0));
  rebasedTo = rebase ? rebaseIfFar(s) : glm::dvec3(0.0);
  return s;
}

std::vector<std::string> shadowMapDepthWarnings(const Scene& scene, int resolution) {
  std::vector<std::string> warnings;
  const WorldGeometry world = flattenScene(scene);
  const auto frusta =
      shadowmap::fitLightFrusta(scene.lights, world.bounds, {.resolution = resolution});
  const vec3 m = glm::max(glm::abs(world.bounds.lo), glm::abs(world.bounds.hi));
  for (std::size_t i = 0; i < frusta.size(); ++i) {
    const shadowmap::LightFrustum& f = frusta[i];
    if (f.kind == shadowmap::ViewKind::Unshadowed) continue;
    const std::string light = fmt::format("light {} '{}'", i, scene.lights[i].name);
    if (!std::isfinite(f.zNear) || !std::isfinite(f.zFar) || !std::isfinite(f.texelScale) ||
        !(f.zFar > f.zNear)) {
      warnings.push_back(fmt::format("{}: shadow-map frustum not finite (near {:g}, far {:g})",
                                     light, f.zNear, f.zFar));
      continue;
    }
    const vec3 pa = glm::abs(f.position);
    const double coordinate =
        std::max({double(m.x), double(m.y), double(m.z), double(pa.x), double(pa.y), double(pa.z)});
    const double depthError = std::ldexp(double(f.zFar), -24) + std::ldexp(coordinate, -22);
    const double texel = f.kind == shadowmap::ViewKind::Ortho ? double(f.texelScale)
                                                              : double(f.texelScale) * f.zNear;
    if (depthError > 0.25 * texel)
      warnings.push_back(fmt::format(
          "{}: depth error {:.3g} exceeds a quarter ({:.3g}) of the nearest shadow-map texel's "
          "footprint (coordinates up to {:.3g}): expect acne or lost contact shadows",
          light, depthError, 0.25 * texel, coordinate));
  }
  return warnings;
}

}  // namespace diptych::cli
