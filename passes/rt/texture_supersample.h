#pragma once
// The exact producer of the texture_filtering slot (docs/textures.md): the mean base colour C
// and coverage over each pixel's footprint, from N x N stratified sub-pixel primary rays traced
// with Embree (a row's rays as coherent streams), each reading level 0 of the colour texture
// (its magnification filter) at the point it hits (resolvedColorAt: colour and alpha only).
// Sub-rays that miss the scene are left out of the mean; a pixel whose centre misses (no G-buffer
// hit) gets -1, and shade then uses its own lookup. N = 1 traces the pixel centre only: the
// Whitted reference's own lookup at its default texture_samples 1 (the built-in hybrid recipe
// uses it so that the all-exact hybrid stays equal to that reference). Counter "rays": the
// sub-pixel rays traced, N^2 per pixel whose centre is covered (uncovered pixels trace none).
#include <cstdint>
#include <span>

#include "engine/graph/pass.h"
#include "engine/rt/rt_scene.h"
#include "engine/rt/whitted.h"
#include "engine/scene/camera_math.h"
#include "passes/slots.h"

namespace diptych {

// Where a pixel's footprint is traced, per kind of secondary ray (index 0 reflected, 1
// transmitted): bit kReflected / kTransmitted of `kinds`, and the hits of that kind the ray
// passes through first (hops: a solid glass's far side is one; texturedSecondaries finds them).
struct FootprintTarget {
  static constexpr std::uint8_t kReflected = 1, kTransmitted = 2;
  std::uint8_t kinds = 0;
  std::uint8_t hops[2] = {0, 0};
};

// The footprint of the textures a camera hit sees along its secondary rays, beside the camera
// hits' own (the texture_samples of rt_whitted, rt_reflection and rt_transmission;
// docs/textures.md): each sub-pixel ray's point casts the mirror or refracted ray its own shading
// would (WhittedTracer::secondaryRay), followed through the target's hops of the same kind, and
// the mean colour and coverage at what it then hits (level 0, as the camera hits') is the signal
// that replaces the lookup at the pixel's own hit there (WhittedTracer::passSignal). Sub-rays whose
// chain breaks (a point that casts no such ray, a miss) are left out; a pixel with none left gets
// -1 for that kind. Only the kinds a pixel's target asks for are traced.
struct SecondaryFootprint {
  const WhittedTracer& tracer;
  std::span<const FootprintTarget> targets;  // targets[i] for out[i]
  std::span<SecondarySignals> out;           // out[i] as supersampleTextureRow's out[i]
  // false: the camera hits' own colours are not looked up (supersampleTextureRow's out gets -1),
  // for the producers that want the secondary hits' alone.
  bool cameraColours = true;
};

// The kinds (of `wanted`) of the secondary rays that camera point p, seen along `direction`,
// casts and that reach a colour-textured material (readsColorTexture), through hits of the same
// kind (a solid glass's far side, a mirror seen in a mirror) up to the tracer's depth: where the
// footprint changes the pixel, and how many hops away. The rays are traced here, one at a time,
// and added to `rays`.
FootprintTarget texturedSecondaries(const WhittedTracer& tracer, const Scene& scene,
                                    const WorldGeometry& geometry, const RtScene& rt,
                                    const SurfacePoint& p, const vec3& direction,
                                    std::uint8_t wanted, std::int64_t& rays);
// Both kinds at the camera ray's hit h (rt_whitted's camera hits): texturedSecondaries where its
// material casts either ray, its surface point built here.
FootprintTarget texturedSecondariesAt(const WhittedTracer& tracer, const Scene& scene,
                                      const WorldGeometry& geometry, const RtScene& rt,
                                      const Ray& ray, const Hit& h, std::int64_t& rays);
// Pixel (x, y)'s SecondaryFootprint for its target (no kinds: none, nothing traced): what
// supersampleTextureRow gives that pixel, for the ray-by-ray paths (SDF objects), whose pixels
// trace their rays inside their own step count. Adds the rays it traced to `rays`.
SecondarySignals secondaryFootprintPixel(const WhittedTracer& tracer, const Scene& scene,
                                         const WorldGeometry& geometry, const RtScene& rt,
                                         const PinholeFrame& pinhole, int n, int x, int y,
                                         const FootprintTarget& target, std::int64_t& rays);

// Row y of the signal into out[i], pixel x0 + i (the whole row: out.size() is the frame's width
// and x0 0), from N x N sub-pixel rays per pixel, traced as coherent Embree streams; returns the
// number of rays traced (with `secondary`, its rays too). covered[i] false: that pixel gets -1
// and traces nothing (the G-buffer's uncovered pixels, or the Whitted reference's pixels whose
// centre ray misses: texture_samples); covered empty: every pixel is traced. A pixel none of
// whose rays hit gets -1.
std::int64_t supersampleTextureRow(const Scene& scene, const WorldGeometry& geometry,
                                   const RtScene& rt, const PinholeFrame& pinhole,
                                   std::span<const std::uint8_t> covered, int n, int y,
                                   std::span<vec4> out,
                                   const SecondaryFootprint* secondary = nullptr, int x0 = 0);

class TextureSupersamplePass : public Pass {
 public:
  static constexpr int kDefaultSamples = 4;  // N, where a recipe does not set it
  static ParamSchema schema();
  Domain domain() const override { return Domain::Cpu; }
  void setup(PassBuilder& builder) override;
  void execute(PassContext& context) override;

  // One pixel's signal traced ray by ray (RtScene::intersect, makeSurfacePoint): the producer
  // before its streams, kept as the reference its test compares with. n: N; (x, y): the pixel.
  static vec4 singleRayPixel(const Scene& scene, const WorldGeometry& geometry, const RtScene& rt,
                             const PinholeFrame& pinhole, int n, int x, int y);

 private:
  int samples_ = 4;  // N
  SlotIo io_;
};

}  // namespace diptych
