#include "engine/rt/rt_scene.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/rt/analytic_geometry.h"
#include "engine/scene/sdf.h"
#include "engine/shading/texture_sampling.h"

namespace diptych {
namespace {

// Rays per stream call. Large enough for Embree to amortise its stream setup, small enough
// that a tile's RTCRay array (48 bytes each) stays on the stack and TBB can balance tiles.
constexpr std::size_t kTileRays = 256;

RTCRay makeRay(const vec3& origin, const vec3& direction, float tnear, float tfar) {
  RTCRay r{};
  r.org_x = origin.x;
  r.org_y = origin.y;
  r.org_z = origin.z;
  r.dir_x = direction.x;
  r.dir_y = direction.y;
  r.dir_z = direction.z;
  r.tnear = tnear;
  r.tfar = tfar;
  r.time = 0.f;
  r.mask = ~0u;  // ray masks are compiled out of Debian's Embree; set as the docs ask anyway
  r.flags = 0;
  return r;
}

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
  rtcSetSceneFlags(scene_, options.robust ? RTC_SCENE_FLAG_ROBUST : RTC_SCENE_FLAG_NONE);

  geometry_.resize(world.meshes.size());
  bool warnedNoFilters = false;
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
      rtcAttachGeometryByID(scene_, geom, unsigned(id));
      rtcReleaseGeometry(geom);
      device.check("adding analytic instance " + std::to_string(id));
      ++analytic_;
      continue;
    }
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles == 0 || mesh.positions.empty()) continue;
    RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, options.quality);
    // Copied, not shared: Embree requires shared vertex buffers to stay readable 16 bytes past
    // the last element (an SSE load of the final vec3), which std::vector<vec3> does not
    // promise. Embree-allocated buffers are padded. The values are bit-identical copies.
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                sizeof(float) * 3, mesh.positions.size()));
    auto* indices = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(std::uint32_t) * 3, triangles));
    device.check("allocating buffers for instance " + std::to_string(id));
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      vertices[3 * i + 0] = mesh.positions[i].x;
      vertices[3 * i + 1] = mesh.positions[i].y;
      vertices[3 * i + 2] = mesh.positions[i].z;
    }
    std::memcpy(indices, mesh.indices.data(), sizeof(std::uint32_t) * 3 * triangles);
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
    rtcAttachGeometryByID(scene_, geom, unsigned(id));
    rtcReleaseGeometry(geom);  // the scene holds its own reference
    device.check("adding instance " + std::to_string(id) + " (" + std::to_string(triangles) +
                 " triangles)");
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
}

std::optional<Hit> RtScene::intersect(const Ray& ray, float tnear, float tfar) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh{};
  rh.ray = makeRay(ray.origin, ray.direction, tnear, tfar);
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &rh);
  raysTraced_.fetch_add(1, std::memory_order_relaxed);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  Hit hit;
  hit.instance = int(rh.hit.geomID);
  hit.primitive = rh.hit.primID;
  hit.u = rh.hit.u;
  hit.v = rh.hit.v;
  hit.t = rh.ray.tfar;
  hit.Ng = vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  hit.analytic = geometry_[rh.hit.geomID].analytic != nullptr;
  return hit;
}

bool RtScene::occluded(const vec3& origin, const vec3& direction, float tnear, float tfar) const {
  if (!(tnear <= tfar)) return false;  // inactive, as in the batch API
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = makeRay(origin, direction, tnear, tfar);
  rtcOccluded1(scene_, &context, &ray);
  raysTraced_.fetch_add(1, std::memory_order_relaxed);
  // Embree sets tfar to -inf on a hit (rtcOccluded1 docs).
  return ray.tfar < 0.f;
}

void RtScene::occludedBatch(std::span<const OcclusionRay> rays, std::span<std::uint8_t> out,
                            bool coherent) const {
  if (out.size() < rays.size()) throw Error("RtScene::occludedBatch: output span too small");
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rays.size(), kTileRays),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      RTCIntersectContext context;
                      rtcInitIntersectContext(&context);
                      context.flags = coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                               : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
                      RTCRay tile[kTileRays];  // RTCRay is RTC_ALIGN(16), as rtcOccluded1M requires
                      std::uint64_t active = 0;
                      for (std::size_t begin = range.begin(); begin < range.end();
                           begin += kTileRays) {
                        const std::size_t count = std::min(kTileRays, range.end() - begin);
                        for (std::size_t i = 0; i < count; ++i) {
                          const OcclusionRay& r = rays[begin + i];
                          tile[i] = makeRay(r.origin, r.direction, r.tnear, r.tfar);
                          active += r.tnear <= r.tfar ? 1 : 0;
                        }
                        rtcOccluded1M(scene_, &context, tile, unsigned(count), sizeof(RTCRay));
                        for (std::size_t i = 0; i < count; ++i) {
                          const OcclusionRay& r = rays[begin + i];
                          // An inactive ray (tnear > tfar) is untouched by Embree; it reports "not
                          // occluded".
                          out[begin + i] = (r.tnear <= r.tfar && tile[i].tfar < 0.f) ? 1 : 0;
                        }
                      }
                      raysTraced_.fetch_add(active, std::memory_order_relaxed);
                    });
}

}  // namespace diptych
