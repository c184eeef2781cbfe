#pragma once
// Window rectangles of scene meshes, for scissoring the per-pixel steps of raster producers to
// the part of the frame where their objects can be (a pixel outside every such rectangle cannot
// show one of them). Used by the blend producers (transparent objects) and the env_* lookups
// (reflective objects).
#include <functional>
#include <vector>

#include "engine/core/math.h"
#include "engine/scene/world_geometry.h"

namespace diptych {

class RenderWorld;

// Window rectangle [lo, hi) (pixels, GL window coordinates, origin bottom left).
struct PixelRect {
  ivec2 lo{0}, hi{0};
  bool empty() const { return hi.x <= lo.x || hi.y <= lo.y; }
  glm::ivec4 scissor() const { return {lo, hi - lo}; }  // (x, y, width, height)
};

// Every pixel centre that `box` can cover: the projection of a box wholly in front of the eye is
// the convex hull of its projected corners, plus one pixel of margin for rounding; a box
// reaching to or behind the eye plane gets the whole viewport; an empty box, nothing.
PixelRect windowRect(const Aabb& box, const mat4& viewProj, int width, int height);

bool overlap(const PixelRect& a, const PixelRect& b);

// World bounds of each mesh of world.geometry(), computed once per world and shared by every
// producer (the geometry of a RenderWorld is fixed).
const std::vector<Aabb>& meshBounds(RenderWorld& world);

// The union of the window rectangles of the meshes for which `select(mesh index)` holds
// (empty when none is visible); `rects` receives every mesh's own rectangle.
PixelRect unionRect(const std::vector<Aabb>& bounds, const mat4& viewProj, int width, int height,
                    const std::function<bool(int)>& select, std::vector<PixelRect>& rects);

}  // namespace diptych
