// texture_filtering slot, raster producers (passes/raster/texture_filter.cpp): per visibility
// texel, the colour the material's model reads (C, or the glTF base colour) x colour texture
// (linear) and coverage, the texture read through
// the filter uMode selects. Background pixels get -1 (shade then uses its own lookup).
#include "common/shading.glsl"
#include "gl/scene_buffers.glsl"
#include "gl/scene_shading.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform usampler2D uHits;  // gbuffer.hits (RGBA32UI)
layout(binding = 0, rgba32f) writeonly uniform image2D uAlbedo;
// TextureFilterKind, defined by the pass: 0 nearest, 1 bilinear, 2 distance, 3 trilinear,
// 4 anisotropic, 5 the texture's own sampler.
const int uMode = TEXTURE_FILTER_MODE;
uniform int uMaxAnisotropy;
uniform vec3 uEye, uForward, uRight, uUp;  // primaryRay's pinhole: d = F + ndc.x R + ndc.y U

// Barycentric weights (of p1, p2) of a point given relative to p0, in the triangle's plane.
vec2 barycentric(vec3 v, vec3 e1, vec3 e2) {
  float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
  float d20 = dot(v, e1), d21 = dot(v, e2);
  float denom = d00 * d11 - d01 * d01;
  if (denom == 0.0) return vec2(0.0);
  return vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / denom;
}

void main() {
  ivec2 size = imageSize(uAlbedo);
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= size.x || p.y >= size.y) return;
  uvec4 texel = texelFetch(uHits, p, 0);
  if (texel.x == 0u) {
    imageStore(uAlbedo, p, vec4(-1.0));
    return;
  }
  // The surface point as surfaceFromHits rebuilds it, without the normals this pass does not use.
  int instance = int(texel.x) - 1;
  int material = sceneInstanceMaterial(instance);
  uvec3 tri = sceneTriangle(sceneInstanceFirstTriangle(instance) + texel.y);
  float bu = uintBitsToFloat(texel.z), bv = uintBitsToFloat(texel.w), bw = 1.0 - bu - bv;
  vec3 p0 = scenePosition(tri.x), p1 = scenePosition(tri.y), p2 = scenePosition(tri.z);
  vec3 position = bw * p0 + bu * p1 + bv * p2;
  vec2 t0 = sceneUv(tri.x);
  vec2 t1 = sceneUv(tri.y);
  vec2 t2 = sceneUv(tri.z);
  vec2 uv = bw * t0 + bu * t1 + bv * t2;
  GpuMaterial g = sceneMaterialRecord(material);
  // The colour the material's model reads (common/shading.glsl textureSignalColor): C for the
  // lecture's, the base colour for glTF's and for materials re-mapped per texel (gate 8,
  // remapsPerTexel: shade maps their coefficients from it); the texel multiplies either.
  bool base = sceneMaterialModel(material) == SHADING_MODEL_GLTF ||
              (int(g.modelTransSpec.w) & 8) != 0;
  vec4 result = vec4(base ? g.baseMetallic.xyz : g.colorKa.xyz, g.transmitAlpha.w);
  int tex = int(g.texColorEmitMrAo.x);
  if (g.emissionChecker.w > 0.5) {  // procedural: point-sampled
    ShadingMaterial checkered = sceneMaterial(material, uv);
    result.xyz = base ? checkered.baseColor : checkered.color;
  } else if (sceneTextureValid(tex)) {
    // The footprint: neighbour pixel rays meet the triangle's plane (ray differentials).
    vec3 e1 = p1 - p0, e2 = p2 - p0;
    vec2 f1 = t1 - t0, f2 = t2 - t0;
    vec3 n = cross(e1, e2);
    vec2 ndc = 2.0 * (vec2(p) + 0.5) / vec2(size) - 1.0;
    vec3 d = uForward + ndc.x * uRight + ndc.y * uUp;
    vec3 stepX = 2.0 * uRight / float(size.x), stepY = 2.0 * uUp / float(size.y);
    float planeDistance = dot(p0 - uEye, n);
    vec3 dirX = d + stepX, dirY = d + stepY;
    // A neighbour ray parallel to the plane has no footprint point: treat it as very far.
    float tx = abs(dot(dirX, n)) > 0.0 ? planeDistance / dot(dirX, n) : 1.0e20;
    float ty = abs(dot(dirY, n)) > 0.0 ? planeDistance / dot(dirY, n) : 1.0e20;
    vec2 bx = barycentric(uEye + tx * dirX - position, e1, e2);
    vec2 by = barycentric(uEye + ty * dirY - position, e1, e2);
    vec2 dx = bx.x * f1 + bx.y * f2, dy = by.x * f1 + by.y * f2;
    vec4 c;
    if (uMode == 0) {
      c = sceneSampleFiltered(tex, uv, 0.0, false, SCENE_MIPS_NONE);
    } else if (uMode == 1) {
      c = sceneSampleFiltered(tex, uv, 0.0, true, SCENE_MIPS_NONE);
    } else if (uMode == 2) {
      // The lecture: the level grows with log2 of the eye distance. Its constant is the
      // footprint of a pixel facing the camera (the ray-cone LOD without the cosine):
      // lambda = log2(distance * 2 tan(fov/2) / H) + 0.5 log2(uv area / world area) + 0.5 log2(w h).
      float worldArea = length(n), uvArea = abs(f1.x * f2.y - f1.y * f2.x);
      vec2 texSize = vec2(sceneTextureInfo(tex).xy);
      float lambda = log2(length(position - uEye) * 2.0 * length(uUp) / float(size.y)) +
                     0.5 * log2(uvArea / worldArea) + 0.5 * log2(texSize.x * texSize.y);
      c = sceneSampleFiltered(tex, uv, worldArea > 0.0 && uvArea > 0.0 ? lambda : 0.0, true,
                              SCENE_MIPS_LINEAR);
    } else if (uMode == 3) {
      c = sceneSampleFiltered(tex, uv, sceneLodFromGradients(tex, dx, dy), true, SCENE_MIPS_LINEAR);
    } else if (uMode == 4) {
      c = sceneSampleAnisotropic(tex, uv, dx, dy, uMaxAnisotropy);
    } else {
      c = sceneSampleTextureLod(tex, uv, sceneLodFromGradients(tex, dx, dy));
    }
    result *= c;
  }
  imageStore(uAlbedo, p, result);
}
