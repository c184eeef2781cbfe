// Materials, lights and instances uploaded by engine/gl/shading_buffers.cpp, and the surface
// point of a visibility-buffer texel reconstructed exactly as the CPU does it
// (engine/rt/surface.cpp). Include after common/shading.glsl and gl/scene_buffers.glsl.
struct GpuMaterial {
  vec4 colorKa;         // C, k_a
  vec4 kdKsExpKps;      // k_d, k_s, e, k_ps
  vec4 specularIor;     // d_i, ior
  vec4 mirrorKt;        // M_PS, k_t
  vec4 transmitAlpha;   // M_T, alpha
  vec4 emissionChecker; // M_E, 1 when the checker replaces C
  vec4 checkerAScale;   // checker colour A, scale
  vec4 checkerBCutoff;  // checker colour B, alpha cutoff
};
layout(std430, binding = 4) readonly buffer SceneMaterials { GpuMaterial sceneMaterials[]; };
layout(std430, binding = 5) readonly buffer SceneInstances { ivec2 sceneInstances[]; };
struct GpuLight {
  vec4 typeRangeCos;     // type, range, cos inner, cos outer
  vec4 colorIntensity;   // colour, intensity
  vec4 positionArea;     // position, area
  vec4 directionShadow;  // direction, 1 when it casts shadows
  vec4 edgeURadius;      // quad edge u, radius
};
layout(std430, binding = 6) readonly buffer SceneLights { GpuLight sceneLights[]; };
uniform int uLightCount;  // sceneLights has a dummy entry when the scene has no lights

// Material m of Scene::materials (-1: the default), with the checker applied at uv
// (colour alternates every 1/scale in u and v, as engine/rt/texture_sampling.cpp).
ShadingMaterial sceneMaterial(int m, vec2 uv) {
  GpuMaterial g = sceneMaterials[m + 1];
  ShadingMaterial s;
  s.color = g.colorKa.xyz;
  if (g.emissionChecker.w > 0.5) {
    vec2 cell = floor(uv * g.checkerAScale.w);
    bool odd = mod(cell.x + cell.y, 2.0) != 0.0;
    s.color = odd ? g.checkerBCutoff.xyz : g.checkerAScale.xyz;
  }
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
  return s;
}

ShadingLight sceneLight(int i) {
  GpuLight g = sceneLights[i];
  ShadingLight l;
  l.type = int(g.typeRangeCos.x);
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

bool sceneLightCastsShadows(int i) { return sceneLights[i].directionShadow.w > 0.5; }

int sceneInstanceMaterial(int instance) { return sceneInstances[instance].x - 1; }
uint sceneInstanceFirstTriangle(int instance) { return uint(sceneInstances[instance].y); }

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

SceneSurface surfaceFromVisibility(uvec4 texel) {
  SceneSurface s;
  s.hit = texel.x != 0u;
  s.instance = int(texel.x) - 1;
  s.position = vec3(0.0);
  s.faceNormal = vec3(0.0, 1.0, 0.0);
  s.shadingNormal = s.faceNormal;
  s.uv = vec2(0.0);
  s.material = -1;
  if (!s.hit) return s;
  float u = uintBitsToFloat(texel.z), v = uintBitsToFloat(texel.w);
  uvec3 tri = sceneTriangle(sceneInstanceFirstTriangle(s.instance) + texel.y);
  vec3 p0 = scenePosition(tri.x), p1 = scenePosition(tri.y), p2 = scenePosition(tri.z);
  float w = 1.0 - u - v;
  s.position = w * p0 + u * p1 + v * p2;
  s.faceNormal = safeNormalize(cross(p1 - p0, p2 - p0));
  vec3 n = w * sceneNormal(tri.x) + u * sceneNormal(tri.y) + v * sceneNormal(tri.z);
  s.shadingNormal = maxAbsComponent(n) > 0.0 ? normalize(n) : s.faceNormal;
  vec2 t0 = vec2(sceneUvs[2u * tri.x], sceneUvs[2u * tri.x + 1u]);
  vec2 t1 = vec2(sceneUvs[2u * tri.y], sceneUvs[2u * tri.y + 1u]);
  vec2 t2 = vec2(sceneUvs[2u * tri.z], sceneUvs[2u * tri.z + 1u]);
  s.uv = w * t0 + u * t1 + v * t2;
  s.material = sceneInstanceMaterial(s.instance);
  return s;
}
