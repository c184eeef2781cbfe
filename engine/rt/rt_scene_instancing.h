#pragma once
// RtScene's building blocks: Embree triangle geometry, and instancing of repeated meshes.
//
// A glTF file may place the same triangles many times (MetalRoughSpheresNoTextures: 102 meshes
// over 26 position/index accessor pairs, 1.04 M triangles). Flattened, each copy gets its own
// BVH; instanced, each distinct mesh is built once, in object space, into a prototype Embree
// scene and every copy is an RTC_GEOMETRY_TYPE_INSTANCE of it (Embree's "instanced_geometry"
// tutorial). Only meshes that occur at least twice are instanced: every other mesh stays a
// world-space copy of WorldMesh, bit for bit, as before.
//
// What instancing changes for a hit: Embree intersects the object-space triangle with the ray
// taken to object space, so (u, v) and t carry the rounding of that transform. The point
// rebuilt by interpolatePosition() from the world-space vertices then lies within a few ULPs of
// the vertex coordinates from the one Embree found, well inside the 256-ULP error box of
// offsetRayOrigin() (engine/rt/ray_offset.h).
#include <embree3/rtcore.h>

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "engine/rt/rt_device.h"
#include "engine/scene/world_geometry.h"

namespace diptych::rt_detail {

// A committed triangle geometry holding copies of `positions` and `indices` (3 per triangle).
// Copied, not shared: Embree requires shared vertex buffers to stay readable 16 bytes past the
// last element (an SSE load of the final vec3), which std::vector<vec3> does not promise.
// Embree-allocated buffers are padded. The values are bit-identical copies.
RTCGeometry newTriangleGeometry(const RtDevice& device, std::span<const vec3> positions,
                                std::span<const std::uint32_t> indices, RTCBuildQuality quality,
                                const std::string& what);

// Groups of world meshes (indices into world.meshes) whose source meshes hold the same
// object-space triangles (equal positions and indices) with the same mirroring, two or more
// members each. Meshes with eligible[i] == false are left out.
std::vector<std::vector<std::size_t>> sharedMeshGroups(const Scene& scene,
                                                       const WorldGeometry& world,
                                                       const std::vector<bool>& eligible);

// The object-space triangles of world mesh `id`'s source mesh, winding flipped as in WorldMesh
// when the instance mirrors, committed into a scene of their own.
RTCScene newPrototypeScene(const RtDevice& device, const Scene& scene, const WorldMesh& mesh,
                           RTCBuildQuality quality, RTCSceneFlags flags);

// An instance of `prototype` placed by `transform` (the Instance's), committed.
RTCGeometry newInstanceGeometry(const RtDevice& device, RTCScene prototype, const mat4& transform);

// A committed scene holding one committed geometry (released into it) at geomID 0.
RTCScene newSceneOf(const RtDevice& device, RTCGeometry geometry, RTCBuildQuality quality,
                    RTCSceneFlags flags, const std::string& what);

// A motion-blurred instance of `prototype` (geometry in the world space of kFrameTime) moving by
// `motion` over the shutter: two time steps, translate((0 - kFrameTime) motion) at time 0 and
// translate((1 - kFrameTime) motion) at time 1, which Embree interpolates linearly at each
// ray's time (Embree 3 docs, rtcSetGeometryTimeStepCount: instance motion blur). At kFrameTime
// the translation is exactly zero: (1 - t) a + t b with b = -a.
RTCGeometry newMovingInstanceGeometry(const RtDevice& device, RTCScene prototype,
                                      const vec3& motion);

}  // namespace diptych::rt_detail
