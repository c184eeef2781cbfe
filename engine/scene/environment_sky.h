#pragma once
// A procedural sky with structure, so that the environment-map producers (cube, sphere,
// equirect) have something to get wrong: a zenith-to-horizon gradient, a sharp horizon over a
// darker ground, a sun disc and a glow around it. It is a documented gradient model of our own
// (not a physical sky such as Preetham 1999): radiance in the shading's linear units,
//
//   above the horizon (cos theta = d.y >= 0):
//     L_sky = mix(horizon, zenith, (d.y)^(1/gradient_exponent))
//   below: L_ground = ground                (the horizon is a step, one texel wide once baked)
//   glow:  + sun_color * glow * exp(-angle / glow_width)          (angle to the sun, radians)
//   disc:  + sun_color * sun_radiance   where angle <= sun_radius
//
// The sky is baked into an equirect image (environment.cpp's (u, v) convention), so every path
// that reads Scene::environment (ray misses, GL maps, the forward background) sees the same
// texels. JSON: "environment": {"sky": {...}} (docs/scene-format.md).
#include "engine/scene/scene.h"

namespace diptych {

struct SkyParams {
  vec3 zenith{0.10f, 0.25f, 0.65f};
  vec3 horizon{0.70f, 0.78f, 0.90f};
  vec3 ground{0.16f, 0.14f, 0.12f};
  float gradientExponent = 2.f;      // > 0; larger keeps the pale band near the horizon thinner
  vec3 sunDirection{0.f, 1.f, 0.f};  // toward the sun; need not be unit length, not zero
  vec3 sunColor{1.f, 0.95f, 0.85f};
  float sunRadius = 0.035f;  // angular radius, radians (about 2 degrees: several texels wide)
  float sunRadiance = 30.f;  // disc radiance, times sunColor
  float glow = 1.5f;         // glow radiance at the sun, times sunColor
  float glowWidth = 0.15f;   // radians
  int width = 1024;          // baked equirect width; height = width / 2
};

// Radiance of the analytic sky along unit direction d (before baking).
vec3 skyRadiance(const SkyParams& sky, const vec3& d);

// The sky baked into an equirect environment of sky.width x sky.width/2 texels; each texel is
// the mean of 2 x 2 stratified samples of skyRadiance over its solid-angle patch, so the sun
// disc's edge is anti-aliased rather than point-sampled.
Environment bakeSky(const SkyParams& sky);

}  // namespace diptych
