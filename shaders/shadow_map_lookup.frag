// Shadow-map lookup (passes/raster/shadow_map*.cpp, docs/shadow-maps.md): for one light, the
// visibility V in [0,1] of the exact G-buffer surface point, from that light's reversed-Z D32F
// map(s) under one bias mode and one filter. A tap is lit when the receiver's depth is at least
// the stored depth (reversed-Z: nearer = greater).
#include "common/bindings.glsl"
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"
#include "gl/gbuffer_surface.glsl"

const int KIND_UNSHADOWED = 0;
const int KIND_ORTHO = 1;
const int KIND_PERSPECTIVE = 2;
const int KIND_CUBE = 3;
const int BIAS_NONE = 0;
const int BIAS_CONSTANT = 1;
const int BIAS_SLOPE = 2;
const int BIAS_NORMAL_OFFSET = 3;
const int BIAS_RECEIVER_PLANE = 4;
const int BIAS_ADAPTIVE = 5;
const int FILTER_NONE = 0;
const int FILTER_PCF = 1;
const int FILTER_POISSON = 2;
const int FILTER_PCSS = 3;

// Layer l: its view-projection and inverse, column by column, texels 8 l .. 8 l + 7 of an RGBA32F
// buffer texture (shadow_map_lookup.cpp GpuLayer).
layout(binding = UNIT_SHADOW_LAYERS) uniform samplerBuffer uShadowLayers;
mat4 shadowLayerMatrix(int layer, int inverse) {
  int t = 8 * layer + 4 * inverse;
  return mat4(texelFetch(uShadowLayers, t), texelFetch(uShadowLayers, t + 1),
              texelFetch(uShadowLayers, t + 2), texelFetch(uShadowLayers, t + 3));
}
struct ShadowLight {
  ivec4 info;            // kind, first layer, layer count, -
  vec4 positionNear;     // light position, near plane (axis depth)
  vec4 directionFar;     // travel direction, far plane (axis depth)
  vec4 texelScaleSize;   // texel footprint (ortho: world; else per unit axis depth), PCSS size
};
// Light i: texels 4 i .. 4 i + 3 of an RGBA32I buffer texture (shadow_map_lookup.cpp
// GpuShadowLight), the float fields as their bits.
layout(binding = UNIT_SHADOW_LIGHTS) uniform isamplerBuffer uShadowLights;
ShadowLight shadowLightRecord(int i) {
  ShadowLight l;
  l.info = texelFetch(uShadowLights, 4 * i);
  l.positionNear = intBitsToFloat(texelFetch(uShadowLights, 4 * i + 1));
  l.directionFar = intBitsToFloat(texelFetch(uShadowLights, 4 * i + 2));
  l.texelScaleSize = intBitsToFloat(texelFetch(uShadowLights, 4 * i + 3));
  return l;
}

layout(binding = 0) uniform usampler2D uHits;
layout(binding = 1) uniform sampler2DArray uShadowMaps;

uniform int uLight;  // -1: a layer with no light, written as lit
uniform int uResolution;
// Light kind, bias mode, filter and PCF kernel are compile-time constants: one program per
// combination (passes/raster/shadow_map_lookup.cpp), as a GPU engine builds shader
// permutations. llvmpipe runs both sides of every branch under a lane mask, so with them as
// uniforms every tap paid for every bias mode and the cube-edge path (docs/benchmarks.md).
const int uBias = DIPTYCH_BIAS;
const int uFilter = DIPTYCH_FILTER;
const int uKernel = DIPTYCH_KERNEL;
const int gKind = DIPTYCH_KIND;
uniform int uTaps;
uniform float uConstantBias;     // world units along the light ray
uniform float uNormalScale;      // texel footprints
uniform float uAdaptiveEpsilon;  // world units (adaptive_epsilon x scene diagonal)
uniform float uPlaneEpsilon;     // relative depth (receiver_plane)
uniform float uRadius;           // texels
uniform float uMaxRadius;        // texels
uniform vec2 uPoisson[64];

layout(location = 0) out float outVisibility;

// The current light and receiver, set once in main() (initialised so no path reads garbage).
int gFirst = 0;
vec3 gLightPos = vec3(0.0), gLightDir = vec3(0.0);
float gNear = 1.0, gFar = 2.0, gTexelScale = 0.0, gLightSize = 0.0;
vec3 gP = vec3(0.0), gPb = vec3(0.0);  // exact surface point, biased lookup point
vec3 gN = vec3(0.0, 1.0, 0.0);         // geometric normal on the light's side
int gFace0 = 0;                        // layer (cube face) of the lookup point
vec4 gSc0 = vec4(0.0);                 // (uv, depth, clip w) of the lookup point on gFace0
vec4 gScP = vec4(0.0);                 // same for the unbiased point (receiver_plane)
vec2 gGrad = vec2(0.0);                // receiver plane: d depth / d uv (Isidoro 2006)
bool gGradOk = false;

// (uv in [0,1]^2, reversed depth, clip w) of a world point on one layer; a point behind a
// perspective light gets uv (-1, -1), outside every map.
vec4 project(int face, vec3 p) {
  vec4 c = shadowLayerMatrix(gFirst + face, 0) * vec4(p, 1.0);
  if (!(c.w > 0.0)) return vec4(-1.0, -1.0, 0.0, 0.0);
  vec3 ndc = c.xyz / c.w;
  return vec4(0.5 * ndc.xy + 0.5, ndc.z, c.w);
}

vec3 unproject(int face, vec2 uv, float depth) {
  vec4 h = shadowLayerMatrix(gFirst + face, 1) * vec4(2.0 * uv - 1.0, depth, 1.0);
  return h.xyz / h.w;
}

// Cube face (+x, -x, +y, -y, +z, -z) whose 90-degree frustum holds direction d: the major axis.
int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

int faceOf(vec3 p) { return gKind == KIND_CUBE ? cubeFace(p - gLightPos) : 0; }

// Axis depth (world units) of a reversed-Z depth value: ortho d = (f - z) / (f - n);
// perspective d = n (f - z) / ((f - n) z).
float linearDepth(float d) {
  if (gKind == KIND_ORTHO) return gFar - d * (gFar - gNear);
  return gNear * gFar / max(d * (gFar - gNear) + gNear, 1e-30);
}

// World size of one texel at axis depth z.
float texelWorld(float z) { return gKind == KIND_ORTHO ? gTexelScale : z * gTexelScale; }

// The receiver's reversed depth to compare with texel `texel` of `face`.
float receiverDepth(int face, ivec2 texel) {
  vec2 centre = (vec2(texel) + 0.5) / float(uResolution);
  if (uBias == BIAS_RECEIVER_PLANE) {
    // Isidoro 2006: the receiver's plane, extrapolated in depth to the texel centre where the
    // rasterizer sampled the occluder, plus a relative epsilon for rounding. Off the receiver's
    // own cube face the gradient means nothing: fall back to the point's own depth there.
    float d = face == gFace0 && gGradOk ? gScP.z + dot(gGrad, centre - gScP.xy)
                                        : project(face, gP).z;
    return d * (1.0 + uPlaneEpsilon);
  }
  if (uBias == BIAS_ADAPTIVE) {
    // Dou et al. 2014: intersect the light ray through the texel centre with the receiver's
    // tangent plane; compare that point, moved epsilon toward the light, with the texel.
    vec3 a = unproject(face, centre, 1.0), b = unproject(face, centre, 0.0);  // near, far
    vec3 ray = b - a;
    float denom = dot(gN, ray);
    vec3 x = gP;
    if (abs(denom) > 1e-6 * length(ray)) {
      float t = dot(gN, gP - a) / denom;
      if (t > 0.0 && t < 1.0) x = a + t * ray;
    }
    return project(face, x - uAdaptiveEpsilon * normalize(ray)).z;
  }
  return project(face, gPb).z;
}

// Bias modes whose receiver depth is the biased point's own depth on its own face, the same for
// every tap there: receiverDepth() = project(gFace0, gPb).z, which main() stores as gSc0.z.
const bool kFlatReceiver = uBias == BIAS_NONE || uBias == BIAS_CONSTANT || uBias == BIAS_SLOPE ||
                           uBias == BIAS_NORMAL_OFFSET;

// 3x3 PCF by four textureGather (GL 4.0) instead of nine texelFetch (DIPTYCH_PCF_GATHER, the
// interior pass, whose taps all read gFace0): the gathers cover the 4x4
// texels from the (-1, -1) tap's, which hold the nine taps' texels, and the same nine compares
// with the one receiver depth are summed, so the result is the loop's. tap() floors
// x + offset: x - 1 is exact (x >= 1 inside the map), so the 0 tap's texel is the -1 tap's + 1;
// x + 1 can round up across a power of two, so the +1 tap's is + 2 or + 3.
float pcf3Gathered() {
  float resolution = float(uResolution);
  vec2 x = gSc0.xy * resolution;
  vec2 lo = floor(x - 1.0), hi = floor(x + 1.0);
  float layer = float(gFirst + gFace0);
  // Gathering at the corner between texels (c, r) and (c + 1, r + 1) returns
  // ((c, r+1), (c+1, r+1), (c+1, r), (c, r)).
  vec4 a = textureGather(uShadowMaps, vec3((lo + 1.0) / resolution, layer));
  vec4 b = textureGather(uShadowMaps, vec3((lo + vec2(3.0, 1.0)) / resolution, layer));
  vec4 c = textureGather(uShadowMaps, vec3((lo + vec2(1.0, 3.0)) / resolution, layer));
  vec4 d = textureGather(uShadowMaps, vec3((lo + 3.0) / resolution, layer));
  vec4 receiver = vec4(gSc0.z);
  vec4 row0 = vec4(greaterThanEqual(receiver, vec4(a.w, a.z, b.w, b.z)));
  vec4 row1 = vec4(greaterThanEqual(receiver, vec4(a.x, a.y, b.x, b.y)));
  vec4 row2 = vec4(greaterThanEqual(receiver, vec4(c.w, c.z, d.w, d.z)));
  vec4 row3 = vec4(greaterThanEqual(receiver, vec4(c.x, c.y, d.x, d.y)));
  vec4 rows = row0 + row1 + (hi.y - lo.y == 2.0 ? row2 : row3);
  float cp = hi.x - lo.x;
  return dot(rows, vec4(1.0, 1.0, cp == 2.0 ? 1.0 : 0.0, cp == 2.0 ? 0.0 : 1.0)) / 9.0;
}

// One tap at `offset` texels from the lookup point: (lit 0/1, stored depth, 1 if it read a map).
vec3 tap(vec2 offset) {
  ivec2 texel = ivec2(floor(gSc0.xy * float(uResolution) + offset));
  int face = gFace0;
#ifndef DIPTYCH_INTERIOR
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(uResolution)))) {
    if (gKind != KIND_CUBE) return vec3(1.0, 0.0, 0.0);  // outside the light's frustum: lit
    // Off the edge of a cube face: carry the texel's direction onto the face that holds it.
    vec3 w = unproject(gFace0, (vec2(texel) + 0.5) / float(uResolution), gSc0.z);
    face = cubeFace(w - gLightPos);
    vec4 q = project(face, w);
    texel = clamp(ivec2(floor(q.xy * float(uResolution))), ivec2(0), ivec2(uResolution - 1));
  }
#endif
  float stored = texelFetch(uShadowMaps, ivec3(texel, gFirst + face), 0).r;
  return vec3(receiverDepth(face, texel) >= stored ? 1.0 : 0.0, stored, 1.0);
}

// Percentage-closer soft shadows (Fernando 2005): blocker search, penumbra from similar
// triangles, then PCF over the penumbra. Sizes in world units are turned into texels with the
// footprint at the receiver's depth; both radii are capped at uMaxRadius texels.
float pcss() {
  float zR = linearDepth(gSc0.z);
  float foot = texelWorld(zR);
  float reach = max(zR - gNear, 0.0);
  // Occluders of part of the light lie in the cone from the receiver to the light's extent;
  // its widest cross-section on the map is at the near plane (ortho: the angular width times
  // the distance).
  float search = gKind == KIND_ORTHO ? 0.5 * gLightSize * reach / foot
                                     : 0.5 * gLightSize * reach / (zR * gNear * gTexelScale);
  search = clamp(search, 1.0, uMaxRadius);
  float blockers = 0.0, sum = 0.0;
  for (int i = 0; i < uTaps; ++i) {
    vec3 t = tap(uPoisson[i] * search);
    if (t.z > 0.0 && t.x == 0.0) {
      blockers += 1.0;
      sum += linearDepth(t.y);
    }
  }
  if (blockers == 0.0) return 1.0;
  float zB = sum / blockers;
  float penumbra = gKind == KIND_ORTHO ? gLightSize * (zR - zB)
                                       : gLightSize * (zR - zB) / max(zB, 1e-30);
  float radius = clamp(0.5 * penumbra / foot, 0.0, uMaxRadius);
  float lit = 0.0;
  for (int i = 0; i < uTaps; ++i) lit += tap(uPoisson[i] * radius).x;
  return lit / float(uTaps);
}

float visibility() {
#if defined(DIPTYCH_INTERIOR) && defined(DIPTYCH_PCF_GATHER)
  if (uFilter == FILTER_PCF && uKernel == 3 && kFlatReceiver) return pcf3Gathered();
#endif
  if (uFilter == FILTER_PCF) {
    int k = uKernel / 2;
    float lit = 0.0;
    for (int j = -k; j <= k; ++j)
      for (int i = -k; i <= k; ++i) lit += tap(vec2(i, j)).x;
    return lit / float(uKernel * uKernel);
  }
  if (uFilter == FILTER_POISSON) {
    float lit = 0.0;
    for (int i = 0; i < uTaps; ++i) lit += tap(uPoisson[i] * uRadius).x;
    return lit / float(uTaps);
  }
  if (uFilter == FILTER_PCSS) return pcss();
  return tap(vec2(0.0)).x;
}

// Cube maps are looked up in two passes (shadow_map_lookup.cpp): DIPTYCH_INTERIOR, without the
// cube-edge path, for pixels whose every tap stays on their own face, marking the rest with
// depth 1; then the full shader, depth-tested, only for those (background pixels are neither).
// llvmpipe runs a branch's code for every lane, so the edge path (two re-projections) cost every
// tap of every pixel. Largest tap offset in texels per filter: the interior test is conservative
// for each of them.
float maxTapOffset() {
  if (uFilter == FILTER_PCF) return float(uKernel / 2);
  if (uFilter == FILTER_POISSON) return uRadius;
  if (uFilter == FILTER_PCSS) return max(uMaxRadius, 1.0);  // both search and filter radii
  return 0.0;
}

void main() {
#ifdef DIPTYCH_INTERIOR
  // Done here; the depth is cleared to 0 too, so discarded (background) pixels keep it and the
  // cleared lit colour, and the second pass skips them. Pixels left to it are marked with 1.
  gl_FragDepth = 0.0;
#endif
  if (uLight < 0) {
    outVisibility = 1.0;
    return;
  }
  uvec4 hits = texelFetch(uHits, ivec2(gl_FragCoord.xy), 0);
  // Background pixels keep the cleared 1 (lit). Discarded, not returned from: llvmpipe skips the
  // rest of the shader for blocks whose pixels are all discarded, not for a divergent branch.
  // Receiver-plane bias keeps them in its quads: its screen derivatives read their lanes.
  if (uBias != BIAS_RECEIVER_PLANE && hits.x == 0u) discard;
  SceneSurface s = gbufferSurface(ivec2(gl_FragCoord.xy), hits);
  ShadowLight light = shadowLightRecord(uLight);
  gFirst = light.info.y;
  gLightPos = light.positionNear.xyz;
  gNear = light.positionNear.w;
  gLightDir = light.directionFar.xyz;
  gFar = light.directionFar.w;
  gTexelScale = light.texelScaleSize.x;
  gLightSize = light.texelScaleSize.y;
  if (gKind == KIND_UNSHADOWED) {  // uniform: the same light for every pixel
    outVisibility = 1.0;
    return;
  }

  gP = s.position;
  vec3 toLight = gKind == KIND_ORTHO ? -gLightDir : safeNormalize(gLightPos - gP);
  // The face normal on the light's side, as the shadow rays offset their origins.
  gN = dot(s.faceNormal, toLight) < 0.0 ? -s.faceNormal : s.faceNormal;

  // Receiver plane (Isidoro 2006): screen-space derivatives of (u, v, depth) give
  // d depth / d(u, v) through the inverse Jacobian of (u, v) w.r.t. the screen. Taken here, in
  // uniform control flow, for every pixel; quads that straddle two surfaces (or two cube
  // faces, or the background) get a wrong plane: an artifact of the technique.
  gScP = project(faceOf(gP), gP);
  vec3 dx = dFdx(gScP.xyz), dy = dFdy(gScP.xyz);
  float det = dx.x * dy.y - dx.y * dy.x;
  gGrad = vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det;
  gGradOk = abs(det) > 0.0 && maxAbsComponent(vec3(gGrad, 0.0)) < SHADING_FLT_MAX;

  if (!s.hit) {
    outVisibility = 1.0;
    return;
  }

  gPb = gP;
  if (uBias == BIAS_CONSTANT) gPb = gP + uConstantBias * toLight;
  if (uBias == BIAS_NORMAL_OFFSET) {
    // Holbert 2011: offset along the normal by the texel footprint at the point, times
    // sin(angle to the light) (no offset facing the light, a full texel at grazing angles).
    float cosTheta = clamp(dot(gN, toLight), 0.0, 1.0);
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    float axisDepth = gKind == KIND_ORTHO ? 1.0 : project(faceOf(gP), gP).w;
    gPb = gP + gN * (uNormalScale * texelWorld(axisDepth) * sinTheta);
  }
  gFace0 = faceOf(gPb);
  gSc0 = project(gFace0, gPb);
#ifdef DIPTYCH_INTERIOR
  // tap() floors gSc0 * resolution + offset, monotonic in the offset: the extreme offsets bound
  // every tap's texel.
  float reach = maxTapOffset();
  ivec2 lo = ivec2(floor(gSc0.xy * float(uResolution) - reach));
  ivec2 hi = ivec2(floor(gSc0.xy * float(uResolution) + reach));
  if (any(lessThan(lo, ivec2(0))) || any(greaterThanEqual(hi, ivec2(uResolution)))) {
    gl_FragDepth = 1.0;  // a tap leaves the face: the full shader writes this pixel
    outVisibility = 0.0;
    return;
  }
#endif
  outVisibility = saturate01(visibility());
}
