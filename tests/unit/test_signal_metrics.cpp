#include <gtest/gtest.h>

#include "engine/metrics/signal_metrics.h"

using namespace diptych;

namespace {
// A w x h visibility with shadow (0) left of column `edge`, lit (1) from it on.
std::vector<float> halfShadow(int w, int h, int edge) {
  std::vector<float> v(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[std::size_t(y) * w + x] = x < edge ? 0.f : 1.f;
  return v;
}
}  // namespace

TEST(VisibilityConfusion, IdenticalSignalsHaveNoErrors) {
  const auto v = halfShadow(20, 10, 8);
  const std::vector<std::uint8_t> mask(200, 1);
  const VisibilityConfusion c = compareVisibility(v, v, mask, 20, 10, 2);
  EXPECT_EQ(c.receivers, 200);
  EXPECT_EQ(c.falseShadowOutside + c.falseLitOutside + c.falseShadowInside + c.falseLitInside, 0);
  EXPECT_DOUBLE_EQ(c.meanBoundaryDisplacement, 0.0);
  EXPECT_GT(c.correctInside, 0);  // the band around column 8 exists
}

TEST(VisibilityConfusion, GrownShadowIsFalseShadowWithPositiveDisplacement) {
  const std::vector<std::uint8_t> mask(20 * 10, 1);
  const auto exact = halfShadow(20, 10, 8);
  const auto grown = halfShadow(20, 10, 12);  // shadow 4 px wider (acne-like over-darkening)
  const VisibilityConfusion c = compareVisibility(grown, exact, mask, 20, 10, 2);
  EXPECT_EQ(c.falseLitOutside + c.falseLitInside, 0);
  EXPECT_EQ(c.falseShadowOutside + c.falseShadowInside, 4 * 10);
  // The exact boundary is columns 7 | 8, so the 2-pixel band covers columns 5..10; column 11
  // is the one false-shadow column outside it.
  EXPECT_EQ(c.falseShadowOutside, 10);
  EXPECT_NEAR(c.meanBoundaryDisplacement, 4.0, 1e-9);
  const VisibilityConfusion s = compareVisibility(halfShadow(20, 10, 6), exact, mask, 20, 10, 2);
  EXPECT_EQ(s.falseLitInside, 20);
  EXPECT_NEAR(s.meanBoundaryDisplacement, -2.0, 1e-9);
}

TEST(VisibilityConfusion, UncoveredPixelsAreIgnored) {
  const auto exact = halfShadow(4, 1, 2);
  const std::vector<float> approx = {1, 1, 1, 1};
  const std::vector<std::uint8_t> mask = {0, 1, 1, 1};
  const VisibilityConfusion c = compareVisibility(approx, exact, mask, 4, 1, 0);
  EXPECT_EQ(c.receivers, 3);
  EXPECT_EQ(c.falseLitInside + c.falseLitOutside, 1);
}

TEST(SignalError, RadianceErrorOverContributingPixelsOnly) {
  Image a(2, 1, 3, 1.f), e(2, 1, 3, 1.f);
  a.at(1, 0, 0) = 3.f;  // error only in the masked-out pixel
  EXPECT_EQ(compareRadiance(a, e, {1, 0}).rmse, 0.0);
  const SignalError s = compareRadiance(a, e, {1, 1});
  EXPECT_EQ(s.pixels, 2);
  EXPECT_NEAR(s.rmse, std::sqrt(4.0 / 6.0), 1e-12);
  EXPECT_NEAR(s.relativeRmse, std::sqrt(4.0 / 6.0), 1e-12);
}
