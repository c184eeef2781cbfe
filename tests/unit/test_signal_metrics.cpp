#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/metrics/signal_metrics.h"

namespace DIPTYCH_UNITY_ID {
using namespace diptych;
// A w x h visibility with shadow (0) left of column `edge`, lit (1) from it on.
std::vector<float> halfShadow(int w, int h, int edge) {
  std::vector<float> v(std::size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[std::size_t(y) * w + x] = x < edge ? 0.f : 1.f;
  return v;
}

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

// Shadow on columns 0..19 of a 40 x 10 frame. The approximate signal has one acne pixel deep in
// the light, a shadow edge pulled back by 8 columns (peter-panning next to the boundary, the
// nearest 3 columns inside the band) and one false-lit pixel 19 px from any exact light (leak).
TEST(ShadowArtifacts, ClassesCountsErrorAndDisplacement) {
  const int w = 40, h = 10;
  const auto exact = halfShadow(w, h, 20);
  auto approx = halfShadow(w, h, 12);
  approx[5 * w + 35] = 0.f;  // acne
  approx[5 * w + 1] = 1.f;   // leak: distance to column 20 is 19 > reach 16
  const std::vector<std::uint8_t> mask(w * h, 1);
  const std::vector<float> footprint(w * h, 0.5f);
  const ShadowArtifacts a = classifyShadows(approx, exact, mask, w, h, footprint, 2, 16);
  EXPECT_EQ(a.receivers, 400);
  EXPECT_EQ(a.litOutside, 170);     // columns 23..39
  EXPECT_EQ(a.shadowOutside, 170);  // columns 0..16
  EXPECT_EQ(a.acne, 1);
  EXPECT_EQ(a.peterPanning, 5 * 10);  // columns 12..16
  EXPECT_EQ(a.lightLeak, 1);
  EXPECT_EQ(a.boundaryErrors, 3 * 10);  // columns 17..19, inside the band
  EXPECT_DOUBLE_EQ(a.acneRate(), 1.0 / 170);
  EXPECT_DOUBLE_EQ(a.peterPanningRate(), 50.0 / 170);
  EXPECT_DOUBLE_EQ(a.misclassified(), 52.0 / 340);
  EXPECT_DOUBLE_EQ(a.meanAbsError, 82.0 / 400);
  EXPECT_NEAR(a.displacementPx, -8.0, 1e-9);  // the whole +-8 px line came loose
  EXPECT_NEAR(a.displacementWorld, -4.0, 1e-9);
  EXPECT_EQ(a.classes[5 * w + 35], ShadowClass::Acne);
  EXPECT_EQ(a.classes[5 * w + 14], ShadowClass::PeterPanning);
  EXPECT_EQ(a.classes[5 * w + 1], ShadowClass::LightLeak);
  EXPECT_EQ(shadowClassImage(a, w, h).width, w);
}

// Contacts decide peter-panning vs leak (docs/shadow-bias.md §3). Exact shadow on columns 0..29
// of a 40 x 10 frame; object 1 covers columns 0..9, object 0 the rest; column 20 is a contact
// (the caster touches the receiver there). False light in column 14 (object 0, 6 px from the
// contact) is peter-panning; in column 8 (12 px away, but on object 1: the walk may not cross to
// another object) it is a leak; with a reach of 4 px the column-14 light is a leak too.
TEST(ShadowArtifacts, ContactsSeparatePeterPanningFromLeaks) {
  const int w = 40, h = 10;
  const auto exact = halfShadow(w, h, 30);
  auto approx = exact;
  ShadowContacts contacts;
  contacts.contact.assign(w * h, 0);
  contacts.object.assign(w * h, 0);
  for (int y = 0; y < h; ++y) {
    approx[y * w + 14] = approx[y * w + 8] = 1.f;
    contacts.contact[y * w + 20] = 1;
    for (int x = 0; x < 10; ++x) contacts.object[y * w + x] = 1;
  }
  const std::vector<std::uint8_t> mask(w * h, 1);
  const ShadowArtifacts a = classifyShadows(approx, exact, mask, w, h, {}, 2, 16, &contacts);
  EXPECT_EQ(a.contacts, h);
  EXPECT_EQ(a.peterPanning, h);
  EXPECT_EQ(a.lightLeak, h);
  EXPECT_EQ(a.classes[5 * w + 14], ShadowClass::PeterPanning);
  EXPECT_EQ(a.classes[5 * w + 8], ShadowClass::LightLeak);
  // Without contacts the distance proxy calls both peter-panning (within 22 px of exact light).
  const ShadowArtifacts proxy = classifyShadows(approx, exact, mask, w, h, {}, 2, 22);
  EXPECT_EQ(proxy.peterPanning, 2 * h);
  const ShadowArtifacts near = classifyShadows(approx, exact, mask, w, h, {}, 2, 4, &contacts);
  EXPECT_EQ(near.peterPanning, 0);
  EXPECT_EQ(near.lightLeak, 2 * h);
  ShadowContacts wrong = contacts;
  wrong.object.pop_back();
  EXPECT_THROW(classifyShadows(approx, exact, mask, w, h, {}, 2, 16, &wrong), Error);
}

// A soft (PCF-like) signal is scored on its value: 0.4 where the exact answer is 0 is no
// classification error (below 0.5) but a mean absolute error of 0.4 on those pixels.
TEST(ShadowArtifacts, SoftValuesCountInTheMeanAbsoluteError) {
  const std::vector<float> exact(16, 0.f), soft(16, 0.4f);
  const std::vector<std::uint8_t> mask(16, 1);
  const ShadowArtifacts a = classifyShadows(soft, exact, mask, 4, 4);
  EXPECT_EQ(a.acne + a.peterPanning + a.lightLeak + a.boundaryErrors, 0);
  EXPECT_NEAR(a.meanAbsError, 0.4, 1e-6);
  EXPECT_THROW(classifyShadows(soft, exact, mask, 4, 4, std::vector<float>(3, 1.f)), Error);
}
}  // namespace DIPTYCH_UNITY_ID
