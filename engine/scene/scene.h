#pragma once
// The in-memory scene every layer reads: meshes, instances, materials (lecture coefficients),
// textures, lights, camera and environment. Loaders fill it and validate it; nothing else
// mutates it after loading.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "engine/core/math.h"
#include "engine/scene/analytic_shape.h"

namespace diptych {

struct SdfObject;  // engine/scene/sdf.h

// An indexed triangle mesh in object space. normals/uvs/tangents are either empty or have one
// entry per position. Triangles are counter-clockwise when seen from the front.
struct Mesh {
  std::string name;  // "meshes[2] 'Helmet' primitive 0" style, used in error messages
  std::vector<vec3> positions;
  std::vector<vec3> normals;
  std::vector<vec2> uvs;
  std::vector<vec4> tangents;          // xyz tangent, w handedness (glTF convention)
  std::vector<std::uint32_t> indices;  // 3 per triangle
  int material = -1;                   // -1: the default material
  // Set when the triangles tessellate an analytic shape that ray tracers should intersect
  // exactly instead (JSON "geometry": "analytic"); rasterizers always draw the triangles.
  std::optional<AnalyticShape> analytic;
  // Set for a signed-distance object ("type": "sdf"): ray tracers sphere-trace it; the
  // triangles are its surface-nets polygonisation.
  std::shared_ptr<const SdfObject> sdf;
  std::size_t triangleCount() const { return indices.size() / 3; }
};

// A placed mesh. A negative determinant mirrors the mesh: consumers that flatten it must flip
// the triangle winding so that front faces stay counter-clockwise.
struct Instance {
  std::string name;
  int mesh = 0;
  mat4 transform{1.f};  // the placement at kFrameTime (engine/scene/camera_math.h)
  // World-space displacement over the shutter interval [0, 1], centred on the frame's instant:
  // at time t the instance is translate((t - kFrameTime) * motion) * transform. Zero: static.
  // Only rays that carry a time see it move (distributed ray tracing's motion blur).
  vec3 motion{0.f};
};

enum class WrapMode { Repeat, ClampToEdge, MirroredRepeat };
enum class FilterMode {
  Nearest,
  Linear,
  NearestMipmapNearest,
  LinearMipmapNearest,
  NearestMipmapLinear,
  LinearMipmapLinear
};

// A texture image decoded to linear float RGBA (colour textures marked sRGB in the file are
// decoded with the sRGB transfer function at load, as glTF specifies for baseColor/emissive).
struct Texture {
  std::string name;
  Image image;  // 4 channels, linear
  bool srgbSource = false;
  WrapMode wrapS = WrapMode::Repeat, wrapT = WrapMode::Repeat;
  FilterMode minFilter = FilterMode::LinearMipmapLinear, magFilter = FilterMode::Linear;
  // Levels 1..n of the lecture's mip chain (engine/scene/mip_chain.h), built by loadScene;
  // empty: only level 0 exists (a sampler then reads level 0 at every LOD).
  std::vector<Image> mips;
};

enum class AlphaMode { Opaque, Mask, Blend };

// Procedural checkerboard in uv space: colour alternates between colorA and colorB every
// 1/scale units of u and v.
struct Checker {
  vec3 colorA{1.f}, colorB{0.f};
  float scale = 1.f;
};

// The lecture's extended local illumination model (Tema 5, "Un M.I.L. extendido"):
// L = M_E + A_G + sum_i V_i S_i [k_a C + k_d C max(0,n.l) + k_s d_i max(0,r.v)^e]
//       + k_ps M_PS L_refl + k_t M_T L_trans.
// d_i is the specular colour (specularColor), white unless authored.
// The lecture's bump mapping (Tema 5, "Perturbación de la normal"): a height field f_h over uv,
// either a greyscale texture (its first channel) or the procedural sinusoid
// f_h = amplitude sin(2 pi frequency.x u) cos(2 pi frequency.y v); d_u, d_v by central
// differences with step `delta` (uv units), scaled by k (engine/shading/bump.h).
struct BumpMap {
  int texture = -1;  // index into Scene::textures; -1: the procedural sinusoid
  float amplitude = 0.f;
  vec2 frequency{1.f};
  float k = 1.f;
  float delta = 1.f / 1024.f;
};

// Which shared model shades a material (shaders/common/shading.glsl dispatches on it): the
// lecture's (JSON default) or glTF 2.0 metallic-roughness (glTF default; pbr.glsl).
enum class ShadingModel { Lecture, Gltf };

struct Material {
  std::string name;
  vec3 color{0.8f};  // C
  float ka = 0.f, kd = 1.f, ks = 0.f, exponent = 32.f;
  vec3 specularColor{1.f};  // d_i
  float kps = 0.f;          // perfect-mirror fraction
  vec3 mirrorColor{1.f};    // M_PS
  float kt = 0.f;           // transmitted fraction
  vec3 transmitColor{1.f};  // M_T
  vec3 emission{0.f};       // M_E
  float ior = 1.5f;
  // KHR_materials_volume, kept for thickness-aware transmission: thickness in object units (0 =
  // thin-walled), Beer-Lambert attenuation colour reached after attenuationDistance (0 = none).
  float thickness = 0.f;
  vec3 attenuationColor{1.f};
  float attenuationDistance = 0.f;
  float alpha = 1.f;  // coverage (glTF baseColor alpha)
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  int colorTexture = -1;           // multiplies C (and alpha); index into Scene::textures
  int emissionTexture = -1;        // multiplies M_E
  std::optional<Checker> checker;  // replaces C when present
  ShadingModel model = ShadingModel::Lecture;
  bool fromGltfPbr = false;  // true when mapped from metallic-roughness (see docs/scene-format.md)
  // glTF metallic-roughness inputs, kept so that textured materials can be mapped per hit
  // (gltfPbrAt in engine/scene/gltf_pbr.h) instead of from one averaged constant.
  vec4 baseColorFactor{1.f};
  float metallicFactor = 1.f, roughnessFactor = 1.f, transmissionFactor = 0.f;
  int metallicRoughnessTexture = -1;  // linear; G = roughness, B = metallic
  int occlusionTexture = -1;          // linear; R scales k_a and A_G
  float occlusionStrength = 1.f;
  int normalTexture = -1;  // linear tangent-space normal map, (2 t - 1) * (scale, scale, 1)
  float normalScale = 1.f;
  std::optional<BumpMap> bump;  // JSON "bump" key; perturbs the shading normal (CPU side)
  float specularWeight = 1.f;   // KHR_materials_specular specularFactor
  vec3 specularTint{1.f};       // KHR_materials_specular specularColorFactor
  // KHR_materials_iridescence: a thin film over the specular layer (pbr.glsl). Strength = factor
  // times the R of iridescenceTexture; thickness (nm) = mix(minimum, maximum, G of
  // iridescenceThicknessTexture), or the maximum without that texture.
  float iridescenceFactor = 0.f;
  float iridescenceIor = 1.3f;
  float iridescenceThicknessMinimum = 100.f, iridescenceThicknessMaximum = 400.f;
  int iridescenceTexture = -1;           // linear; R scales iridescenceFactor
  int iridescenceThicknessTexture = -1;  // linear; G blends minimum to maximum
  bool castsShadows = true;
};

enum class LightType { Point, Directional, Spot, QuadArea, DiscArea, SphereArea };

// S_i of the lecture is color * intensity (/ d^2 for point and spot): the radiance a white
// Lambertian surface facing the light reflects (docs/materials.md, "Light units"). JSON scenes
// give it directly; the glTF loader converts KHR_lights_punctual candela and lux to it. Area
// lights give radiance per unit area. Point/spot/area fall off with 1/d^2 (range ignored except
// as a hard cut-off when > 0).
struct Light {
  std::string name;
  LightType type = LightType::Point;
  vec3 color{1.f};
  float intensity = 1.f;
  vec3 position{0.f};
  vec3 direction{0.f, -1.f, 0.f};  // direction the light travels (directional, spot, area normal)
  float range = 0.f;               // 0: infinite
  float innerConeAngle = 0.f, outerConeAngle = 0.7853982f;  // spot, radians
  vec3 edgeU{0.f}, edgeV{0.f};  // quad area: corners position +- edgeU/2 +- edgeV/2
  float radius = 0.f;           // disc and sphere area lights
  bool castsShadows = true;
};

struct Camera {
  vec3 position{0.f, 0.f, 5.f};
  vec3 target{0.f};
  vec3 up{0.f, 1.f, 0.f};
  float verticalFov = 0.7853982f;  // radians
  float aperture = 0.f;  // thin-lens radius (rt_distributed, rt_path: thinLensRay); 0 = pinhole
  float focusDistance = 1.f;
  float znear = 0.05f;  // reversed-Z makes far irrelevant to precision; kept finite for export
  float zfar = 1000.f;
};

enum class EnvironmentType { Color, Equirect, Cube };

// Background radiance on a miss. Equirect uses u = 0.5 + atan2(d.z, d.x)/2pi, v = acos(d.y)/pi
// (v = 0 at the top row); cube faces are in OpenGL order +x,-x,+y,-y,+z,-z.
struct Environment {
  EnvironmentType type = EnvironmentType::Color;
  vec3 color{0.f};
  float intensity = 1.f;
  Image equirect;                  // linear RGB(A)
  std::array<Image, 6> cubeFaces;  // linear RGB(A)
  std::string source;              // file(s) it came from, for reports
};

struct Scene {
  std::string sourcePath;
  // Every file the scene was read from: itself, included glTF files, their buffers and images,
  // environment images. Caches key on their bytes, so an edited texture invalidates them.
  std::vector<std::string> sourceFiles;
  std::vector<Mesh> meshes;
  std::vector<Instance> instances;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Light> lights;
  Camera camera;
  bool hasCamera = false;  // false: a camera was framed automatically from the bounds
  // Where the file's origin went when the world was rebased (rebaseIfFar): a position p given in
  // the file's coordinates (e.g. a --light added after loading) is at p - worldOrigin here.
  glm::dvec3 worldOrigin{0.0};
  Environment environment;
  vec3 ambient{0.f};                  // A_G
  std::vector<std::string> warnings;  // recoveries made while loading, each naming the place

  // -1 or out of range -> the default material. Inline: every traced hit asks (several times);
  // the default's function-local static paid a guard test and a call on each.
  const Material& material(int index) const {
    return index >= 0 && index < int(materials.size()) ? materials[std::size_t(index)]
                                                       : defaultMaterial();
  }
  static const Material& defaultMaterial();
  Aabb bounds() const;          // world-space bounds of all instances
  int movingInstances() const;  // instances with a non-zero Instance::motion (motion blur)
  bool hasMotion() const { return movingInstances() > 0; }
};

}  // namespace diptych
