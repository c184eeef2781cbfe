#include "engine/rt/rt_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <string>

#include "engine/core/check.h"
#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/rt/analytic_geometry.h"
#include "engine/rt/rt_scene_instancing.h"
#include "engine/scene/analytic_hit.h"
#include "engine/scene/sdf.h"
#include "engine/shading/texture_sampling.h"

namespace diptych {
namespace {

// Rays per stream call. Large enough for Embree to amortise its stream setup, small enough
// that a tile's RTCRay array (48 bytes each) stays on the stack and TBB can balance tiles.
constexpr std::size_t kTileRays = 256;

// Embree filter function (intersection and occlusion alike): valid[i] == -1 marks a live hit;
// setting it to 0 makes Embree ignore that hit and continue traversal, so the closest hit
// behind a hole is found and an any-hit query keeps looking. Reads only immutable data, as it
// runs on every tracing thread at once.
void alphaMaskFilter(const RTCFilterFunctionNArguments* args) {
  const auto* data = static_cast<const RtScene::GeometryData*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] != -1) continue;
    const std::uint32_t primitive = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i), v = RTCHitN_v(args->hit, args->N, i);
    if (data->coverage(primitive, u, v) < data->alphaCutoff) args->valid[i] = 0;
  }
}

}  // namespace

float RtScene::GeometryData::coverage(std::uint32_t primitive, float u, float v) const {
  if (!alphaTexture || mesh->uvs.empty()) {
    // A mesh without uvs samples uv (0, 0) everywhere, as the GPU side does (its uv buffer
    // holds zeros there), so that both producers cut the same holes.
    return alphaTexture ? alpha * sampleTexture(*alphaTexture, vec2(0.f)).w : alpha;
  }
  return alpha * sampleTexture(*alphaTexture, interpolateUv(*mesh, primitive, u, v)).w;
}

float RtScene::GeometryData::coverageAt(vec2 uv) const {
  return alphaTexture ? alpha * sampleTexture(*alphaTexture, uv).w : alpha;
}

RtScene::RtScene(const RtDevice& device, const WorldGeometry& world, RtSceneOptions options)
    : RtScene(device, world, nullptr, options) {}

RtScene::RtScene(const RtDevice& device, const WorldGeometry& world, const Scene& scene,
                 RtSceneOptions options)
    : RtScene(device, world, &scene, options) {}

RtScene::RtScene(const RtDevice& device, const WorldGeometry& world, const Scene* scene,
                 RtSceneOptions options)
    : device_(device) {
  RTCDevice dev = device.handle();
  scene_ = rtcNewScene(dev);
  device.check("rtcNewScene");
  rtcSetSceneBuildQuality(scene_, options.quality);
  const RTCSceneFlags flags = options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE;
  rtcSetSceneFlags(scene_, flags);

  geometry_.resize(world.meshes.size());
  // Repeated opaque triangle meshes: built once, instanced (rt_scene_instancing.h).
  std::vector<std::vector<std::size_t>> groups;
  std::vector<int> shared(world.meshes.size(), -1);  // group of each mesh, -1: none
  if (scene && options.instancing) {
    std::vector<bool> eligible(world.meshes.size());
    for (std::size_t id = 0; id < world.meshes.size(); ++id) {
      const WorldMesh& m = world.meshes[id];
      eligible[id] = !(m.analytic && options.analytic) && m.motion == vec3(0.f) &&
                     scene->material(m.material).alphaMode != AlphaMode::Mask;
    }
    groups = rt_detail::sharedMeshGroups(*scene, world, eligible);
    for (std::size_t g = 0; g < groups.size(); ++g)
      for (const std::size_t id : groups[g]) shared[id] = int(g);
  }
  bool warnedNoFilters = false;
  // A moving instance's geometry goes into a prototype of its own, in the world space of
  // kFrameTime, placed by a two-step motion-blurred instance (rt_scene_instancing.h); every
  // other geometry goes into the scene itself.
  const auto attach = [&](RTCGeometry geom, std::size_t id) {
    const WorldMesh& mesh = world.meshes[id];
    if (mesh.motion == vec3(0.f)) {
      rtcAttachGeometryByID(scene_, geom, unsigned(id));
      rtcReleaseGeometry(geom);  // the scene holds its own reference
      return;
    }
    RTCScene proto = rt_detail::newSceneOf(device, geom, options.quality, flags,
                                           "instance " + std::to_string(id));
    prototypes_.push_back(proto);
    RTCGeometry inst = rt_detail::newMovingInstanceGeometry(device, proto, mesh.motion);
    rtcAttachGeometryByID(scene_, inst, unsigned(id));
    rtcReleaseGeometry(inst);
    geometry_[id].instanced = true;  // normalToWorld stays the identity: a translation
    ++moving_;
  };
  for (std::size_t id = 0; id < world.meshes.size(); ++id) {
    const WorldMesh& mesh = world.meshes[id];
    GeometryData& data = geometry_[id];
    data.mesh = &mesh;
    if (scene) {
      const Material& m = scene->material(mesh.material);
      data.alphaMasked = m.alphaMode == AlphaMode::Mask;
      data.alpha = m.alpha;
      data.alphaCutoff = m.alphaCutoff;
      const int t = m.colorTexture;
      // resolveMaterial: a checker replaces the colour texture, alpha included.
      if (!m.checker && t >= 0 && t < int(scene->textures.size()))
        data.alphaTexture = &scene->textures[std::size_t(t)];
    }
    if (mesh.analytic && options.analytic) {  // quadrics and SDF objects
      data.analytic = &*mesh.analytic;
      if (data.analytic->sdf) data.sdfStats = std::make_unique<SdfStats>();
      RTCGeometry geom = newAnalyticGeometry(dev, data);
      rtcCommitGeometry(geom);
      attach(geom, id);
      device.check("adding analytic instance " + std::to_string(id));
      ++analytic_;
      alphaMasked_ += data.alphaMasked ? 1 : 0;  // tested in its own callbacks
      continue;
    }
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles == 0 || mesh.positions.empty()) continue;
    if (shared[id] >= 0) continue;  // added below as an instance of its group's prototype
    RTCGeometry geom = rt_detail::newTriangleGeometry(
        device, mesh.positions, mesh.indices, options.quality, "instance " + std::to_string(id));
    rtcSetGeometryUserData(geom, &data);
    if (data.alphaMasked) {
      if (rtcGetDeviceProperty(dev, RTC_DEVICE_PROPERTY_FILTER_FUNCTION_SUPPORTED)) {
        rtcSetGeometryIntersectFilterFunction(geom, alphaMaskFilter);
        rtcSetGeometryOccludedFilterFunction(geom, alphaMaskFilter);
        ++alphaMasked_;
      } else if (!warnedNoFilters) {
        warnedNoFilters = true;
        log().warn(
            "this Embree build has no filter functions: alpha-masked materials are opaque"
            " to rays");
      }
    }
    rtcCommitGeometry(geom);
    attach(geom, id);
    device.check("adding instance " + std::to_string(id) + " (" + std::to_string(triangles) +
                 " triangles)");
  }
  for (const auto& group : groups) {
    RTCScene proto = rt_detail::newPrototypeScene(device, *scene, world.meshes[group.front()],
                                                  options.quality, flags);
    prototypes_.push_back(proto);
    for (const std::size_t id : group) {
      const mat4& transform = scene->instances[std::size_t(world.meshes[id].instance)].transform;
      RTCGeometry geom = rt_detail::newInstanceGeometry(device, proto, transform);
      rtcAttachGeometryByID(scene_, geom, unsigned(id));
      rtcReleaseGeometry(geom);
      const mat3 linear(transform);
      geometry_[id].instanced = true;
      geometry_[id].normalToWorld = glm::determinant(linear) * glm::transpose(glm::inverse(linear));
      ++instanced_;
    }
  }
  rtcCommitScene(scene_);
  device.check("rtcCommitScene");
}

RtScene::SdfStepStats RtScene::sdfStepStats() const {
  SdfStepStats s;
  for (const GeometryData& g : geometry_) {
    if (!g.sdfStats) continue;
    const SdfStats& o = *g.sdfStats;
    s.rays += o.rays.load(std::memory_order_relaxed);
    s.steps += o.steps.load(std::memory_order_relaxed);
    s.capped += o.capped.load(std::memory_order_relaxed);
    s.maxSteps = std::max(s.maxSteps, o.maxSteps.load(std::memory_order_relaxed));
  }
  return s;
}

void RtScene::resetSdfStepStats() const {
  for (const GeometryData& g : geometry_)
    if (g.sdfStats) g.sdfStats->reset();
}

RtScene::~RtScene() {
  if (scene_) rtcReleaseScene(scene_);
  for (RTCScene proto : prototypes_) rtcReleaseScene(proto);
}

std::optional<Hit> RtScene::intersect(const Ray& ray, float tnear, float tfar,
                                      bool wantNormal) const {
  Hit hit;
  if (!intersect(ray, tnear, tfar, hit, wantNormal)) return std::nullopt;
  return hit;
}

bool RtScene::intersect(const Ray& ray, float tnear, float tfar, Hit& hit, bool wantNormal) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  // Field by field, not built in a temporary and assigned: that built the ray in
  // 4-byte stores and copied it in 16-byte loads, two store-forwarding stalls per ray (perf
  // annotate, issue 14). Embree reads only the ray and writes the hit (rtcIntersect1 docs).
  RTCRayHit rh;
  setEmbreeRay(rh.ray, ray.origin, ray.direction, tnear, tfar, ray.time);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  raysTraced_.add(1);
  return hitOf(rh, hit, wantNormal);
}

void RtScene::intersectRays(std::span<const Ray> rays, std::span<Hit> hits,
                            std::span<const Hit*> found, bool wantNormal, bool coherent) const {
  DIPTYCH_CHECK(hits.size() >= rays.size() && found.size() >= rays.size(),
                "RtScene::intersectRays: output smaller than the rays");
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = streamFlag(coherent);
  for (std::size_t begin = 0; begin < rays.size(); begin += kStreamRays) {
    const std::size_t n = std::min(kStreamRays, rays.size() - begin);
    RTCRayHit tile[kStreamRays];  // RTC_ALIGN(16), as rtcIntersect1M requires
    for (std::size_t i = 0; i < n; ++i) {
      const Ray& r = rays[begin + i];
      setEmbreeRay(tile[i].ray, r.origin, r.direction, 0.f, std::numeric_limits<float>::infinity(),
                   r.time);
      // Embree writes the hit only where it finds one: a miss must read as one.
      tile[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
      tile[i].hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    }
    rtcIntersect1M(scene_, &context, tile, unsigned(n), sizeof(RTCRayHit));
    raysTraced_.add(n);
    for (std::size_t i = 0; i < n; ++i) {
      Hit& h = hits[begin + i];
      found[begin + i] = hitOf(tile[i], h, wantNormal) ? &h : nullptr;
    }
  }
}

bool RtScene::hitOf(const RTCRayHit& rh, Hit& hit, bool wantNormal) const {
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  // A hit inside a prototype names its instance in instID[0] and has an object-space Ng.
  const bool instanced = rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID;
  const unsigned id = instanced ? rh.hit.instID[0] : rh.hit.geomID;
  // Stored field by field into the caller's Hit: a local Hit returned in a std::optional was
  // built in 1- to 8-byte stores and copied in 16-byte loads, three store-forwarding stalls per
  // ray, about half of this function's time (perf annotate, issue 14).
  hit.instance = int(id);
  hit.primitive = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  hit.t = rh.ray.tfar;
  hit.Ng = vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  if (instanced) hit.Ng = geometry_[id].normalToWorld * hit.Ng;
  const AnalyticInstance* analytic = geometry_[id].analytic;
  hit.analytic = analytic != nullptr;
  // The intersect callback leaves a quadric's Ng to here (analytic_geometry.cpp).
  if (wantNormal && analytic && !analytic->sdf)
    hit.Ng = analyticHitNormal(*analytic, int(hit.primitive), vec2(hit.u, hit.v));
  return true;
}

bool RtScene::occluded(const vec3& origin, const vec3& direction, float tnear, float tfar,
                       float time) const {
  if (!(tnear <= tfar)) return false;  // inactive, as in the batch API
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray;
  setEmbreeRay(ray, origin, direction, tnear, tfar, time);
  rtcOccluded1(scene_, &context, &ray);
  raysTraced_.add(1);
  // Embree sets tfar to -inf on a hit (rtcOccluded1 docs).
  return ray.tfar < 0.f;
}

RTCIntersectContextFlags RtScene::streamFlag(bool coherent) const {
  // Embree 3.13.5's coherent stream kernels hung, intermittently, inside rtcOccluded1M on a scene
  // with instances: four ordinary shadow rays (finite, tnear 0, tfar ~20) never returned on
  // NegativeScaleTest's mirrored instances, in the ASan build (both CI runs of a branch that
  // only changed the caller's stack layout, and 3 of 4 runs here); with the INCOHERENT flag,
  // which takes Embree's packet path instead of its frustum path, 8 of 8 passed. It is also the
  // faster flag there (MetalRoughSpheresNoTextures, 640x480: rt_shadows 31.1 against 37.6 CPU
  // ms, rt_reflection 53.2 against 71.7, same image); on whitted, which has no instances, the
  // coherent flag saves rt_shadows a fifth (22.9 against 28.3): docs/benchmarks.md, session 17.
  return coherent && instanced_ == 0 && moving_ == 0 ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                     : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
}

void RtScene::occludedTile(std::span<RTCRay> rays, bool coherent) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = streamFlag(coherent);
  std::uint64_t active = 0;
  for (const RTCRay& r : rays) active += r.tnear <= r.tfar ? 1 : 0;
  if (alphaMasked_ > 0) {
    // Alpha-filtered geometry: one ray at a time. A coherent rtcOccluded1M stream over this
    // scene's filter functions hung inside Embree 3.13.5, intermittently, in the ASan suite
    // (VisibilityAlpha; docs/benchmarks.md, session 13); rtcOccluded1 gives the same answers.
    for (RTCRay& r : rays)
      if (r.tnear <= r.tfar) rtcOccluded1(scene_, &context, &r);
  } else {
    rtcOccluded1M(scene_, &context, rays.data(), unsigned(rays.size()), sizeof(RTCRay));
  }
  raysTraced_.add(active);
}

void RtScene::occludedBatch(std::span<const OcclusionRay> rays, std::span<std::uint8_t> out,
                            bool coherent) const {
  if (out.size() < rays.size()) throw Error("RtScene::occludedBatch: output span too small");
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, rays.size(), kTileRays),
      [&](const tbb::blocked_range<std::size_t>& range) {
        RTCRay tile[kTileRays];  // RTCRay is RTC_ALIGN(16), as rtcOccluded1M requires
        for (std::size_t begin = range.begin(); begin < range.end(); begin += kTileRays) {
          const std::size_t count = std::min(kTileRays, range.end() - begin);
          for (std::size_t i = 0; i < count; ++i) setEmbreeRay(tile[i], rays[begin + i]);
          occludedTile({tile, count}, coherent);
          // An inactive ray (tnear > tfar) is untouched by Embree; it reports "not
          // occluded".
          for (std::size_t i = 0; i < count; ++i)
            out[begin + i] = rays[begin + i].tnear <= rays[begin + i].tfar && tile[i].tfar < 0.f;
        }
      });
}

}  // namespace diptych
