#pragma once
// Camera matrices and primary rays. Raster and ray tracing both derive from these, so that a
// pixel centre is the same ray on both sides. Image pixel (x, y) has y = 0 at the top row.
#include <span>

#include "engine/scene/scene.h"

namespace diptych {

mat4 viewMatrix(const Camera& camera);
// Infinite reversed-Z perspective (depth 1 at the near plane, -> 0 at infinity) for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE) with a D32F buffer cleared to 0 and GL_GREATER.
mat4 reversedZProjection(const Camera& camera, float aspect);

// The instant of the shutter interval [0, 1] that a frame shows: raster passes draw every moving
// instance there (Instance::motion is centred on it), and every ray that carries no time of its
// own is traced there. Distributed ray tracing spreads its samples over the whole interval
// (motion blur: Cook, Porter and Carpenter 1984; docs/reference-renderers.md).
inline constexpr float kFrameTime = 0.5f;

struct Ray {
  vec3 origin;
  vec3 direction;           // unit length
  float time = kFrameTime;  // in the shutter interval [0, 1] (Embree's RTCRay::time)
};

// Ray through the point (x + sx, y + sy) of the image, sx, sy in [0,1); (0.5, 0.5) is the centre.
Ray primaryRay(const Camera& camera, int width, int height, float x, float y);

// primaryRay's camera frame (view axes, tan of the half angle, aspect), built once for a whole
// image: primaryRay rebuilds it on every call (a tan, two normalisations, two cross products),
// which per-pixel loops need not repeat. ray(x, y) == primaryRay(camera, width, height, x, y)
// bit for bit: primaryRay is implemented with it.
class PinholeFrame {
 public:
  PinholeFrame(const Camera& camera, int width, int height);
  Ray ray(float x, float y) const;
  // The directions of ray(x + 0.5f, y + 0.5f) for x = 0 .. out.size() - 1 (a row's pixel
  // centres), bit for bit: the same operations in the same order, computed several pixels per
  // instruction (a loop the compiler vectorises; per-pixel loops over whole rows spent ~5% of a
  // hybrid frame in ray(), perf). out.size() is at most the image width.
  void rowDirections(int y, std::span<vec3> out) const;
  const vec3& position() const { return position_; }  // every ray's origin
  const vec3& forward() const { return forward_; }
  const vec3& right() const { return right_; }
  const vec3& up() const { return up_; }

 private:
  vec3 position_, forward_, right_, up_;
  float aspect_, tanHalf_, width_, height_;
};

// Shirley & Chiu's concentric map from the unit square to the unit disc ("A Low Distortion Map
// Between Disk and Square", JGT 2(3), 1997): strata of the square stay compact on the disc, so
// stratified lens and disc-light samples stay stratified.
vec2 concentricDisk(vec2 s);

// Thin-lens primary ray (Cook, Porter and Carpenter, "Distributed Ray Tracing", SIGGRAPH 1984,
// depth of field): the point of the pinhole ray primaryRay(x, y) at distance
// camera.focusDistance along the view axis is in focus; the ray leaves from the point
// camera.aperture * concentricDisk(lens) of the lens disc (spanned by the camera's right and up
// axes) toward it. lens in [0,1)^2. aperture == 0 returns primaryRay(x, y) exactly (pinhole).
Ray thinLensRay(const Camera& camera, int width, int height, float x, float y, vec2 lens);

// thinLensRay with the camera's frame built once (per image, as PinholeFrame for primaryRay):
// the per-pixel loops built it for every sample (normalisations, a cross product and a tangent:
// ~8% of rt_path's samples, perf). The ray is thinLensRay's bit for bit (it is defined by this).
class ThinLensFrame {
 public:
  ThinLensFrame(const Camera& camera, int width, int height);
  Ray ray(float x, float y, vec2 lens) const;
  const PinholeFrame& pinhole() const { return pinhole_; }

 private:
  PinholeFrame pinhole_;
  vec3 position_;
  float aperture_, focusDistance_;
};

// A camera that frames the bounds (used when a scene has none).
Camera frameBounds(const Aabb& bounds);

// near/far fitted to the scene's bounds as seen from camera.position: far just past the farthest
// box corner, near half the distance to the box (1e-4 far when the camera is inside it), so
// that the clip range scales with the scene (docs/numerics.md). An empty box leaves c unchanged.
void fitNearFar(Camera& c, const Aabb& bounds);

}  // namespace diptych
