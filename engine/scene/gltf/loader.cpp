// glTF 2.0 through tinygltf: file loading with our OpenImageIO image decoder, required
// extensions, the node hierarchy (iterative, with explicit cycle and shared-child checks),
// cameras and KHR_lights_punctual.
#include "engine/scene/gltf/tinygltf.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/json_text.h"
#include "engine/scene/gltf/gltf_internal.h"
#include "engine/scene/load.h"

namespace diptych {
namespace {

const std::set<std::string> kSupportedExtensions = {
    "KHR_lights_punctual",      "KHR_materials_transmission",      "KHR_materials_ior",
    "KHR_materials_volume",     "KHR_materials_emissive_strength", "KHR_materials_specular",
    "KHR_materials_iridescence"};

// tinygltf image callback: decode with OpenImageIO, keep the float pixels beside the model.
// A failure is recorded, not raised, so that an unused broken image does not fail the file.
bool decodeImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                 const unsigned char* bytes, int size, void* user) {
  auto& decoded = *static_cast<gltf::DecodedImages*>(user);
  if (index < 0) return true;
  if (std::size_t(index) >= decoded.images.size()) {
    decoded.images.resize(index + 1);
    decoded.errors.resize(index + 1);
  }
  try {
    const std::string name =
        image->uri.empty() ? "images[" + std::to_string(index) + "]" : image->uri;
    decoded.images[index] = readImageFromMemory(name, bytes, std::size_t(std::max(size, 0)));
    image->width = decoded.images[index].width;
    image->height = decoded.images[index].height;
    image->component = decoded.images[index].channels;
  } catch (const Error& e) {
    decoded.errors[index] = e.what();
  }
  return true;
}

// tinygltf reads external buffers and images through these: the same regular-file and size
// checks as every other input (docs/robustness.md), no path expansion, and never a write.
bool fileExists(const std::string& path, void*) {
  std::error_code ec;
  return std::filesystem::exists(path, ec);
}
std::string expandNothing(const std::string& path, void*) {
  return path;
}
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void*) {
  try {
    const std::string bytes = readInputFile(path, kMaxBinaryFileBytes);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const Error& e) {
    if (err) *err += std::string(e.what()) + "\n";
    return false;
  }
}
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err += "writing is disabled\n";
  return false;
}

// tinygltf turns "extras" and "extensions" into Values recursively: refuse deep nesting in the
// JSON (for a .glb, its first chunk) before handing it over.
void checkGltfDepth(const std::string& bytes, bool binary, const std::string& file) {
  if (!binary) return checkJsonDepth(bytes, file);
  if (bytes.size() < 20) return;  // tinygltf reports the short header
  std::uint32_t length = 0;
  for (int i = 0; i < 4; ++i) length |= std::uint32_t(std::uint8_t(bytes[12 + i])) << (8 * i);
  checkJsonDepth(bytes.substr(20, length), file);
}

mat4 localTransform(const tinygltf::Node& node) {
  if (node.matrix.size() == 16) {
    mat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = float(node.matrix[i]);  // column-major
    return m;
  }
  mat4 m(1.f);
  if (node.translation.size() == 3)
    m = glm::translate(m, vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (node.rotation.size() == 4)  // glTF stores (x, y, z, w); glm::quat takes (w, x, y, z)
    m *= glm::mat4_cast(glm::normalize(quat(float(node.rotation[3]), float(node.rotation[0]),
                                            float(node.rotation[1]), float(node.rotation[2]))));
  if (node.scale.size() == 3) m = glm::scale(m, vec3(node.scale[0], node.scale[1], node.scale[2]));
  return m;
}

bool finiteMatrix(const mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

std::string nodeRef(int i) {
  return "nodes[" + std::to_string(i) + "]";
}

// glTF requires nodes to form disjoint strict trees (spec 3.5.3). Checks child indices, that
// no node has two parents, and that following parents never loops; returns each node's parent.
std::vector<int> checkHierarchy(const tinygltf::Model& model, const std::string& file) {
  const int n = int(model.nodes.size());
  std::vector<int> parent(n, -1);
  for (int i = 0; i < n; ++i) {
    for (int child : model.nodes[i].children) {
      if (child < 0 || child >= n)
        throw InputError(file, nodeRef(i) + ".children",
                         "child " + std::to_string(child) + " does not exist");
      if (child == i)
        throw InputError(file, nodeRef(i) + ".children", "node cycle: node is its own child");
      if (parent[child] >= 0)
        throw InputError(file, nodeRef(i) + ".children",
                         "node " + std::to_string(child) + " already has parent " +
                             nodeRef(parent[child]) + " (nodes must form a tree)");
      parent[child] = i;
    }
  }
  // With at most one parent each, a cycle is a parent chain that returns to its start; a chain
  // longer than n nodes must have looped.
  for (int start = 0; start < n; ++start) {
    std::string chain = nodeRef(start);
    int steps = 0;
    for (int p = parent[start]; p >= 0; p = parent[p]) {
      chain = nodeRef(p) + " -> " + chain;
      if (p == start || ++steps > n)
        throw InputError(file, nodeRef(start) + ".children", "node cycle: " + chain);
    }
  }
  return parent;
}

std::vector<int> rootNodes(const tinygltf::Model& model, const std::vector<int>& parent,
                           const std::string& file) {
  int sceneIndex = model.defaultScene;
  if (sceneIndex >= int(model.scenes.size()))
    throw InputError(file, "scene", "scene " + std::to_string(sceneIndex) + " does not exist");
  if (sceneIndex < 0 && !model.scenes.empty()) sceneIndex = 0;
  std::vector<int> roots;
  if (sceneIndex >= 0) {
    for (int node : model.scenes[sceneIndex].nodes) {
      if (node < 0 || node >= int(model.nodes.size()))
        throw InputError(file, "scenes[" + std::to_string(sceneIndex) + "].nodes",
                         "node " + std::to_string(node) + " does not exist");
      roots.push_back(node);
    }
  } else {
    for (int i = 0; i < int(parent.size()); ++i)
      if (parent[i] < 0) roots.push_back(i);
  }
  return roots;
}

// KHR_lights_punctual gives candela (point, spot) and lux (directional); the shading's S_i is the
// radiance a white Lambertian surface facing the light reflects, E / pi (docs/materials.md,
// "Light units"). Point and spot: I [W/sr] = cd / 683 lm/W, the SI luminous efficacy at 555 nm
// that Blender's exporter multiplies by (PBR_WATTS_TO_LUMENS), so S d^2 = cd / (683 pi).
// Directional: Blender's exporter writes the sun's W/m^2 unchanged as "lux" (and reads it back
// so), so lux is taken as W/m^2 and S = lux / pi; an SI-lux sun (1e5 lx) needs --exposure auto.
float photometricToShading(LightType type) {
  constexpr float kPi = 3.14159265358979f;
  constexpr float kLumensPerWatt = 683.f;
  return type == LightType::Directional ? 1.f / kPi : 1.f / (kLumensPerWatt * kPi);
}

void addLight(const tinygltf::Model& model, int lightIndex, const mat4& world,
              const std::string& file, const std::string& place, Scene& scene) {
  if (lightIndex < 0 || lightIndex >= int(model.lights.size()))
    throw InputError(file, place, "light " + std::to_string(lightIndex) + " does not exist");
  const tinygltf::Light& src = model.lights[lightIndex];
  Light light;
  light.name = src.name.empty() ? "lights[" + std::to_string(lightIndex) + "]" : src.name;
  if (src.type == "point") {
    light.type = LightType::Point;
  } else if (src.type == "spot") {
    light.type = LightType::Spot;
    light.innerConeAngle = float(src.spot.innerConeAngle);
    light.outerConeAngle = float(src.spot.outerConeAngle);
  } else if (src.type == "directional") {
    light.type = LightType::Directional;
  } else {
    throw InputError(
        file, "extensions.KHR_lights_punctual.lights[" + std::to_string(lightIndex) + "].type",
        "unknown light type '" + src.type + "'");
  }
  if (src.color.size() >= 3) light.color = vec3(src.color[0], src.color[1], src.color[2]);
  light.intensity = float(src.intensity) * photometricToShading(light.type);
  light.range = float(src.range);
  // Lights sit at the node origin and shine along the node's local -Z.
  light.position = vec3(world * vec4(0.f, 0.f, 0.f, 1.f));
  const vec3 forward = vec3(world * vec4(0.f, 0.f, -1.f, 0.f));
  if (glm::length(forward) > 0.f) light.direction = glm::normalize(forward);
  scene.lights.push_back(light);
}

void setCamera(const tinygltf::Model& model, int cameraIndex, const mat4& world,
               const std::string& file, const std::string& place, Scene& scene) {
  if (cameraIndex < 0 || cameraIndex >= int(model.cameras.size()))
    throw InputError(file, place, "camera " + std::to_string(cameraIndex) + " does not exist");
  const tinygltf::Camera& src = model.cameras[cameraIndex];
  if (src.type != "perspective") {
    scene.warnings.push_back(file + ": cameras[" + std::to_string(cameraIndex) +
                             "]: only perspective cameras are used; ignored");
    return;
  }
  Camera& cam = scene.camera;
  // The camera looks along its node's local -Z with +Y up (spec 3.10.1).
  cam.position = vec3(world * vec4(0.f, 0.f, 0.f, 1.f));
  const vec3 forward = vec3(world * vec4(0.f, 0.f, -1.f, 0.f));
  cam.target = cam.position + (glm::length(forward) > 0.f ? glm::normalize(forward) : forward);
  cam.up = vec3(world * vec4(0.f, 1.f, 0.f, 0.f));
  if (glm::length(cam.up) > 0.f) cam.up = glm::normalize(cam.up);
  cam.verticalFov = float(src.perspective.yfov);
  if (src.perspective.znear > 0) cam.znear = float(src.perspective.znear);
  if (src.perspective.zfar > 0) cam.zfar = float(src.perspective.zfar);
  scene.hasCamera = true;
}

void convertNodes(const tinygltf::Model& model, const std::vector<std::vector<int>>& meshes,
                  const std::string& file, Scene& scene) {
  const std::vector<int> parent = checkHierarchy(model, file);
  struct Pending {
    int node;
    mat4 parentWorld;
  };
  std::vector<Pending> stack;
  for (int root : rootNodes(model, parent, file)) stack.push_back({root, mat4(1.f)});
  std::vector<bool> visited(model.nodes.size(), false);
  while (!stack.empty()) {
    const Pending item = stack.back();
    stack.pop_back();
    const std::string place = nodeRef(item.node);
    if (visited[item.node])
      throw InputError(file, place, "node reached twice from the scene's roots");
    visited[item.node] = true;
    const tinygltf::Node& node = model.nodes[item.node];
    const mat4 local = localTransform(node);
    if (!finiteMatrix(local))
      throw InputError(
          file, place + (node.matrix.size() == 16 ? ".matrix" : ".translation/rotation/scale"),
          "non-finite transform");
    const mat4 world = item.parentWorld * local;
    if (!finiteMatrix(world))
      throw InputError(file, place, "world transform overflows to a non-finite value");
    if (node.mesh >= 0) {
      if (node.mesh >= int(meshes.size()))
        throw InputError(file, place + ".mesh",
                         "mesh " + std::to_string(node.mesh) + " does not exist");
      for (int mesh : meshes[node.mesh])
        scene.instances.push_back({node.name.empty() ? place : node.name, mesh, world});
    }
    if (node.camera >= 0 && !scene.hasCamera)
      setCamera(model, node.camera, world, file, place + ".camera", scene);
    auto lightExt = node.extensions.find("KHR_lights_punctual");
    if (lightExt != node.extensions.end() && lightExt->second.Has("light"))
      addLight(model, lightExt->second.Get("light").GetNumberAsInt(), world, file,
               place + ".extensions.KHR_lights_punctual.light", scene);
    if (node.skin >= 0)
      scene.warnings.push_back(file + ": " + place + ": skin ignored (bind pose rendered)");
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
      stack.push_back({*child, world});
  }
}

}  // namespace

Scene loadGltfUnvalidated(const std::filesystem::path& path) {
  const std::string file = path.string();
  tinygltf::TinyGLTF loader;
  gltf::DecodedImages decoded;
  loader.SetImageLoader(&decodeImage, &decoded);
  loader.SetFsCallbacks({&fileExists, &expandNothing, &readWholeFile, &refuseWrite, nullptr});
  tinygltf::Model model;
  std::string err, warn;
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  const bool binary = ext == ".glb";
  const std::string bytes = readInputFile(path, binary ? kMaxBinaryFileBytes : kMaxJsonFileBytes);
  checkGltfDepth(bytes, binary, file);
  // tinygltf takes 32-bit lengths; both limits are far below 4 GiB.
  const std::string base = path.parent_path().string();
  const bool ok =
      binary ? loader.LoadBinaryFromMemory(&model, &err, &warn,
                                           reinterpret_cast<const unsigned char*>(bytes.data()),
                                           unsigned(bytes.size()), base)
             : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), unsigned(bytes.size()),
                                          base);
  if (!ok) {
    while (!err.empty() && (err.back() == '\n' || err.back() == ' ')) err.pop_back();
    throw InputError(file, "", "glTF parse error (tinygltf): " + (err.empty() ? warn : err));
  }
  decoded.images.resize(model.images.size());
  decoded.errors.resize(model.images.size());

  for (std::size_t i = 0; i < model.extensionsRequired.size(); ++i) {
    if (!kSupportedExtensions.count(model.extensionsRequired[i]))
      throw InputError(file, "extensionsRequired[" + std::to_string(i) + "]",
                       "unsupported required extension " + model.extensionsRequired[i]);
  }
  Scene scene;
  scene.sourcePath = file;
  scene.sourceFiles.push_back(file);
  auto external = [&](const std::string& uri) {  // data: URIs and .glb chunks live in the file
    if (!uri.empty() && uri.rfind("data:", 0) != 0)
      scene.sourceFiles.push_back((path.parent_path() / uri).string());
  };
  for (const tinygltf::Buffer& b : model.buffers) external(b.uri);
  for (const tinygltf::Image& i : model.images) external(i.uri);
  for (const std::string& used : model.extensionsUsed) {
    if (!kSupportedExtensions.count(used))
      scene.warnings.push_back(file + ": extensionsUsed: " + used + " is not supported; ignored");
  }
  gltf::convertMaterials(model, decoded, file, scene);
  const auto meshes = gltf::convertMeshes(model, file, scene);
  convertNodes(model, meshes, file, scene);
  gltf::scaleVolumeThickness(scene);
  return scene;
}

}  // namespace diptych
