#include "engine/scene/validate.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/gtx/component_wise.hpp>
#include <type_traits>

#include "engine/core/error.h"

namespace diptych {
namespace {

bool finite(float v) {
  return std::isfinite(v);
}
bool finite(const vec2& v) {
  return finite(v.x) && finite(v.y);
}
bool finite(const vec3& v) {
  return allFinite(v);
}
bool finite(const vec4& v) {
  return finite(vec3(v)) && finite(v.w);
}
bool finite(const mat4& m) {
  for (int c = 0; c < 4; ++c)
    if (!finite(m[c])) return false;
  return true;
}

// Whether every float of a float or float-vector array is finite (a 2048^2 RGBA texture is 16 M
// values): the exponent bits are all ones exactly for Inf and NaN (IEEE 754), and then adding
// one to the exponent field carries into the sign bit, so OR-ing (bits & exponent) + one over a
// block and testing the sign bit checks every value without a branch. Blocks of a fixed length
// let the compiler vectorise the scan at -O2, where a per-element std::isfinite with an early
// exit is not. Only when it fails does finiteArray look for the first bad element, to name it.
template <typename T>
bool allFiniteFloats(const std::vector<T>& values) {
  static_assert(std::is_same_v<T, float> ||
                requires { requires std::is_same_v<typename T::value_type, float>; });
  static_assert(sizeof(T) % sizeof(float) == 0);
  constexpr std::uint32_t kExponent = 0x7f800000u, kOne = 0x00800000u, kSign = 0x80000000u;
  constexpr std::size_t kBlock = 64;
  const std::size_t n = values.size() * (sizeof(T) / sizeof(float));
  const auto* data = reinterpret_cast<const unsigned char*>(values.data());
  const auto word = [data](std::size_t i) {
    std::uint32_t bits;
    std::memcpy(&bits, data + i * sizeof(float), sizeof(float));
    return bits;
  };
  std::uint32_t carried = 0;
  std::size_t i = 0;
  for (; i + kBlock <= n; i += kBlock)
    for (std::size_t j = 0; j < kBlock; ++j) carried |= (word(i + j) & kExponent) + kOne;
  for (; i < n; ++i) carried |= (word(i) & kExponent) + kOne;
  return (carried & kSign) == 0;
}

class SceneChecker {
 public:
  explicit SceneChecker(const Scene& scene) : file_(scene.sourcePath) {}

  template <typename T>
  void finiteValue(const T& v, const std::string& place) const {
    if (!finite(v)) fail(place, "non-finite value");
  }
  template <typename T>
  void finiteArray(const std::vector<T>& values, const std::string& place) const {
    if (allFiniteFloats(values)) return;
    for (std::size_t i = 0; i < values.size(); ++i)
      if (!finite(values[i])) fail(place + "[" + std::to_string(i) + "]", "non-finite value");
  }
  void nonNegative(float v, const std::string& place) const {
    finiteValue(v, place);
    if (v < 0.f) fail(place, "must not be negative (is " + std::to_string(v) + ")");
  }
  void nonNegative(const vec3& v, const std::string& place) const {
    finiteValue(v, place);
    if (v.x < 0.f || v.y < 0.f || v.z < 0.f) fail(place, "components must not be negative");
  }
  // A non-negative value (or each component) at most `limit`.
  template <typename T>
  void bounded(const T& v, float limit, const std::string& place) const {
    nonNegative(v, place);
    if (glm::compMax(vec3(v)) > limit)
      fail(place, fmt::format("must be at most {:g} (is {:g})", limit, glm::compMax(vec3(v))));
  }
  // Each component's magnitude at most `limit`.
  template <typename T>
  void magnitude(const T& v, float limit, const std::string& place) const {
    finiteValue(v, place);
    if (glm::compMax(glm::abs(vec3(v))) > limit)
      fail(place, fmt::format("magnitude must be at most {:g} (is {:g})", limit,
                              glm::compMax(glm::abs(vec3(v)))));
  }
  [[noreturn]] void fail(const std::string& place, const std::string& message) const {
    throw InputError(file_, place, message);
  }

 private:
  const std::string& file_;
};

std::string meshPlace(const Mesh& mesh, std::size_t index) {
  return mesh.name.empty() ? "mesh " + std::to_string(index) : mesh.name;
}

void checkMesh(Mesh& mesh, std::size_t index, const Scene& scene, const SceneChecker& check,
               std::vector<std::string>& warnings) {
  const std::string place = meshPlace(mesh, index);
  const std::size_t n = mesh.positions.size();
  check.finiteArray(mesh.positions, place + " positions");
  check.finiteArray(mesh.normals, place + " normals");
  check.finiteArray(mesh.uvs, place + " uvs");
  check.finiteArray(mesh.tangents, place + " tangents");
  auto sameLength = [&](std::size_t size, const char* what) {
    if (size != 0 && size != n)
      check.fail(place, std::string(what) + " has " + std::to_string(size) + " entries for " +
                            std::to_string(n) + " positions");
  };
  sameLength(mesh.normals.size(), "normals");
  sameLength(mesh.uvs.size(), "uvs");
  sameLength(mesh.tangents.size(), "tangents");
  if (mesh.indices.size() % 3 != 0)
    check.fail(place + " indices", "count " + std::to_string(mesh.indices.size()) +
                                       " is not a whole number of triangles");
  for (std::size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] >= n)
      check.fail(place + " indices[" + std::to_string(i) + "]",
                 "index " + std::to_string(mesh.indices[i]) + " is out of range (" +
                     std::to_string(n) + " vertices)");
  if (mesh.material < -1 || mesh.material >= int(scene.materials.size()))
    check.fail(place + " material",
               "material " + std::to_string(mesh.material) + " does not exist");

  // Zero normals would normalise to NaN in every shader; rebuild them from the faces.
  std::size_t zero = 0;
  std::vector<vec3> rebuilt;
  for (std::size_t v = 0; v < mesh.normals.size(); ++v) {
    const float len = glm::length(mesh.normals[v]);
    if (len > 1e-20f) {
      mesh.normals[v] /= len;
      continue;
    }
    if (rebuilt.empty()) rebuilt = areaWeightedNormals(mesh);
    mesh.normals[v] = rebuilt[v] == vec3(0.f) ? vec3(0.f, 1.f, 0.f) : rebuilt[v];
    ++zero;
  }
  if (zero > 0)
    warnings.push_back(scene.sourcePath + ": " + place + ": " + std::to_string(zero) +
                       " zero-length normals replaced by area-weighted face normals");
}

void checkMaterial(const Material& m, std::size_t index, const Scene& scene,
                   const SceneChecker& check) {
  const std::string place = "materials[" + std::to_string(index) + "] '" + m.name + "'";
  check.bounded(m.color, kMaxReflectance, place + " color");
  check.bounded(m.ka, kMaxReflectance, place + " ka");
  check.bounded(m.kd, kMaxReflectance, place + " kd");
  check.bounded(m.ks, kMaxReflectance, place + " ks");
  check.bounded(m.exponent, kMaxExponent, place + " exponent");
  check.bounded(m.specularColor, kMaxReflectance, place + " specular_color");
  check.bounded(m.kps, kMaxReflectance, place + " kps");
  check.bounded(m.mirrorColor, kMaxReflectance, place + " mirror_color");
  check.bounded(m.kt, kMaxReflectance, place + " kt");
  check.bounded(m.transmitColor, kMaxReflectance, place + " transmit_color");
  check.bounded(m.emission, kMaxEmitted, place + " emission");
  check.bounded(m.thickness, kMaxCoordinate, place + " thickness");
  check.nonNegative(m.attenuationColor, place + " attenuation_color");
  check.bounded(m.attenuationDistance, kMaxCoordinate, place + " attenuation_distance");
  check.finiteValue(m.ior, place + " ior");
  // 0 is KHR_materials_ior's specular-glossiness compatibility mode, an infinite IOR: the F0
  // formula ((n-1)/(n+1))^2 gives its limit 1 at n = 0, and refractLecture sends an infinite or
  // zero eta straight on (with weight 0: the Fresnel term is 1).
  if (m.ior < 0.f)
    check.fail(place + " ior", "must be positive, or 0 (KHR_materials_ior: an infinite IOR)");
  check.finiteValue(m.alpha, place + " alpha");
  check.finiteValue(m.alphaCutoff, place + " alphaCutoff");
  for (int t : {m.colorTexture, m.emissionTexture})
    if (t < -1 || t >= int(scene.textures.size()))
      check.fail(place, "texture " + std::to_string(t) + " does not exist");
  if (m.checker) {
    check.bounded(m.checker->colorA, kMaxReflectance, place + " checker.a");
    check.bounded(m.checker->colorB, kMaxReflectance, place + " checker.b");
    check.finiteValue(m.checker->scale, place + " checker.scale");
    if (m.checker->scale <= 0.f) check.fail(place + " checker.scale", "must be positive");
    check.magnitude(m.checker->scale, kMaxCoordinate, place + " checker.scale");
  }
}

void checkLight(const Light& l, std::size_t index, const SceneChecker& check) {
  const std::string place = "lights[" + std::to_string(index) + "] '" + l.name + "'";
  check.nonNegative(l.color, place + " color");
  check.nonNegative(l.intensity, place + " intensity");
  check.bounded(l.color * l.intensity, kMaxEmitted, place + " color x intensity");
  check.magnitude(l.position, kMaxCoordinate, place + " position");
  check.finiteValue(l.direction, place + " direction");
  check.bounded(l.range, kMaxCoordinate, place + " range");
  check.magnitude(l.edgeU, kMaxCoordinate, place + " edge_u");
  check.magnitude(l.edgeV, kMaxCoordinate, place + " edge_v");
  check.bounded(l.radius, kMaxCoordinate, place + " radius");
  const bool directed = l.type == LightType::Directional || l.type == LightType::Spot ||
                        l.type == LightType::DiscArea;
  if (directed && glm::length(l.direction) == 0.f)
    check.fail(place + " direction", "must not be the zero vector");
  if (l.type == LightType::Spot) {
    check.nonNegative(l.innerConeAngle, place + " inner cone angle");
    check.finiteValue(l.outerConeAngle, place + " outer cone angle");
    if (l.outerConeAngle <= 0.f || l.outerConeAngle > 0.5f * glm::pi<float>() ||
        l.innerConeAngle > l.outerConeAngle)
      check.fail(place, "spot cone angles need 0 <= inner <= outer <= 90 degrees, outer > 0");
  }
  if (l.type == LightType::QuadArea && glm::length(glm::cross(l.edgeU, l.edgeV)) == 0.f)
    check.fail(place, "quad area light has zero area (edge_u and edge_v are parallel or zero)");
  if ((l.type == LightType::DiscArea || l.type == LightType::SphereArea) && l.radius <= 0.f)
    check.fail(place + " radius", "must be positive");
}

void checkCamera(const Camera& c, const SceneChecker& check) {
  check.magnitude(c.position, kMaxCoordinate, "camera position");
  check.magnitude(c.target, kMaxCoordinate, "camera target");
  check.finiteValue(c.up, "camera up");
  check.finiteValue(c.verticalFov, "camera fov");
  check.nonNegative(c.aperture, "camera aperture");
  check.finiteValue(c.focusDistance, "camera focus_distance");
  const float degrees = glm::degrees(c.verticalFov);
  if (!(degrees > 0.f && degrees < 180.f))
    check.fail("camera fov", "must be in (0, 180) degrees (is " + std::to_string(degrees) + ")");
  if (c.position == c.target) check.fail("camera target", "equals the camera position");
  if (glm::length(glm::cross(c.target - c.position, c.up)) == 0.f)
    check.fail("camera up", "is zero or parallel to the viewing direction");
  if (!(c.znear > 0.f) || !(c.zfar > c.znear) || !finite(c.zfar))
    check.fail("camera near/far", "need 0 < near < far");
  if (c.focusDistance <= 0.f) check.fail("camera focus_distance", "must be positive");
  check.bounded(c.zfar, kMaxCoordinate, "camera near/far");
  check.bounded(c.focusDistance, kMaxCoordinate, "camera focus_distance");
  check.bounded(c.aperture, kMaxCoordinate, "camera aperture");
}

}  // namespace

std::vector<vec3> areaWeightedNormals(const Mesh& mesh) {
  std::vector<vec3> sum(mesh.positions.size(), vec3(0.f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const vec3 faceTimesTwiceArea =
        glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    for (std::uint32_t v : {a, b, c}) sum[v] += faceTimesTwiceArea;
  }
  for (vec3& n : sum) {
    const float len = glm::length(n);
    n = len > 0.f && std::isfinite(len) ? n / len : vec3(0.f);
  }
  return sum;
}

void validateScene(Scene& scene) {
  const SceneChecker check(scene);
  std::vector<std::string> warnings;
  if (scene.lights.size() > kMaxLights)
    check.fail("lights",
               fmt::format("{} lights; the limit is {}", scene.lights.size(), kMaxLights));
  std::size_t triangles = 0;
  for (const Instance& inst : scene.instances)
    if (inst.mesh >= 0 && inst.mesh < int(scene.meshes.size()))
      triangles += scene.meshes[inst.mesh].indices.size() / 3;
  if (triangles > kMaxTriangles)
    check.fail("instances",
               fmt::format("{} triangles in all; the limit is {}", triangles, kMaxTriangles));
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    checkMesh(scene.meshes[i], i, scene, check, warnings);
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    const std::string place = "instances[" + std::to_string(i) + "] '" + inst.name + "'";
    if (inst.mesh < 0 || inst.mesh >= int(scene.meshes.size()))
      check.fail(place + " mesh", "mesh " + std::to_string(inst.mesh) + " does not exist");
    check.finiteValue(inst.transform, place + " transform");
    check.magnitude(inst.motion, kMaxCoordinate, place + " motion");
  }
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    checkMaterial(scene.materials[i], i, scene, check);
  for (std::size_t i = 0; i < scene.textures.size(); ++i) {
    const Texture& t = scene.textures[i];
    const std::string place = "textures[" + std::to_string(i) + "] '" + t.name + "'";
    if (t.image.empty() || t.image.channels != 4) check.fail(place, "texture has no RGBA pixels");
    check.finiteArray(t.image.pixels, place + " pixels");
  }
  for (std::size_t i = 0; i < scene.lights.size(); ++i) checkLight(scene.lights[i], i, check);
  checkCamera(scene.camera, check);
  check.bounded(scene.ambient, kMaxEmitted, "ambient");
  const Environment& env = scene.environment;
  check.nonNegative(env.color, "environment color");
  check.nonNegative(env.intensity, "environment intensity");
  check.bounded(env.color * env.intensity, kMaxEmitted, "environment color x intensity");
  // World bounds (after instance transforms), once every mesh and transform is finite.
  if (const Aabb box = scene.bounds(); !box.empty()) {
    check.magnitude(box.lo, kMaxCoordinate, "scene bounds (lowest corner)");
    check.magnitude(box.hi, kMaxCoordinate, "scene bounds (highest corner)");
    // Moving instances reach half their motion beyond the frame instant's bounds.
    vec3 reach(0.f);
    for (const Instance& inst : scene.instances)
      reach = glm::max(reach, 0.5f * glm::abs(inst.motion));
    if (reach != vec3(0.f))
      check.magnitude(glm::max(glm::abs(box.lo), glm::abs(box.hi)) + reach, kMaxCoordinate,
                      "scene bounds swept by the motion");
  }
  if (env.type == EnvironmentType::Equirect) {
    if (env.equirect.empty()) check.fail("environment equirect", "image is empty");
    check.finiteArray(env.equirect.pixels, "environment equirect pixels");
  }
  if (env.type == EnvironmentType::Cube) {
    for (int f = 0; f < 6; ++f) {
      const Image& face = env.cubeFaces[f];
      const std::string place = "environment cube[" + std::to_string(f) + "]";
      if (face.empty() || face.width != face.height || face.width != env.cubeFaces[0].width)
        check.fail(place, "cube faces must be square and all the same size");
      check.finiteArray(face.pixels, place + " pixels");
    }
  }
  scene.warnings.insert(scene.warnings.end(), warnings.begin(), warnings.end());
}

}  // namespace diptych
