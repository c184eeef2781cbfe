#include "passes/raster/screen_rect.h"

#include <limits>

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
  // One pixel of margin for rounding in the projection and the rasterizer's snapping.
  PixelRect r;
  r.lo = glm::clamp(ivec2(glm::floor(lo)) - 1, ivec2(0), ivec2(width, height));
  r.hi = glm::clamp(ivec2(glm::ceil(hi)) + 1, ivec2(0), ivec2(width, height));
  return r;
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

const std::vector<Aabb>& meshBounds(std::vector<Aabb>& cache, const WorldGeometry& geometry) {
  if (cache.size() != geometry.meshes.size()) {
    cache.assign(geometry.meshes.size(), Aabb{});
    for (std::size_t m = 0; m < geometry.meshes.size(); ++m)
      for (const vec3& p : geometry.meshes[m].positions) cache[m].extend(p);
  }
  return cache;
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
