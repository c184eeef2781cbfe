#include "samples/diptych/compare/same_image.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "engine/shading/shading.h"

namespace diptych::cli {
namespace {

// Producers that a scene may leave without any difference, and the scene property that does it.
struct SceneHint {
  std::set<std::string> types;  // both passes are of these types
  bool (*applies)(const Scene&);
  const char* text;
};

bool constantEnvironment(const Scene& scene) {
  return scene.environment.type == EnvironmentType::Color;
}

bool atMostOneTransparentMesh(const Scene& scene) {
  std::set<int> meshes;
  for (const Instance& i : scene.instances)
    if (shading::materialHasTransmission(scene.material(scene.meshes[i.mesh].material)))
      meshes.insert(i.mesh);
  return meshes.size() <= 1;
}

// Every colour texture that the scene's instances show has a glTF sampler asking for these
// filters: texture_sampler (each texture's own sampler) then reads as the producer that imposes
// them. At least one colour texture is needed (a scene without one has nothing to filter); a
// checker replaces the colour texture; a material no instance uses shows nothing.
template <FilterMode kMin, FilterMode kMag>
bool colourSamplersAre(const Scene& scene) {
  std::set<int> shown;
  for (const Instance& i : scene.instances) shown.insert(scene.meshes[i.mesh].material);
  int textured = 0;
  for (const int index : shown) {
    const Material& m = scene.material(index);
    if (m.checker || m.colorTexture < 0 || m.colorTexture >= int(scene.textures.size())) continue;
    const Texture& t = scene.textures[std::size_t(m.colorTexture)];
    if (t.minFilter != kMin || t.magFilter != kMag) return false;
    ++textured;
  }
  return textured > 0;
}

const SceneHint kHints[] = {
    {{"env_cube", "env_sphere", "env_equirect"},
     constantEnvironment,
     "the scene's environment is one colour, which every parameterisation stores exactly"},
    {{"sorted_blend", "unsorted_blend"},
     atMostOneTransparentMesh,
     "the scene has at most one transparent mesh, so there is no order to get wrong"},
    {{"texture_sampler", "texture_trilinear"},
     colourSamplersAre<FilterMode::LinearMipmapLinear, FilterMode::Linear>,
     "every colour texture's glTF sampler asks for trilinear filtering"},
    {{"texture_sampler", "texture_bilinear"},
     colourSamplersAre<FilterMode::Linear, FilterMode::Linear>,
     "every colour texture's glTF sampler asks for bilinear filtering without mipmaps"},
    {{"texture_sampler", "texture_nearest"},
     colourSamplersAre<FilterMode::Nearest, FilterMode::Nearest>,
     "every colour texture's glTF sampler asks for nearest filtering without mipmaps"},
};

// "env_sphere" or, for the same type, the parameters that differ: "bias=adaptive".
std::string setting(const nlohmann::json& pass, const nlohmann::json& other) {
  if (pass["type"] != other["type"]) return pass["type"].get<std::string>();
  std::string out;
  for (const auto& [key, value] : pass["params"].items())
    if (!other["params"].contains(key) || other["params"][key] != value)
      out += (out.empty() ? "" : ",") + key + "=" +
             (value.is_string() ? value.get<std::string>() : value.dump());
  return out;
}

}  // namespace

double largestRelativeDifference(const Image& a, const Image& b, double stopAbove) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return kInf;
  double largest = 0.0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i) {
    const double x = a.pixels[i], y = b.pixels[i];
    if (std::isnan(x) || std::isnan(y)) {
      if (std::isnan(x) != std::isnan(y)) return kInf;
      continue;
    }
    if (x == y) continue;  // also equal infinities
    const double scale = std::max({std::abs(x), std::abs(y), 1e-6});
    largest = std::max(largest, std::abs(x - y) / scale);  // inf against a finite value: inf
    if (largest > stopAbove) return largest;
  }
  return largest;
}

std::string sameImageReason(const FrameIdentity& mine, const FrameIdentity& earlier,
                            const Scene& scene) {
  std::string differ, hint;
  for (const auto& [name, p] : mine.passes.items()) {
    if (p["culled"].get<bool>() || !earlier.passes.contains(name)) continue;
    const nlohmann::json& q = earlier.passes[name];
    if (q["culled"].get<bool>() || (q["type"] == p["type"] && q["params"] == p["params"])) continue;
    differ += (differ.empty() ? "" : "; ") + name + ": " + setting(p, q) + ", not " + setting(q, p);
    for (const SceneHint& h : kHints)
      if (hint.empty() && h.types.contains(p["type"].get<std::string>()) &&
          h.types.contains(q["type"].get<std::string>()) && h.applies(scene))
        hint = h.text;
  }
  if (hint.empty()) hint = "this scene does not tell them apart";
  return differ.empty() ? hint : differ + ": " + hint;
}

}  // namespace diptych::cli
