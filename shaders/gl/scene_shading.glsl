// Materials, lights and instances uploaded by engine/gl/shading_buffers.cpp, and the surface
// point of a visibility-buffer texel reconstructed exactly as the CPU does it
// (engine/rt/surface_point.cpp). Include after common/shading.glsl and gl/scene_buffers.glsl.
#include "common/bindings.glsl"
#include "gl/scene_textures.glsl"
#include "common/bump.glsl"
#include "common/gltf_lecture.glsl"
struct GpuMaterial {
  vec4 colorKa;         // C, k_a
  vec4 kdKsExpKps;      // k_d, k_s, e, k_ps
  vec4 specularIor;     // d_i, ior
  vec4 mirrorKt;        // M_PS, k_t
  vec4 transmitAlpha;   // M_T, alpha
  vec4 emissionChecker; // M_E, 1 when the checker replaces C
  vec4 checkerAScale;   // checker colour A, scale
  vec4 checkerBCutoff;  // checker colour B, alpha cutoff
  vec4 alphaMask;       // layer of uSceneAlphaMasks (-1: none), width, height, flags
  vec4 baseMetallic;    // glTF model: base colour, metallic
  vec4 tintRoughness;   // KHR_materials_specular colour, roughness
  vec4 modelTransSpec;  // SHADING_MODEL_*, transmission, specular weight, gates (sceneHitMay*,
                        // 8: remapsPerTexel)
  // --- textures (engine/gl/shading_buffers.cpp packMaterial; -1: none) ---
  vec4 texColorEmitMrAo;      // base colour, emission, metallic-roughness, occlusion textures
  vec4 texNormalScales;       // normal texture, normal scale, occlusion strength, transmission
  vec4 baseFactorMetallic;    // glTF baseColorFactor.rgb, metallicFactor
  vec4 roughnessFactor;       // glTF roughnessFactor, volume transmittance over the thickness (rgb)
  // --- end textures ---
  vec4 bumpKindTexKDelta;     // bump: 0 none, 1 height texture, 2 sinusoid; texture, k, delta
  vec4 bumpWave;              // sinusoid amplitude, frequency u, frequency v, unused
  vec4 iridescence;           // KHR_materials_iridescence factor, film IOR, thickness min, max (nm)
  vec4 iridescenceTextures;   // iridescence texture (R), thickness texture (G), unused, unused
};
// Material m (-1: the default) as engine/gl/shading_buffers.cpp packMaterial writes it: the
// texels (m + 1) GPU_MATERIAL_TEXELS + k of an RGBA32F buffer texture, k in GpuMaterial's
// order. A caller's unused fields cost nothing: their fetches are dead code to the compiler.
layout(binding = UNIT_SCENE_MATERIALS) uniform samplerBuffer uSceneMaterials;
vec4 sceneMaterialTexel(int m, int k) {
  return texelFetch(uSceneMaterials, (m + 1) * GPU_MATERIAL_TEXELS + k);
}
GpuMaterial sceneMaterialRecord(int m) {
  GpuMaterial g;
  g.colorKa = sceneMaterialTexel(m, 0);
  g.kdKsExpKps = sceneMaterialTexel(m, 1);
  g.specularIor = sceneMaterialTexel(m, 2);
  g.mirrorKt = sceneMaterialTexel(m, 3);
  g.transmitAlpha = sceneMaterialTexel(m, 4);
  g.emissionChecker = sceneMaterialTexel(m, 5);
  g.checkerAScale = sceneMaterialTexel(m, 6);
  g.checkerBCutoff = sceneMaterialTexel(m, 7);
  g.alphaMask = sceneMaterialTexel(m, 8);
  g.baseMetallic = sceneMaterialTexel(m, 9);
  g.tintRoughness = sceneMaterialTexel(m, 10);
  g.modelTransSpec = sceneMaterialTexel(m, 11);
  g.texColorEmitMrAo = sceneMaterialTexel(m, 12);
  g.texNormalScales = sceneMaterialTexel(m, 13);
  g.baseFactorMetallic = sceneMaterialTexel(m, 14);
  g.roughnessFactor = sceneMaterialTexel(m, 15);
  g.bumpKindTexKDelta = sceneMaterialTexel(m, 16);
  g.bumpWave = sceneMaterialTexel(m, 17);
  g.iridescence = sceneMaterialTexel(m, 18);
  g.iridescenceTextures = sceneMaterialTexel(m, 19);
  return g;
}
// Per instance (material + 1, first triangle in the shared buffers): RG32I.
layout(binding = UNIT_SCENE_INSTANCES) uniform isamplerBuffer uSceneInstances;
struct GpuLight {
  vec4 typeRangeCos;     // type, range, cos inner, cos outer
  vec4 colorIntensity;   // colour, intensity
  vec4 positionArea;     // position, area
  vec4 directionShadow;  // direction, 1 when it casts shadows
  vec4 edgeURadius;      // quad edge u, radius
};
// Light i, GPU_LIGHT_TEXELS RGBA32F texels in GpuLight's order (engine/gl/shading_buffers.cpp
// packLight).
layout(binding = UNIT_SCENE_LIGHTS) uniform samplerBuffer uSceneLights;
GpuLight sceneLightRecord(int i) {
  GpuLight g;
  g.typeRangeCos = texelFetch(uSceneLights, GPU_LIGHT_TEXELS * i + 0);
  g.colorIntensity = texelFetch(uSceneLights, GPU_LIGHT_TEXELS * i + 1);
  g.positionArea = texelFetch(uSceneLights, GPU_LIGHT_TEXELS * i + 2);
  g.directionShadow = texelFetch(uSceneLights, GPU_LIGHT_TEXELS * i + 3);
  g.edgeURadius = texelFetch(uSceneLights, GPU_LIGHT_TEXELS * i + 4);
  return g;
}
uniform int uLightCount;  // the buffer has a dummy entry when the scene has no lights
// Alpha of the colour textures of alpha-masked materials, one per layer at its own size in the
// layer's corner, image row y at GL row y (engine/gl/shading_buffers.cpp).
layout(binding = UNIT_SCENE_ALPHA_MASKS) uniform sampler2DArray uSceneAlphaMasks;

// --- textures: the material at a texel, as engine/rt/surface_point.cpp resolveMaterial ---
// The glTF metallic-roughness mapping (common/gltf_lecture.glsl, the C++ loaders' and
// resolveMaterial's too) written into s's lecture coefficients.
void sceneApplyGltfPbr(inout ShadingMaterial s, vec3 base, float metallic, float roughness,
                       float transmission) {
  LectureCoefficients k = gltfPbrToLecture(base, metallic, roughness, transmission, s.ior);
  s.color = k.color;
  s.kd = k.kd;
  s.ks = k.ks;
  s.exponent = k.exponent;
  s.specularColor = k.specularColor;
  s.kps = k.kps;
  s.mirrorColor = k.mirrorColor;
  s.kt = k.kt;
  s.transmitColor = k.transmitColor;
}

// A texture of the material at uv: level 0 by its magnification filter when uvLod is below
// -1e38 (sceneMaterial), else lambda = uvLod + 0.5 log2(w h) (ray-cone style footprint).
vec4 sceneMaterialTexture(int tex, vec2 uv, float uvLod) {
  if (!sceneTextureValid(tex)) return vec4(1.0);
  if (!(uvLod > -1.0e38)) return sceneSampleTexture(tex, uv);
  vec2 size = vec2(sceneTextureInfo(tex).xy);
  return sceneSampleTextureLod(tex, uv, uvLod + 0.5 * log2(max(size.x * size.y, 1.0)));
}

// The shading model of material m (SHADING_MODEL_*): a constant where every material has one.
int sceneMaterialModel(int m) {
#if DIPTYCH_SCENE_MODEL >= 0
  return DIPTYCH_SCENE_MODEL;  // shading.glsl's model dispatch folds
#else
  return int(sceneMaterialRecord(m).modelTransSpec.x + 0.5);
#endif
}

// Material m of Scene::materials (-1: the default) at uv: the checker (colour alternates every
// 1/scale in u and v) or the base-colour texture times C and alpha, the emission texture times
// M_E, the lecture coefficients re-mapped per texel where remapsPerTexel (gate 8: a
// metallic-roughness texture, or a partly metal or transmissive glTF material's colour texture
// or checker),
// occlusion scaling k_a, the film's strength and thickness textures.
ShadingMaterial sceneMaterialLod(int m, vec2 uv, float uvLod) {
  GpuMaterial g = sceneMaterialRecord(m);
  ShadingMaterial s;
  s.color = g.colorKa.xyz;
  s.ka = g.colorKa.w;
  s.kd = g.kdKsExpKps.x;
  s.ks = g.kdKsExpKps.y;
  s.exponent = g.kdKsExpKps.z;
  s.kps = g.kdKsExpKps.w;
  s.specularColor = g.specularIor.xyz;
  s.ior = g.specularIor.w;
  s.mirrorColor = g.mirrorKt.xyz;
  s.kt = g.mirrorKt.w;
  s.transmitColor = g.transmitAlpha.xyz;
  s.alpha = g.transmitAlpha.w;
  s.emission = g.emissionChecker.xyz;
  s.model = sceneMaterialModel(m);
  s.baseColor = g.baseMetallic.xyz;
  s.metallic = g.baseMetallic.w;
  s.roughness = g.tintRoughness.w;
  s.specularTint = g.tintRoughness.xyz;
  s.transmission = g.modelTransSpec.y;
  s.specularWeight = g.modelTransSpec.z;
#if DIPTYCH_SCENE_IRIDESCENCE
  s.iridescence = g.iridescence.x;
  s.iridescenceIor = g.iridescence.y;
  s.iridescenceThickness = g.iridescence.w;
  int filmTex = int(g.iridescenceTextures.x);
  if (sceneTextureValid(filmTex)) s.iridescence *= sceneMaterialTexture(filmTex, uv, uvLod).x;
  int thicknessTex = int(g.iridescenceTextures.y);
  if (sceneTextureValid(thicknessTex))
    s.iridescenceThickness =
        mix(g.iridescence.z, g.iridescence.w, sceneMaterialTexture(thicknessTex, uv, uvLod).y);
#else
  s.iridescence = 0.0;  // a constant: pbr.glsl's film paths fold away
  s.iridescenceIor = 1.0;
  s.iridescenceThickness = 0.0;
#endif
#if DIPTYCH_SCENE_CHECKER || DIPTYCH_SCENE_TEXTURES
  int colourTex = int(g.texColorEmitMrAo.x);
  if (DIPTYCH_SCENE_CHECKER != 0 && g.emissionChecker.w > 0.5) {
    vec2 cell = floor(uv * g.checkerAScale.w);
    bool odd = mod(cell.x + cell.y, 2.0) != 0.0;
    s.color = odd ? g.checkerBCutoff.xyz : g.checkerAScale.xyz;
    s.baseColor = s.color;
  } else if (DIPTYCH_SCENE_TEXTURES != 0 && sceneTextureValid(colourTex)) {
    vec4 c = sceneMaterialTexture(colourTex, uv, uvLod);
    s.color *= c.xyz;
    s.baseColor *= c.xyz;
    s.alpha *= c.w;
  }
#endif
#if DIPTYCH_SCENE_TEXTURES
  int emissionTex = int(g.texColorEmitMrAo.y);
  if (sceneTextureValid(emissionTex)) s.emission *= sceneMaterialTexture(emissionTex, uv, uvLod).xyz;
#endif
#if DIPTYCH_SCENE_REMAP
  // remapsPerTexel (gate 8): the glTF inputs at this texel (a metallic-roughness texel, 1
  // without that texture; the base colour factor times the colour texel, or the checker's
  // colour, which replaces it) through the loader's mapping, as resolveMaterial.
  if ((int(g.modelTransSpec.w) & 8) != 0) {
    vec4 mr = sceneMaterialTexture(int(g.texColorEmitMrAo.z), uv, uvLod);
    vec3 base = sceneTextureValid(colourTex) ? sceneMaterialTexture(colourTex, uv, uvLod).xyz : vec3(1.0);
    if (DIPTYCH_SCENE_CHECKER == 0 || g.emissionChecker.w <= 0.5) base *= g.baseFactorMetallic.xyz;
    else base = s.baseColor;  // the checker's colour (above)
    sceneApplyGltfPbr(s, base, g.baseFactorMetallic.w * mr.z, g.roughnessFactor.x * mr.y,
                      g.texNormalScales.w);
    // The glTF model's own inputs at this texel (resolveMaterial does the same).
    s.metallic = clamp(g.baseFactorMetallic.w * mr.z, 0.0, 1.0);
    s.roughness = clamp(g.roughnessFactor.x * mr.y, 0.0, 1.0);
  }
#endif
#if DIPTYCH_SCENE_TEXTURES
  int aoTex = int(g.texColorEmitMrAo.w);
  if (sceneTextureValid(aoTex)) {
    float ao = sceneMaterialTexture(aoTex, uv, uvLod).x;
    s.ka *= 1.0 + g.texNormalScales.z * (ao - 1.0);
  }
#endif
  return s;
}

ShadingMaterial sceneMaterial(int m, vec2 uv) { return sceneMaterialLod(m, uv, -3.0e38); }

// KHR_materials_volume on the raster side: volumeTransmittance over the material's
// thicknessFactor (1 for thin-walled materials), packed by engine/gl/shading_buffers.cpp.
vec3 sceneVolumeTransmittance(int m) { return sceneMaterialRecord(m).roughnessFactor.yzw; }

// glTF 3.9.3 normal map as engine/rt/surface_point.cpp normalMapped: n' = normalize(T x + B y
// + N z), (x, y, z) = (2 texel - 1) * (scale, scale, 1), T Gram-Schmidt against n, B = w (N x T).
vec3 sceneNormalMapped(int m, vec3 n, vec4 tangent, vec2 uv) {
#if !DIPTYCH_SCENE_NORMAL_MAPS
  return n;
#endif
  GpuMaterial g = sceneMaterialRecord(m);
  int tex = int(g.texNormalScales.x);
  if (!sceneTextureValid(tex)) return n;
  vec3 nn = length(n) > 0.0 ? normalize(n) : n;
  vec3 t = tangent.xyz - nn * dot(nn, tangent.xyz);
  float len = length(t);
  if (!(len > 0.0) || isinf(len)) return n;
  t /= len;
  vec3 b = cross(nn, t) * (tangent.w < 0.0 ? -1.0 : 1.0);
  vec4 texel = sceneSampleTexture(tex, uv);
  float scale = g.texNormalScales.y;
  vec3 ts = vec3((2.0 * texel.x - 1.0) * scale, (2.0 * texel.y - 1.0) * scale, 2.0 * texel.z - 1.0);
  vec3 mapped = ts.x * t + ts.y * b + ts.z * nn;
  float mlen = length(mapped);
  return mlen > 0.0 && !isinf(mlen) ? mapped / mlen : n;
}
// --- end textures ---

// The lecture's bump mapping as engine/shading/bump.cpp bumpMapNormal: f_h from the height
// texture's first channel (bilinear, level 0, its wrap modes) or the sinusoid
// A sin(2 pi f_u u) cos(2 pi f_v v); d_u, d_v by central differences (common/bump.glsl).
float sceneBumpHeight(GpuMaterial g, vec2 uv) {
  if (g.bumpKindTexKDelta.x > 1.5) {
    const float kTwoPi = 6.28318530717959;
    return g.bumpWave.x * sin(kTwoPi * g.bumpWave.y * uv.x) * cos(kTwoPi * g.bumpWave.z * uv.y);
  }
  int tex = int(g.bumpKindTexKDelta.y);
  return sceneTextureValid(tex) ? sceneSampleLevel(tex, 0, uv, true).x : 0.0;
}

// n' of material m at uv from t_u = dP/du, t_v = dP/dv; n unchanged without a bump map.
vec3 sceneBumpMapped(int m, vec3 n, vec3 tu, vec3 tv, vec2 uv) {
  GpuMaterial g = sceneMaterialRecord(m);
  if (!(g.bumpKindTexKDelta.x > 0.5)) return n;
  float k = g.bumpKindTexKDelta.z, d = g.bumpKindTexKDelta.w;
  float du = bumpSlope(sceneBumpHeight(g, uv + vec2(d, 0.0)), sceneBumpHeight(g, uv - vec2(d, 0.0)), k, d);
  float dv = bumpSlope(sceneBumpHeight(g, uv + vec2(0.0, d)), sceneBumpHeight(g, uv - vec2(0.0, d)), k, d);
  return bumpNormal(tu, tv, n, du, dv);
}

// dP/du, dP/dv of a triangle (engine/shading/bump.cpp triangleTangents); zero when its uv
// triangle is degenerate.
void sceneTriangleTangents(vec3 p0, vec3 p1, vec3 p2, vec2 t0, vec2 t1, vec2 t2, out vec3 tu,
                           out vec3 tv) {
  vec3 e1 = p1 - p0, e2 = p2 - p0;
  vec2 d1 = t1 - t0, d2 = t2 - t0;
  float det = d1.x * d2.y - d2.x * d1.y;
  tu = vec3(0.0);
  tv = vec3(0.0);
  if (!(abs(det) > 0.0) || isinf(det)) return;
  float r = 1.0 / det;
  tu = (e1 * d2.y - e2 * d1.y) * r;
  tv = (e2 * d1.x - e1 * d2.x) * r;
}

// Surface detail on a triangle, in makeSurfacePoint's order: the normal map, then the bump map.
vec3 sceneDetailNormal(int m, vec3 n, vec4 tangent, vec3 p0, vec3 p1, vec3 p2, vec2 t0, vec2 t1,
                       vec2 t2, vec2 uv) {
  n = sceneNormalMapped(m, n, tangent, uv);
#if DIPTYCH_SCENE_BUMP  // gl/scene_features.glsl
  if (!(sceneMaterialRecord(m).bumpKindTexKDelta.x > 0.5)) return n;
  vec3 tu, tv;
  sceneTriangleTangents(p0, p1, p2, t0, t1, t2, tu, tv);
  n = sceneBumpMapped(m, n, tu, tv, uv);
#endif
  return n;
}

// Coverage of material m at uv: its alpha times its colour texture's alpha (nearest or
// bilinear by the texture's magnification filter), as resolveMaterial computes it on the CPU.
float sceneMaterialAlpha(int m, vec2 uv) {
  GpuMaterial g = sceneMaterialRecord(m);
  float alpha = g.transmitAlpha.w;
  int layer = int(g.alphaMask.x);
  if (layer < 0) return alpha;
  ivec2 size = ivec2(g.alphaMask.yz);
  int flags = int(g.alphaMask.w);
  int wrapS = flags & 3, wrapT = (flags >> 2) & 3;
  vec2 t = vec2(sceneReduceCoordinate(uv.x, wrapS), sceneReduceCoordinate(uv.y, wrapT));
  if ((flags & 16) == 0) {
    ivec2 p = ivec2(floor(t * vec2(size)));
    p = ivec2(sceneWrapTexel(p.x, size.x, wrapS), sceneWrapTexel(p.y, size.y, wrapT));
    return alpha * texelFetch(uSceneAlphaMasks, ivec3(p, layer), 0).r;
  }
  vec2 x = t * vec2(size) - 0.5;
  vec2 x0 = floor(x);
  vec2 f = x - x0;
  ivec2 i0 = ivec2(x0);
  int xa = sceneWrapTexel(i0.x, size.x, wrapS), xb = sceneWrapTexel(i0.x + 1, size.x, wrapS);
  int ya = sceneWrapTexel(i0.y, size.y, wrapT), yb = sceneWrapTexel(i0.y + 1, size.y, wrapT);
  float top = mix(texelFetch(uSceneAlphaMasks, ivec3(xa, ya, layer), 0).r,
                  texelFetch(uSceneAlphaMasks, ivec3(xb, ya, layer), 0).r, f.x);
  float bottom = mix(texelFetch(uSceneAlphaMasks, ivec3(xa, yb, layer), 0).r,
                     texelFetch(uSceneAlphaMasks, ivec3(xb, yb, layer), 0).r, f.x);
  return alpha * mix(top, bottom, f.y);
}

float sceneMaterialAlphaCutoff(int m) { return sceneMaterialRecord(m).checkerBCutoff.w; }

ShadingLight sceneLight(int i) {
  GpuLight g = sceneLightRecord(i);
  ShadingLight l;
#if DIPTYCH_SCENE_LIGHT_TYPE >= 0
  l.type = DIPTYCH_SCENE_LIGHT_TYPE;  // a constant: sampleLight's type tests fold
#else
  l.type = int(g.typeRangeCos.x);
#endif
  l.range = g.typeRangeCos.y;
  l.cosInner = g.typeRangeCos.z;
  l.cosOuter = g.typeRangeCos.w;
  l.color = g.colorIntensity.xyz;
  l.intensity = g.colorIntensity.w;
  l.position = g.positionArea.xyz;
  l.area = g.positionArea.w;
  l.direction = g.directionShadow.xyz;
  return l;
}

bool sceneLightCastsShadows(int i) { return sceneLightRecord(i).directionShadow.w > 0.5; }

int sceneInstanceMaterial(int instance) { return texelFetch(uSceneInstances, instance).x - 1; }
uint sceneInstanceFirstTriangle(int instance) { return uint(texelFetch(uSceneInstances, instance).y); }

// Whether the material of a hits texel can have a reflection (`lobe`: as hasReflection) or a
// transmission signal at any of its points (bits packed by engine/gl/shading_buffers.cpp from
// shading::materialHas*): false means hasReflection / hasTransmission is false at every point,
// so a producer writes its zero without rebuilding the surface (as passes/rt/rt_secondary.cpp).
bool sceneHitMayReflect(uvec4 hits, bool lobe) {
  if (hits.x == 0u) return false;
  int gates = int(sceneMaterialRecord(sceneInstanceMaterial(int(hits.x) - 1)).modelTransSpec.w);
  return (gates & (lobe ? 2 : 1)) != 0;
}
bool sceneHitMayTransmit(uvec4 hits) {
  if (hits.x == 0u) return false;
  int gates = int(sceneMaterialRecord(sceneInstanceMaterial(int(hits.x) - 1)).modelTransSpec.w);
  return (gates & 4) != 0;
}

// A point on the scene named by a visibility texel (instance + 1, primitive, u bits, v bits).
struct SceneSurface {
  bool hit;
  int instance;
  vec3 position;       // (1-u-v) p0 + u p1 + v p2, the CPU's interpolatePosition order
  vec3 faceNormal;     // unit, counter-clockwise front face
  vec3 shadingNormal;  // interpolated vertex normal, unit (face normal if degenerate)
  vec2 uv;
  int material;        // -1: default material
};

// A hits texel's instance and hit flag, every other field at its background value (what a
// background pixel keeps; surfaceFromHits and surfaceFromGBuffer fill the rest on a hit).
SceneSurface sceneSurfaceDefaults(uvec4 texel) {
  SceneSurface s;
  s.hit = texel.x != 0u;
  s.instance = int(texel.x) - 1;
  s.position = vec3(0.0);
  s.faceNormal = vec3(0.0, 1.0, 0.0);
  s.shadingNormal = s.faceNormal;
  s.uv = vec2(0.0);
  s.material = -1;
  return s;
}

SceneSurface surfaceFromHits(uvec4 texel) {
  SceneSurface s = sceneSurfaceDefaults(texel);
  if (!s.hit) return s;
  float u = uintBitsToFloat(texel.z), v = uintBitsToFloat(texel.w);
  uvec3 tri = sceneTriangle(sceneInstanceFirstTriangle(s.instance) + texel.y);
  vec3 p0 = scenePosition(tri.x), p1 = scenePosition(tri.y), p2 = scenePosition(tri.z);
  float w = 1.0 - u - v;
  s.position = w * p0 + u * p1 + v * p2;
  s.faceNormal = safeNormalize(cross(p1 - p0, p2 - p0));
  vec3 n = w * sceneNormal(tri.x) + u * sceneNormal(tri.y) + v * sceneNormal(tri.z);
  s.shadingNormal = maxAbsComponent(n) > 0.0 ? normalize(n) : s.faceNormal;
  vec2 t0 = sceneUv(tri.x);
  vec2 t1 = sceneUv(tri.y);
  vec2 t2 = sceneUv(tri.z);
  s.uv = w * t0 + u * t1 + v * t2;
  s.material = sceneInstanceMaterial(s.instance);
  // The CPU maps the interpolated normal (makeSurfacePoint); zero tangents leave it unchanged.
#if DIPTYCH_SCENE_NORMAL_MAPS || DIPTYCH_SCENE_BUMP
  vec4 tg = w * sceneTangent(tri.x) + u * sceneTangent(tri.y) + v * sceneTangent(tri.z);
  s.shadingNormal = sceneDetailNormal(s.material, s.shadingNormal, tg, p0, p1, p2, t0, t1, t2, s.uv);
#endif
  return s;
}
