// Window rectangles of mesh bounds (passes/raster/screen_rect.cpp), which scissor the env_* and
// blend producers: a rectangle that misses a pixel of its box drops that pixel's reflection or
// transmission. Corners just in front of the eye plane project far beyond the int range; they
// must give the whole covered side of the viewport, never an empty or wrapped rectangle.
#include <gtest/gtest.h>

#include "passes/raster/screen_rect.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

constexpr int kW = 160, kH = 120;

// Eye at the origin looking down -z (clip w = view depth), 90 degrees vertical field of view.
mat4 viewProj() {
  return glm::perspective(glm::radians(90.f), float(kW) / float(kH), 0.05f, 100.f) *
         glm::lookAt(vec3(0.f), vec3(0.f, 0.f, -1.f), vec3(0.f, 1.f, 0.f));
}

Aabb box(vec3 lo, vec3 hi) {
  Aabb b;
  b.extend(lo);
  b.extend(hi);
  return b;
}

void expectRect(const PixelRect& r, ivec2 lo, ivec2 hi) {
  EXPECT_EQ(r.lo.x, lo.x);
  EXPECT_EQ(r.lo.y, lo.y);
  EXPECT_EQ(r.hi.x, hi.x);
  EXPECT_EQ(r.hi.y, hi.y);
}

TEST(ScreenRect, ABoxInViewGetsItsProjectionPlusOnePixel) {
  // x, y in [-1, 1] at depth 2, 90 degree vertical fov, aspect 4:3: NDC x in +-0.375, y in
  // +-0.5, so pixels [50, 110) x [30, 90), plus one pixel of margin (and one of rounding).
  const PixelRect r =
      windowRect(box(vec3(-1.f, -1.f, -2.f), vec3(1.f, 1.f, -2.f)), viewProj(), kW, kH);
  EXPECT_NEAR(r.lo.x, 49, 1);
  EXPECT_NEAR(r.lo.y, 29, 1);
  EXPECT_NEAR(r.hi.x, 111, 1);
  EXPECT_NEAR(r.hi.y, 91, 1);
}

TEST(ScreenRect, ABoxTouchingTheEyePlaneGetsEveryPixelItCovers) {
  // Its near corners have w = 2e-6 (just above the 1e-6 cut), so x / w * width / 2 is ~1e11,
  // far beyond int: converted without clamping, this gave an empty rectangle.
  const PixelRect whole = windowRect(
      box(vec3(-1000.f, -1000.f, -2.f), vec3(1000.f, 1000.f, -2e-6f)), viewProj(), kW, kH);
  expectRect(whole, ivec2(0), ivec2(kW, kH));
  // Only the right half (x >= 0) and the upper half (y >= 0): its rectangle starts at the
  // centre (less one pixel of margin) and reaches the frame's edges.
  const PixelRect quarter =
      windowRect(box(vec3(0.f, 0.f, -2.f), vec3(1000.f, 1000.f, -2e-6f)), viewProj(), kW, kH);
  expectRect(quarter, ivec2(kW / 2 - 1, kH / 2 - 1), ivec2(kW, kH));
}

TEST(ScreenRect, ABoxStraddlingTheEyePlaneGetsTheWholeViewport) {
  const PixelRect r =
      windowRect(box(vec3(0.5f, 0.5f, -2.f), vec3(1.f, 1.f, 1.f)), viewProj(), kW, kH);
  expectRect(r, ivec2(0), ivec2(kW, kH));
}

TEST(ScreenRect, ABoxFarOffScreenGetsAnEmptyRectangle) {
  // Right of the frame by ~1e11 pixels (beyond int), and just right of it.
  EXPECT_TRUE(
      windowRect(box(vec3(1e9f, -1.f, -2.f), vec3(2e9f, 1.f, -1.f)), viewProj(), kW, kH).empty());
  EXPECT_TRUE(
      windowRect(box(vec3(10.f, -1.f, -2.f), vec3(11.f, 1.f, -2.f)), viewProj(), kW, kH).empty());
  EXPECT_TRUE(windowRect(Aabb{}, viewProj(), kW, kH).empty());
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
