#include "engine/scene/validate.h"

#include <cmath>

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

class SceneChecker {
 public:
  explicit SceneChecker(const Scene& scene) : file_(scene.sourcePath) {}

  template <typename T>
  void finiteValue(const T& v, const std::string& place) const {
    if (!finite(v)) fail(place, "non-finite value");
  }
  template <typename T>
  void finiteArray(const std::vector<T>& values, const std::string& place) const {
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
  check.nonNegative(m.color, place + " color");
  check.nonNegative(m.ka, place + " ka");
  check.nonNegative(m.kd, place + " kd");
  check.nonNegative(m.ks, place + " ks");
  check.nonNegative(m.exponent, place + " exponent");
  check.nonNegative(m.specularColor, place + " specular_color");
  check.nonNegative(m.kps, place + " kps");
  check.nonNegative(m.mirrorColor, place + " mirror_color");
  check.nonNegative(m.kt, place + " kt");
  check.nonNegative(m.transmitColor, place + " transmit_color");
  check.nonNegative(m.emission, place + " emission");
  check.nonNegative(m.thickness, place + " thickness");
  check.nonNegative(m.attenuationColor, place + " attenuation_color");
  check.nonNegative(m.attenuationDistance, place + " attenuation_distance");
  check.finiteValue(m.ior, place + " ior");
  if (m.ior <= 0.f) check.fail(place + " ior", "must be positive");
  check.finiteValue(m.alpha, place + " alpha");
  check.finiteValue(m.alphaCutoff, place + " alphaCutoff");
  for (int t : {m.colorTexture, m.emissionTexture})
    if (t < -1 || t >= int(scene.textures.size()))
      check.fail(place, "texture " + std::to_string(t) + " does not exist");
  if (m.checker) {
    check.nonNegative(m.checker->colorA, place + " checker.a");
    check.nonNegative(m.checker->colorB, place + " checker.b");
    check.finiteValue(m.checker->scale, place + " checker.scale");
    if (m.checker->scale <= 0.f) check.fail(place + " checker.scale", "must be positive");
  }
}

void checkLight(const Light& l, std::size_t index, const SceneChecker& check) {
  const std::string place = "lights[" + std::to_string(index) + "] '" + l.name + "'";
  check.nonNegative(l.color, place + " color");
  check.nonNegative(l.intensity, place + " intensity");
  check.finiteValue(l.position, place + " position");
  check.finiteValue(l.direction, place + " direction");
  check.nonNegative(l.range, place + " range");
  check.finiteValue(l.edgeU, place + " edge_u");
  check.finiteValue(l.edgeV, place + " edge_v");
  check.nonNegative(l.radius, place + " radius");
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
  check.finiteValue(c.position, "camera position");
  check.finiteValue(c.target, "camera target");
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
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    checkMesh(scene.meshes[i], i, scene, check, warnings);
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    const std::string place = "instances[" + std::to_string(i) + "] '" + inst.name + "'";
    if (inst.mesh < 0 || inst.mesh >= int(scene.meshes.size()))
      check.fail(place + " mesh", "mesh " + std::to_string(inst.mesh) + " does not exist");
    check.finiteValue(inst.transform, place + " transform");
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
  check.nonNegative(scene.ambient, "ambient");
  const Environment& env = scene.environment;
  check.nonNegative(env.color, "environment color");
  check.nonNegative(env.intensity, "environment intensity");
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
