#pragma once
// The receivers of one sweep scene state (docs/shadow-bias.md): per pixel, the world geometry
// the classes and the analytic predictions need — pixel footprint, incidence, steepest light-
// depth direction, the contacts of the swept light — and the texel-size predictions at a map
// resolution.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/graph/render_world.h"
#include "engine/metrics/signal_metrics.h"
#include "samples/diptych/compare/runner.h"

namespace diptych::cli {

inline constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// The middle element of v (the upper one of the two middle elements for an even count; 0 for
// none): the sweep's per-receiver summaries.
double upperMedian(std::vector<double> v);

struct ReceiverPixel {
  std::size_t pixel = 0;
  vec3 position{0.f}, toLight{0.f};
  vec3 normal{0.f};      // unit face normal, on the light's side
  double incidence = 0;  // degrees between the light-side face normal and the light
  bool lit = false;      // the exact answer (visibility >= 0.5)
};

// One scene state: its world, the exact signal, the receiver mask and per-pixel geometry.
struct StateReference {
  std::unique_ptr<Scene> scene;
  std::unique_ptr<RenderWorld> world;
  GraphRun exact;
  std::string exactSignal;
  std::vector<std::uint8_t> mask;
  std::vector<float> footprint;  // world size of a pixel on its receiver (sqrt of its area)
  std::vector<double> receiverFootprints;
  std::vector<ReceiverPixel> receivers;  // light-dependent fields only when the light exists
  ShadowContacts contacts;               // of the swept light (empty without one)
  double contactDistance = 0;            // world units
  std::string contactFile;               // its image, relative to the sweep's folder
  int unreachedPixels = 0;               // left out of the mask: the light sends them nothing
};

// The contacts as an image: contact pixels red, other receivers grey, background black.
Image contactImage(const StateReference& state, int width, int height);

// Fills footprint, receivers and contacts from the exact run's G-buffer and signal. A contact
// pixel is exactly shadowed and its exact shadow ray (toward the light's centre) meets the
// occluder within `contactDistance` world units (< 0: 1e-3 x the scene's bounding diagonal).
// `reachedOnly` (a visibility sweep): a pixel that the light sends nothing (lightReaches: outside
// a spot's cone, behind a one-sided area light, beyond its range) leaves the mask. Its visibility
// multiplies zero in every shading, and the exact side writes 1 there without tracing a ray,
// so a shadow map's 0 there would count as a false shadow that no image shows.
void measureGeometry(StateReference& state, const FrameSettings& frame, int light,
                     double contactDistance, bool reachedOnly);

// The contacts of light `light` on the frame whose G-buffer hits are `gbuffer` and exact
// visibility `exact` (one layer): a pixel is a contact when it is exactly shadowed and its exact
// shadow ray meets the occluder within `distance` world units; < 0 asks for the default,
// 1e-3 x the scene's bounding diagonal, and is replaced by it.
ShadowContacts shadowContacts(RenderWorld& world, const CpuImage& gbuffer, const Camera& camera,
                              int light, const std::vector<float>& exact, double& distance);

// The analytic prediction of one point (docs/shadow-bias.md §4) at map resolution `resolution`.
struct TexelPrediction {
  // Median over receivers of the effective texel w, the one for which (w/2) tan(theta) is the
  // pixel's acne threshold (orthographic: the world texel's extent along the receiver's slope).
  double texelWorld = 0;
  double incidenceDeg = 0;  // median incidence over receivers
  // Predicted acne rate at constant bias `bias` (< 0 when not asked): mean over exactly lit
  // receivers of P(self-comparison error > b), the sub-texel position uniform over the texel
  // (the error's slopes along the map's u and v from its projection at the pixel).
  double acneRate = -1;
};
TexelPrediction predictTexel(const StateReference& state, int resolution, int light, double bias);

// P(X + Y > s) for X, Y independent and uniform on [-a, a] and [-c, c] (a, c >= 0).
double uniformSumAbove(double a, double c, double s);

}  // namespace diptych::cli
