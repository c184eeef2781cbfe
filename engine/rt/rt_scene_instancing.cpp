#include "engine/rt/rt_scene_instancing.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <map>
#include <tuple>

#include "engine/scene/camera_math.h"

namespace diptych::rt_detail {

RTCGeometry newTriangleGeometry(const RtDevice& device, std::span<const vec3> positions,
                                std::span<const std::uint32_t> indices, RTCBuildQuality quality,
                                const std::string& what) {
  const std::size_t triangles = indices.size() / 3;
  RTCGeometry geom = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuildQuality(geom, quality);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, sizeof(float) * 3, positions.size()));
  auto* index = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, sizeof(std::uint32_t) * 3, triangles));
  if (!vertices || !index) rtcReleaseGeometry(geom);
  device.check("allocating buffers for " + what);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    vertices[3 * i + 0] = positions[i].x;
    vertices[3 * i + 1] = positions[i].y;
    vertices[3 * i + 2] = positions[i].z;
  }
  std::memcpy(index, indices.data(), sizeof(std::uint32_t) * 3 * triangles);
  return geom;
}

namespace {

// Object-space triangle index k of a world mesh's source, winding as in WorldMesh.
std::uint32_t sourceIndex(const Mesh& m, bool mirrored, std::size_t k) {
  const std::size_t corner = k % 3;
  if (mirrored && corner != 0) k += corner == 1 ? 1 : -1;  // swap corners 1 and 2
  return m.indices[k];
}

bool sameTriangles(const Mesh& a, const Mesh& b) {
  if (&a == &b) return true;
  return a.positions.size() == b.positions.size() && a.indices.size() == b.indices.size() &&
         std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(vec3)) ==
             0 &&
         std::memcmp(a.indices.data(), b.indices.data(),
                     a.indices.size() * sizeof(std::uint32_t)) == 0;
}

}  // namespace

std::vector<std::vector<std::size_t>> sharedMeshGroups(const Scene& scene,
                                                       const WorldGeometry& world,
                                                       const std::vector<bool>& eligible) {
  // Candidates are bucketed by sizes, mirroring and a few sampled coordinates, then compared in
  // full (memcmp) with each group's first member: linear in the bytes, no hashing of every mesh.
  using Key = std::tuple<std::size_t, std::size_t, bool, float, float, float>;
  std::map<Key, std::vector<std::vector<std::size_t>>> buckets;
  for (std::size_t id = 0; id < world.meshes.size(); ++id) {
    if (!eligible[id]) continue;
    const WorldMesh& w = world.meshes[id];
    const Mesh& m = scene.meshes[scene.instances[std::size_t(w.instance)].mesh];
    if (m.positions.empty() || m.indices.size() < 3) continue;
    const vec3& first = m.positions.front();
    const vec3& last = m.positions.back();
    const Key key{
        m.positions.size(), m.indices.size(), w.mirrored, first.x, first.y + last.z, last.x};
    auto& groups = buckets[key];
    bool placed = false;
    for (auto& g : groups) {
      const WorldMesh& rep = world.meshes[g.front()];
      if (sameTriangles(scene.meshes[scene.instances[std::size_t(rep.instance)].mesh], m)) {
        g.push_back(id);
        placed = true;
        break;
      }
    }
    if (!placed) groups.push_back({id});
  }
  std::vector<std::vector<std::size_t>> shared;
  for (auto& [key, groups] : buckets)
    for (auto& g : groups)
      if (g.size() >= 2) shared.push_back(std::move(g));
  return shared;
}

RTCScene newPrototypeScene(const RtDevice& device, const Scene& scene, const WorldMesh& mesh,
                           RTCBuildQuality quality, RTCSceneFlags flags) {
  const Mesh& m = scene.meshes[scene.instances[std::size_t(mesh.instance)].mesh];
  std::vector<std::uint32_t> indices(m.indices.size());
  for (std::size_t k = 0; k < indices.size(); ++k) indices[k] = sourceIndex(m, mesh.mirrored, k);
  RTCGeometry geom = newTriangleGeometry(device, m.positions, indices, quality, m.name);
  rtcCommitGeometry(geom);
  return newSceneOf(device, geom, quality, flags, m.name);
}

RTCGeometry newInstanceGeometry(const RtDevice& device, RTCScene prototype, const mat4& transform) {
  RTCGeometry inst = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(inst, prototype);
  rtcSetGeometryTransform(inst, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &transform[0][0]);
  rtcCommitGeometry(inst);
  device.check("instancing a prototype");
  return inst;
}

RTCScene newSceneOf(const RtDevice& device, RTCGeometry geometry, RTCBuildQuality quality,
                    RTCSceneFlags flags, const std::string& what) {
  RTCScene scene = rtcNewScene(device.handle());
  device.check("rtcNewScene (prototype of " + what + ")");
  rtcSetSceneBuildQuality(scene, quality);
  rtcSetSceneFlags(scene, flags);
  rtcAttachGeometryByID(scene, geometry, 0);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene);
  device.check("building the prototype of " + what);
  return scene;
}

RTCGeometry newMovingInstanceGeometry(const RtDevice& device, RTCScene prototype,
                                      const vec3& motion) {
  RTCGeometry inst = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(inst, prototype);
  rtcSetGeometryTimeStepCount(inst, 2);
  for (unsigned step = 0; step < 2; ++step) {
    const mat4 moved = glm::translate(mat4(1.f), (float(step) - kFrameTime) * motion);
    rtcSetGeometryTransform(inst, step, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &moved[0][0]);
  }
  rtcCommitGeometry(inst);
  device.check("a moving instance");
  return inst;
}

}  // namespace diptych::rt_detail
