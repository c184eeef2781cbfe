#include "engine/rt/analytic_geometry.h"

#include <bit>
#include <cmath>
#include <limits>
#include <optional>

#include "engine/scene/analytic_hit.h"

namespace diptych {
namespace {

const RtScene::GeometryData& dataOf(void* userPtr) {
  return *static_cast<const RtScene::GeometryData*>(userPtr);
}
const AnalyticInstance& shapeOf(void* userPtr) {
  return *dataOf(userPtr).analytic;
}

void boundsCallback(const RTCBoundsFunctionArguments* args) {
  const AnalyticInstance& a = shapeOf(args->geometryUserPtr);
  dvec3 wlo, whi;
  analyticPartWorldBounds(a, int(args->primID), wlo, whi);
  // Rounded outward, so the float box holds the double one; a flat part (disc) gets a box of
  // nonzero width from the rounding, which Embree's traversal needs no more than that.
  constexpr float kInf = std::numeric_limits<float>::infinity();
  RTCBounds* b = args->bounds_o;
  b->lower_x = std::nextafter(float(wlo.x), -kInf);
  b->lower_y = std::nextafter(float(wlo.y), -kInf);
  b->lower_z = std::nextafter(float(wlo.z), -kInf);
  b->upper_x = std::nextafter(float(whi.x), kInf);
  b->upper_y = std::nextafter(float(whi.y), kInf);
  b->upper_z = std::nextafter(float(whi.z), kInf);
}

// Ray i of a packet as our types.
struct PacketRay {
  vec3 origin, direction;
  float tnear, tfar;
};
PacketRay readRay(RTCRayN* rays, unsigned n, unsigned i) {
  return {vec3(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)),
          vec3(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)),
          RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i)};
}

// Alpha-masked shapes (glTF alphaMode MASK): a hit whose coverage at its uv is below the cutoff
// is passed over and the shape's next root beyond it tried, as alphaMaskFilter does for
// triangles (Embree runs no filter function for user geometry unless the callback asks).
// tmin = the next float after the rejected t excludes that root (intersectAnalyticPart compares
// float(t) >= tmin). A part has at most two roots; an SDF may have more, hence the cap. The
// coverage is read at the record's texture uv (analyticHitUv: a sphere's spherical parameters
// from its octahedral normal); SDF surfaces have no uv (materials see (0, 0): surface_point.h).
constexpr int kMaxMaskedRoots = 16;
// The step both loops share: true where the mask keeps the root at t (record: its hit record);
// else tmin moves just past it. The loops stay two, one per hit type: quadrics keep their hit
// in registers (PartHit), SDF hits carry their object-space point (ShapeHit); one template
// over both would need accessors for t, record and "no hit" longer than the loops themselves.
bool keepsRoot(const RtScene::GeometryData& data, int part, double t, vec2 record, float& tmin) {
  if (!data.alphaMasked ||
      data.coverageAt(analyticHitUv(*data.analytic, part, record)) >= data.alphaCutoff)
    return true;
  tmin = std::nextafter(float(t), std::numeric_limits<float>::infinity());
  return false;
}
// Quadrics, in registers (PartHit, analytic_hit.h); t NaN: none.
PartHit coveredQuadricHit(const RtScene::GeometryData& data, int part, const PacketRay& r) {
  float tmin = r.tnear;
  for (int i = 0; i < kMaxMaskedRoots; ++i) {
    const PartHit hit = analyticPartHit(*data.analytic, part, r.origin, r.direction, tmin, r.tfar);
    if (std::isnan(hit.t) || keepsRoot(data, part, hit.t, hit.record, tmin)) return hit;
  }
  return {std::numeric_limits<double>::quiet_NaN(), vec2(0.f)};
}
// SDF objects, whose hit carries its object-space point.
std::optional<ShapeHit> coveredHit(const RtScene::GeometryData& data, int part,
                                   const PacketRay& r) {
  float tmin = r.tnear;
  for (int i = 0; i < kMaxMaskedRoots; ++i) {
    auto hit = intersectAnalyticPart(*data.analytic, part, r.origin, r.direction, tmin, r.tfar,
                                     data.sdfStats.get());
    if (!hit || keepsRoot(data, part, hit->t, hit->record, tmin)) return hit;
  }
  return std::nullopt;
}

void intersectCallback(const RTCIntersectFunctionNArguments* args) {
  const RtScene::GeometryData& data = dataOf(args->geometryUserPtr);
  const AnalyticInstance& a = *data.analytic;
  const unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
  const int part = int(args->primID);
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const PacketRay r = readRay(rays, n, i);
    // (u, v) is the hit record (engine/scene/analytic_hit.h). SDF hits carry their object-space
    // point: x, y as (u, v), z's bits as the primitive id (SurfaceHit's encoding,
    // engine/rt/surface_point.h). A quadric's Ng is left at 0 here: RtScene::intersect computes
    // it from the record for the closest hit only, when asked (the tracers rebuild the normal
    // themselves), instead of once per candidate hit.
    PartHit hit;
    vec3 normal(0.f);
    unsigned primitive = args->primID;
    if (!a.sdf) {
      hit = coveredQuadricHit(data, part, r);
      if (std::isnan(hit.t)) continue;
    } else {
      const auto sdfHit = coveredHit(data, part, r);
      if (!sdfHit) continue;
      hit = {sdfHit->t, sdfHit->record};
      normal = sdfNormal(a, sdfHit->point);
      primitive = std::bit_cast<unsigned>(float(sdfHit->point.z));
    }
    RTCRayN_tfar(rays, n, i) = float(hit.t);
    RTCHitN_Ng_x(hits, n, i) = normal.x;
    RTCHitN_Ng_y(hits, n, i) = normal.y;
    RTCHitN_Ng_z(hits, n, i) = normal.z;
    RTCHitN_u(hits, n, i) = hit.record.x;
    RTCHitN_v(hits, n, i) = hit.record.y;
    RTCHitN_primID(hits, n, i) = primitive;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
  }
}

void occludedCallback(const RTCOccludedFunctionNArguments* args) {
  const RtScene::GeometryData& data = dataOf(args->geometryUserPtr);
  const AnalyticInstance& a = *data.analytic;
  const unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    const PacketRay r = readRay(args->ray, n, i);
    const int part = int(args->primID);
    const bool hit = !data.alphaMasked ? analyticPartOccludes(a, part, r.origin, r.direction,
                                                              r.tnear, r.tfar, data.sdfStats.get())
                     : a.sdf           ? coveredHit(data, part, r).has_value()
                                       : !std::isnan(coveredQuadricHit(data, part, r).t);
    if (hit)
      RTCRayN_tfar(args->ray, n, i) = -std::numeric_limits<float>::infinity();  // Embree: hit
  }
}

}  // namespace

RTCGeometry newAnalyticGeometry(RTCDevice device, RtScene::GeometryData& data) {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, unsigned(analyticPartCount(*data.analytic)));
  rtcSetGeometryUserData(geom, &data);
  rtcSetGeometryBoundsFunction(geom, boundsCallback, &data);
  rtcSetGeometryIntersectFunction(geom, intersectCallback);
  rtcSetGeometryOccludedFunction(geom, occludedCallback);
  return geom;
}

}  // namespace diptych
