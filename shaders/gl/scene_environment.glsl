// The environment along a direction, exactly as engine/scene/environment.cpp's
// sampleEnvironment() computes it on the CPU (same (u, v) or cube-face (s, t), same bilinear
// weights with texel centres at +0.5, same wrap and clamp), from the texels uploaded by
// passes/raster/gl_environment.cpp. No GL filtering is used, so the GL shade pass shows the
// background the CPU shade pass shows (docs/gl-shade.md).
const int ENVIRONMENT_COLOR = 0;
const int ENVIRONMENT_EQUIRECT = 1;
const int ENVIRONMENT_CUBE = 2;
#ifdef SCENE_ENVIRONMENT_TYPE
// One program per environment kind (gl_shade.cpp): llvmpipe would run every kind's lookup.
const int uEnvironmentType = SCENE_ENVIRONMENT_TYPE;
#else
uniform int uEnvironmentType;
#endif
uniform vec3 uEnvironmentColor;  // the constant times the intensity
// Layer 0: the lat-long image; layers 0..5: cube faces +x,-x,+y,-y,+z,-z. RGB already times
// the intensity; GL row r holds image row height - 1 - r (engine/gl/transfer.h flips rows).
layout(binding = UNIT_SCENE_ENVIRONMENT) uniform sampler2DArray uEnvironmentTexels;

vec3 environmentTexel(int x, int y, int layer, ivec2 size, bool wrapX) {
  x = wrapX ? ((x % size.x) + size.x) % size.x : clamp(x, 0, size.x - 1);
  y = clamp(y, 0, size.y - 1);
  return texelFetch(uEnvironmentTexels, ivec3(x, size.y - 1 - y, layer), 0).rgb;
}

// environment.cpp's bilinear(): continuous pixel coordinates (x, y), image row 0 on top.
vec3 environmentBilinear(float x, float y, int layer, bool wrapX) {
  ivec2 size = textureSize(uEnvironmentTexels, 0).xy;
  float fx = x - 0.5, fy = y - 0.5;
  int x0 = int(floor(fx)), y0 = int(floor(fy));
  float ax = fx - float(x0), ay = fy - float(y0);
  vec3 top = mix(environmentTexel(x0, y0, layer, size, wrapX),
                 environmentTexel(x0 + 1, y0, layer, size, wrapX), ax);
  vec3 bottom = mix(environmentTexel(x0, y0 + 1, layer, size, wrapX),
                    environmentTexel(x0 + 1, y0 + 1, layer, size, wrapX), ax);
  return mix(top, bottom, ay);
}

// atan2 to float precision. Mesa lowers GLSL's atan and acos to polynomials with errors near
// 1e-5, enough to move a lat-long lookup by a visible fraction of a texel (measured: relative
// RMSE 2.8e-4 against the CPU on a random 37x19 map); this evaluates them in double: range
// reduction by atan(t) = 2 atan(t / (1 + sqrt(1 + t^2))) twice (|t| <= tan(pi/16)), then the
// Taylor series to t^19 (< 1e-13), so GL and the CPU's std::atan2 pick the same texels.
const double ENVIRONMENT_PI = 3.14159265358979323846LF;
double environmentAtanUnit(double t) {  // |t| <= 1
  for (int i = 0; i < 2; ++i) t = t / (1.0LF + sqrt(1.0LF + t * t));
  double t2 = t * t, term = t, sum = t;
  for (int k = 1; k <= 9; ++k) {
    term *= -t2;
    sum += term / double(2 * k + 1);
  }
  return 4.0LF * sum;
}

float environmentAtan2(float y, float x) {
  double ay = abs(double(y)), ax = abs(double(x));
  if (ax == 0.0LF && ay == 0.0LF) return 0.0;
  double a = ay <= ax ? environmentAtanUnit(ay / ax)
                      : 0.5LF * ENVIRONMENT_PI - environmentAtanUnit(ax / ay);
  if (x < 0.0) a = ENVIRONMENT_PI - a;
  return float(y < 0.0 ? -a : a);
}

vec3 sceneEnvironment(vec3 direction) {
  float len = length(direction);
  if (!(len > 0.0) || isinf(len)) return vec3(0.0);
  vec3 d = direction / len;
  if (uEnvironmentType == ENVIRONMENT_COLOR) return uEnvironmentColor;
  ivec2 size = textureSize(uEnvironmentTexels, 0).xy;
  if (uEnvironmentType == ENVIRONMENT_EQUIRECT) {
    const float PI = 3.14159265358979;
    float u = 0.5 + environmentAtan2(d.z, d.x) / (2.0 * PI);
    // acos(y) = atan2(sqrt(1 - y^2), y), with 1 - y^2 formed in double.
    double y = double(clamp(d.y, -1.0, 1.0));
    float v = environmentAtan2(float(sqrt((1.0LF - y) * (1.0LF + y))), float(y)) / PI;
    return environmentBilinear(u * float(size.x), v * float(size.y), 0, true);
  }
  // OpenGL 4.5 table 8.19, as cubeFace(): the major axis picks the face and (sc, tc, ma).
  vec3 a = abs(d);
  int face;
  float sc, tc, ma;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x >= 0.0 ? 0 : 1;
    sc = d.x >= 0.0 ? -d.z : d.z;
    tc = -d.y;
    ma = a.x;
  } else if (a.y >= a.z) {
    face = d.y >= 0.0 ? 2 : 3;
    sc = d.x;
    tc = d.y >= 0.0 ? d.z : -d.z;
    ma = a.y;
  } else {
    face = d.z >= 0.0 ? 4 : 5;
    sc = d.z >= 0.0 ? d.x : -d.x;
    tc = -d.y;
    ma = a.z;
  }
  vec2 st = vec2(0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0));
  return environmentBilinear(st.x * float(size.x), st.y * float(size.y), face, false);
}
