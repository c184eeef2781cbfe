#include "passes/raster/screen_rect.h"

#include <limits>
#include <mutex>

#include "engine/graph/render_world.h"

namespace diptych {

PixelRect windowRect(const Aabb& box, const mat4& viewProj, int width, int height) {
  const PixelRect whole{ivec2(0), ivec2(width, height)};
  if (box.empty()) return {};
  vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int i = 0; i < 8; ++i) {
    const vec4 c = viewProj * vec4(i & 1 ? box.hi.x : box.lo.x, i & 2 ? box.hi.y : box.lo.y,
                                   i & 4 ? box.hi.z : box.lo.z, 1.f);
    if (!(c.w > 1e-6f)) return whole;
    const vec2 w = (0.5f * vec2(c) / c.w + 0.5f) * vec2(float(width), float(height));
    lo = glm::min(lo, w);
    hi = glm::max(hi, w);
  }
  // Clamped in float first: a corner just in front of the eye plane (w a little above 1e-6)
  // projects far beyond the int range, and converting that to int is undefined (x86 gives
  // INT_MIN, which made the rectangle empty). Clamping to one pixel beyond the viewport keeps
  // every value exact in int and leaves the result unchanged for in-range corners.
  const vec2 size{float(width), float(height)};
  lo = glm::clamp(lo, vec2(-1.f), size + 1.f);
  hi = glm::clamp(hi, vec2(-1.f), size + 1.f);
  // One pixel of margin for rounding in the projection and the rasterizer's snapping.
  PixelRect r;
  r.lo = glm::clamp(ivec2(glm::floor(lo)) - 1, ivec2(0), ivec2(width, height));
  r.hi = glm::clamp(ivec2(glm::ceil(hi)) + 1, ivec2(0), ivec2(width, height));
  return r;
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

namespace {
// One per RenderWorld (RenderWorld::cpuCached): its geometry never changes, so the bounds are
// computed on first use and shared by every producer that asks.
struct MeshBoundsCache {
  std::once_flag once;
  std::vector<Aabb> bounds;
};
}  // namespace

const std::vector<Aabb>& meshBounds(RenderWorld& world) {
  auto& cache = world.cpuCached<MeshBoundsCache>();
  std::call_once(cache.once, [&] {
    const WorldGeometry& geometry = world.geometry();
    cache.bounds.assign(geometry.meshes.size(), Aabb{});
    for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
      for (const vec3& p : geometry.meshes[m].positions) cache.bounds[m].extend(p);
  });
  return cache.bounds;
}

PixelRect unionRect(const std::vector<Aabb>& bounds, const mat4& viewProj, int width, int height,
                    const std::function<bool(int)>& select, std::vector<PixelRect>& rects) {
  rects.assign(bounds.size(), PixelRect{});
  PixelRect covered{ivec2(width, height), ivec2(0)};
  for (std::size_t m = 0; m < bounds.size(); ++m) {
    rects[m] = windowRect(bounds[m], viewProj, width, height);
    if (select(int(m)) && !rects[m].empty()) {
      covered.lo = glm::min(covered.lo, rects[m].lo);
      covered.hi = glm::max(covered.hi, rects[m].hi);
    }
  }
  return covered;
}

}  // namespace diptych
