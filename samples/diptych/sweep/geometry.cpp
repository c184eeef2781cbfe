#include "samples/diptych/sweep/geometry.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/rt/shadow_rays.h"
#include "engine/rt/surface_point.h"
#include "engine/shading/shading.h"
#include "passes/common/hits_texel.h"
#include "passes/raster/shadow_map_frusta.h"

namespace diptych::cli {
namespace {

// Cube face (+x, -x, +y, -y, +z, -z) of direction d: its major axis, as the lookup shader's
// cubeFace() picks it.
int cubeFace(const vec3& d) {
  const vec3 a = glm::abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0 ? 2 : 3;
  return d.z >= 0 ? 4 : 5;
}

// The self-comparison error of a planar receiver at p on the map layer `m` (resolution n), as
// half-widths (a, c) in world units of bias along the ray: the map stores, per texel, the depth
// D (NDC, reversed) of the receiver at the texel centre, and D is affine in the map's (u, v) on
// a plane (also under a perspective projection), so a point delta = (du, dv) texels from the
// centre differs by dD/du du + dD/dv dv, |du|, |dv| <= 1/2; a bias b along the ray changes the
// receiver's D by b |grad D . l|. Orthographic maps give a = (tan theta / 2) |t . e_u| (e_u the
// world texel edge across the ray); perspective and cube maps compare axis depth, not distance
// along the ray, so a receiver normal to the map's axis has no error at all (docs §4).
bool selfError(const mat4& m, int n, const ReceiverPixel& r, double& a, double& c) {
  const vec4 clip = m * vec4(r.position, 1.f);
  if (!(clip.w > 0.f)) return false;  // behind a perspective light
  const vec3 ndc = vec3(clip) / clip.w;
  if (std::abs(ndc.x) > 1.f || std::abs(ndc.y) > 1.f) return false;  // outside the map: lit
  auto row = [&](int i) { return vec3(m[0][i], m[1][i], m[2][i]); };
  // d(ndc_i)/d(world) = (row_i - ndc_i row_3) / w; texels per world unit: n / 2 of x and y.
  const vec3 gu = (row(0) - ndc.x * row(3)) * (0.5f * float(n) / clip.w);
  const vec3 gv = (row(1) - ndc.y * row(3)) * (0.5f * float(n) / clip.w);
  const vec3 gd = (row(2) - ndc.z * row(3)) / clip.w;
  // World steps on the receiver plane that move one texel along u and along v: J^-1.
  const vec3 helper = std::abs(r.normal.x) < 0.9f ? vec3(1, 0, 0) : vec3(0, 1, 0);
  const vec3 ta = glm::normalize(glm::cross(r.normal, helper)), tb = glm::cross(r.normal, ta);
  const double j00 = glm::dot(gu, ta), j01 = glm::dot(gu, tb), j10 = glm::dot(gv, ta),
               j11 = glm::dot(gv, tb), det = j00 * j11 - j01 * j10;
  const double perBias = std::abs(glm::dot(gd, r.toLight));
  if (!(std::abs(det) > 0) || !(perBias > 0)) return false;
  const vec3 eu = ta * float(j11 / det) - tb * float(j10 / det);
  const vec3 ev = tb * float(j00 / det) - ta * float(j01 / det);
  a = 0.5 * std::abs(glm::dot(gd, eu)) / perBias;
  c = 0.5 * std::abs(glm::dot(gd, ev)) / perBias;
  return true;
}

}  // namespace

double uniformSumAbove(double a, double c, double s) {
  const double big = std::max(a, c);
  if (!(big > 0)) return s < 0 ? 1.0 : 0.0;
  if (std::min(a, c) <= 1e-9 * big) return std::clamp((a + c - s) / (2 * (a + c)), 0.0, 1.0);
  // The area of the rectangle [-a, a] x [-c, c] above the line x + y = s, by inclusion-
  // exclusion over its corners: each corner (X, Y) adds the triangle {x <= X, y <= Y, x + y > s}.
  auto g = [](double u) { return u > 0 ? 0.5 * u * u : 0.0; };
  const double area = g(a + c - s) - g(a - c - s) - g(c - a - s) + g(-a - c - s);
  return std::clamp(area / (4 * a * c), 0.0, 1.0);
}

void measureGeometry(StateReference& s, const FrameSettings& frame, int light,
                     double contactDistance, bool reachedOnly) {
  const CpuImage& gb = s.exact.outputs.at("gbuffer.hits");
  const int w = gb.desc.width, h = gb.desc.height;
  const std::size_t n = std::size_t(w) * h;
  s.footprint.assign(n, 0.f);
  s.receiverFootprints.clear();
  s.receivers.clear();
  const double pixelAngle = 2.0 * std::tan(frame.camera.verticalFov / 2.0) / h;
  const Light* l = light < int(s.scene->lights.size()) ? &s.scene->lights[light] : nullptr;
  const CpuImage& signal = s.exact.outputs.at(s.exactSignal);
  const std::vector<float> exact =
      l ? layer(signal, std::min(light, signal.desc.layers - 1)) : std::vector<float>(n, 1.f);
  const WorldGeometry& world = s.world->geometry();
  // The hybrid's G-buffer is a visibility buffer: (u, v) come from the pixel ray (hits_texel.h),
  // and its analytic spheres are impostors, whose texels name no triangle: the exact point, and
  // where an impostor missed its sphere the traced one.
  const PinholeFrame pinhole(frame.camera, w, h);
  const RtScene& rt = s.world->rtScene();
  const std::optional<shading::ShadingLight> reach =
      reachedOnly && l && lightMayNotReach(*l) ? std::optional(shading::toShadingLight(*l))
                                               : std::nullopt;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (!s.mask[i]) continue;
      const auto hit = exactTexel(gb, world, pinhole, x, y, &rt);
      if (!hit) {  // an impostor's sliver whose ray, traced, found the background
        s.mask[i] = 0;
        continue;
      }
      const SurfacePoint p = makeSurfacePoint(*s.scene, world, *hit, vec3(0.f));
      if (reach && !lightReaches(*reach, p.position)) {
        s.mask[i] = 0;
        ++s.unreachedPixels;
        continue;
      }
      const vec3 view = p.position - frame.camera.position;
      const double cosView = std::abs(glm::dot(glm::normalize(view), p.faceNormal));
      s.footprint[i] = float(glm::length(view) * pixelAngle / std::sqrt(std::max(cosView, 1e-3)));
      s.receiverFootprints.push_back(s.footprint[i]);
      ReceiverPixel r;
      r.pixel = i;
      r.position = p.position;
      r.lit = exact[i] >= 0.5f;
      if (l) {
        r.toLight = l->type == LightType::Directional ? -glm::normalize(l->direction)
                                                      : glm::normalize(l->position - p.position);
        vec3 nrm = p.faceNormal;
        if (glm::dot(nrm, r.toLight) < 0) nrm = -nrm;  // the light's side, as shadow rays do
        r.normal = nrm;
        r.incidence =
            std::acos(std::clamp(double(glm::dot(nrm, r.toLight)), -1.0, 1.0)) / kRadiansPerDegree;
      }
      s.receivers.push_back(r);
    }
  if (!l) return;
  s.contactDistance = contactDistance;
  s.contacts = shadowContacts(*s.world, gb, frame.camera, light, exact, s.contactDistance);
}

namespace {
double defaultContactDistance(const RenderWorld& world) {
  return 1e-3 * double(glm::length(world.geometry().bounds.hi - world.geometry().bounds.lo));
}
}  // namespace

ShadowContacts shadowContacts(RenderWorld& world, const CpuImage& gb, const Camera& camera,
                              int light, const std::vector<float>& exact, double& distance) {
  const int w = gb.desc.width, h = gb.desc.height;
  const std::size_t n = std::size_t(w) * h;
  if (distance < 0) distance = defaultContactDistance(world);
  ShadowContacts c;
  c.contact.assign(n, 0);
  c.object.assign(n, -1);
  const Light& l = world.scene().lights.at(std::size_t(light));
  const WorldGeometry& geometry = world.geometry();
  const RtScene& rt = world.rtScene();  // built here: it is lazy and not thread-safe
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> t(n, inf);  // occluder distance of each exactly shadowed receiver
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      if (gb.u(x, y, 0) == 0u) continue;
      c.object[i] = std::int32_t(gb.u(x, y, 0)) - 1;
      if (exact[i] >= 0.5f) continue;
      const auto hit = exactTexel(gb, geometry, camera, x, y, &rt);
      if (hit) t[i] = occluderDistance(rt, l, shadowReceiver(geometry, *hit));
    }
  });
  // A contact line is thinner than a pixel: the pixels nearest it may all lie farther than the
  // contact distance from their occluder. So a pixel is also a contact when its occluder
  // distance, growing linearly over the next two pixels of its own object in one of the 8
  // directions (the second step within 25% of the first), extrapolates to the contact distance
  // one pixel back. A thin wall (constant distance) or a jump to another occluder does not.
  const float d = float(distance);
  auto at = [&](int x, int y) { return std::size_t(y) * w + x; };
  tbb::parallel_for(0, h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = at(x, y);
      if (!(t[i] < inf)) continue;
      bool contact = t[i] <= d;
      for (int dy = -1; dy <= 1 && !contact; ++dy)
        for (int dx = -1; dx <= 1 && !contact; ++dx) {
          const int x2 = x + 2 * dx, y2 = y + 2 * dy;
          if ((dx == 0 && dy == 0) || x2 < 0 || y2 < 0 || x2 >= w || y2 >= h) continue;
          const std::size_t q = at(x + dx, y + dy), r = at(x2, y2);
          if (c.object[q] != c.object[i] || c.object[r] != c.object[i]) continue;
          const float s1 = t[q] - t[i], s2 = t[r] - t[q];  // inf - inf is NaN: fails below
          contact = s1 > 0.f && std::abs(s2 - s1) <= 0.25f * s1 && t[i] - s1 <= d;
        }
      c.contact[i] = contact;
    }
  });
  return c;
}

Image contactImage(const StateReference& s, int width, int height) {
  Image img(width, height, 3, 0.f);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = std::size_t(y) * width + x;
      if (!s.mask[i]) continue;
      const bool contact = !s.contacts.contact.empty() && s.contacts.contact[i];
      img.at(x, y, 0) = contact ? 1.f : 0.4f;
      img.at(x, y, 1) = img.at(x, y, 2) = contact ? 0.f : 0.4f;
    }
  return img;
}

TexelPrediction predictTexel(const StateReference& s, int resolution, int light, double bias) {
  TexelPrediction out;
  if (light >= int(s.scene->lights.size())) return out;
  shadowmap::FrustumOptions options;
  options.resolution = resolution;
  const auto f =
      shadowmap::fitLightFrusta(s.scene->lights, s.world->geometry().bounds, options)[light];
  if (f.kind == shadowmap::ViewKind::Unshadowed) return out;
  std::vector<double> widths, incidences;
  double acne = 0;
  long long lit = 0;
  for (const ReceiverPixel& r : s.receivers) {
    incidences.push_back(r.incidence);
    const int face = f.kind == shadowmap::ViewKind::Cube ? cubeFace(r.position - f.position) : 0;
    const bool counted = bias >= 0 && r.lit;  // outside the map the lookup says lit: no acne
    lit += counted ? 1 : 0;
    double a = 0, c = 0;
    if (!selfError(f.viewProj[std::size_t(face)], resolution, r, a, c)) continue;
    // The effective texel w of the pixel: the one for which (w/2) tan(theta) is its threshold.
    const double tanTheta = std::tan(std::min(r.incidence, 89.999) * kRadiansPerDegree);
    if (tanTheta > 1e-6) widths.push_back(2 * (a + c) / tanTheta);
    if (counted) acne += uniformSumAbove(a, c, bias);
  }
  out.texelWorld = upperMedian(widths);
  out.incidenceDeg = upperMedian(incidences);
  if (bias >= 0) out.acneRate = lit ? acne / double(lit) : 0.0;
  return out;
}

double upperMedian(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace diptych::cli
