// glTF metallic-roughness materials mapped onto the lecture's coefficients. The formulas are
// documented in docs/scene-format.md ("glTF material mapping"); the comments here say why.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "engine/core/error.h"
#include "engine/core/srgb_table.h"
#include "engine/scene/gltf/gltf_internal.h"
#include "engine/scene/gltf_pbr.h"

namespace diptych::gltf {
namespace {

vec3 toVec3(const std::vector<double>& v, vec3 fallback) {
  return v.size() >= 3 ? vec3(float(v[0]), float(v[1]), float(v[2])) : fallback;
}

vec3 valueVec3(const tinygltf::Value& v, vec3 fallback) {
  if (!v.IsArray() || v.ArrayLen() < 3) return fallback;
  vec3 out;
  for (int i = 0; i < 3; ++i) out[i] = float(v.Get(i).GetNumberAsDouble());
  return out;
}

float valueNumber(const tinygltf::Value& object, const char* key, float fallback) {
  if (!object.IsObject() || !object.Has(key) || !object.Get(key).IsNumber()) return fallback;
  return float(object.Get(key).GetNumberAsDouble());
}

// A bound for an error message: "1", "1.5", or "inf" for the largest float.
std::string formatBound(float x) {
  if (x >= std::numeric_limits<float>::max()) return "inf";
  std::string s = std::to_string(x);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

const tinygltf::Value* extension(const tinygltf::Material& m, const char* name) {
  auto it = m.extensions.find(name);
  return it == m.extensions.end() ? nullptr : &it->second;
}

WrapMode wrapMode(int gl) {
  switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
      return WrapMode::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
      return WrapMode::MirroredRepeat;
    default:
      return WrapMode::Repeat;
  }
}

FilterMode filterMode(int gl, FilterMode fallback) {
  switch (gl) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      return FilterMode::Nearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      return FilterMode::Linear;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      return FilterMode::NearestMipmapNearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      return FilterMode::LinearMipmapNearest;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      return FilterMode::NearestMipmapLinear;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
      return FilterMode::LinearMipmapLinear;
    default:
      return fallback;  // -1: sampler leaves it to the implementation
  }
}

// Expands 1-4 channels to RGBA (grey replicated, alpha 1 when absent) and decodes sRGB colour
// channels to linear; alpha is always linear (glTF 3.9.2).
// Rows are independent, so they convert in parallel; 8-bit texels decode through a table
// (SrgbByteDecoder, bit-identical to srgbToLinear).
Image toLinearRgba(const Image& src, bool srgb) {
  Image out(src.width, src.height, 4, 1.f);
  const SrgbByteDecoder& decode = SrgbByteDecoder::instance();
  const int n = src.channels;
  const std::size_t w = std::size_t(src.width);
  tbb::parallel_for(tbb::blocked_range<int>(0, src.height),
                    [&](const tbb::blocked_range<int>& rows) {
                      for (int y = rows.begin(); y < rows.end(); ++y) {
                        const float* in = src.pixels.data() + std::size_t(y) * w * std::size_t(n);
                        float* to = out.pixels.data() + std::size_t(y) * w * 4;
                        for (std::size_t x = 0; x < w; ++x, in += n, to += 4) {
                          const bool grey = n <= 2;
                          const float r = in[0], g = grey ? in[0] : in[1], b = grey ? in[0] : in[2];
                          to[0] = srgb ? decode(r) : r;
                          to[1] = srgb ? decode(g) : g;
                          to[2] = srgb ? decode(b) : b;
                          to[3] = n == 2 ? in[1] : n >= 4 ? in[3] : 1.f;
                        }
                      }
                    });
  return out;
}

class TextureTable {
 public:
  TextureTable(const tinygltf::Model& model, const DecodedImages& decoded, const std::string& file,
               Scene& scene)
      : model_(model), decoded_(decoded), file_(file), scene_(scene) {}

  // Scene texture index for glTF texture `index`, decoded as sRGB colour; `place` names the
  // material slot that uses it, for errors.
  int colorTexture(const tinygltf::TextureInfo& info, const std::string& place) {
    return texture(info.index, info.texCoord, info.extensions, place, true);
  }
  // The same for data textures (metallic-roughness, occlusion, normal): values stay linear.
  template <typename Info>
  int dataTexture(const Info& info, const std::string& place) {
    return texture(info.index, info.texCoord, info.extensions, place, false);
  }

  // The same for a textureInfo held in an extension's JSON (tinygltf leaves those as Values):
  // `key` of `ext`, absent: -1. `place` names `ext`.
  int dataTexture(const tinygltf::Value& ext, const char* key, const std::string& place) {
    if (!ext.IsObject() || !ext.Has(key)) return -1;
    const tinygltf::Value& info = ext.Get(key);
    const std::string at = place + "." + key;
    if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt())
      throw InputError(file_, at + ".index", "a textureInfo needs an integer index");
    const int texCoord = info.Has("texCoord") && info.Get("texCoord").IsInt()
                             ? info.Get("texCoord").GetNumberAsInt()
                             : 0;
    tinygltf::ExtensionMap extensions;
    if (info.Has("extensions") && info.Get("extensions").IsObject())
      for (const std::string& name : info.Get("extensions").Keys())
        extensions[name] = info.Get("extensions").Get(name);
    const int index = info.Get("index").GetNumberAsInt();
    if (index < 0) throw InputError(file_, at + ".index", "texture index is negative");
    return texture(index, texCoord, extensions, at, false);
  }
  const std::string& file() const { return file_; }
  // A recovery made while reading `place` (Scene::warnings: the program prints them).
  void warn(const std::string& place, const std::string& what) {
    scene_.warnings.push_back(file_ + ": " + place + ": " + what);
  }

  int texture(int index, int texCoord, const tinygltf::ExtensionMap& extensions,
              const std::string& place, bool srgb) {
    tinygltf::TextureInfo info;
    info.index = index;
    info.texCoord = texCoord;
    info.extensions = extensions;
    if (info.index < 0) return -1;
    if (info.index >= int(model_.textures.size()))
      throw InputError(file_, place + ".index",
                       "texture " + std::to_string(info.index) + " does not exist");
    if (info.texCoord != 0)
      scene_.warnings.push_back(file_ + ": " + place + ": uses TEXCOORD_" +
                                std::to_string(info.texCoord) + "; only TEXCOORD_0 is read");
    if (info.extensions.count("KHR_texture_transform"))
      scene_.warnings.push_back(file_ + ": " + place + ": KHR_texture_transform ignored");
    // One scene texture per (glTF texture, encoding): an image used both as colour and as data
    // would be decoded twice, differently.
    const int key = 2 * info.index + (srgb ? 1 : 0);
    auto found = made_.find(key);
    if (found != made_.end()) return found->second;

    const tinygltf::Texture& tex = model_.textures[info.index];
    const std::string texPlace = "textures[" + std::to_string(info.index) + "]";
    if (tex.source < 0 || tex.source >= int(model_.images.size()))
      throw InputError(file_, texPlace + ".source",
                       "image " + std::to_string(tex.source) + " does not exist");
    const std::string imagePlace = "images[" + std::to_string(tex.source) + "]";
    const Image& pixels = decoded_.images[tex.source];
    if (pixels.empty()) {
      const std::string& why = decoded_.errors[tex.source];
      const std::string& uri = model_.images[tex.source].uri;
      throw InputError(file_, imagePlace,
                       "image missing or undecodable" + (uri.empty() ? "" : " ('" + uri + "')") +
                           (why.empty() ? "" : ": " + why));
    }
    Texture out;
    out.name = tex.name.empty() ? texPlace : tex.name;
    out.image = toLinearRgba(pixels, srgb);
    out.srgbSource = srgb;
    if (tex.sampler >= 0) {
      if (tex.sampler >= int(model_.samplers.size()))
        throw InputError(file_, texPlace + ".sampler",
                         "sampler " + std::to_string(tex.sampler) + " does not exist");
      const tinygltf::Sampler& s = model_.samplers[tex.sampler];
      out.wrapS = wrapMode(s.wrapS);
      out.wrapT = wrapMode(s.wrapT);
      out.minFilter = filterMode(s.minFilter, out.minFilter);
      out.magFilter = filterMode(s.magFilter, out.magFilter);
    }
    scene_.textures.push_back(std::move(out));
    return made_[key] = int(scene_.textures.size()) - 1;
  }

  // Mean of the green (roughness) and blue (metallic) channels of a metallicRoughnessTexture,
  // or (1, 1) when there is none: the material's constants (the reflection / transmission gates
  // read them); both sides sample the texture per hit for shading (remapsPerTexel).
  vec2 meanRoughnessMetallic(const tinygltf::TextureInfo& info, const std::string& place) {
    if (info.index < 0) return vec2(1.f);
    if (info.index >= int(model_.textures.size()))
      throw InputError(file_, place + ".index",
                       "texture " + std::to_string(info.index) + " does not exist");
    const int source = model_.textures[info.index].source;
    if (source < 0 || source >= int(decoded_.images.size()) || decoded_.images[source].empty())
      throw InputError(file_, place, "image missing or undecodable");
    const Image& img = decoded_.images[source];
    if (img.channels < 3) return vec2(1.f);
    double g = 0.0, b = 0.0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        g += img.at(x, y, 1);
        b += img.at(x, y, 2);
      }
    const double n = double(img.width) * img.height;
    return vec2(float(g / n), float(b / n));
  }

 private:
  const tinygltf::Model& model_;
  const DecodedImages& decoded_;
  const std::string& file_;
  Scene& scene_;
  std::map<int, int> made_;
};

// KHR_materials_iridescence into m. Out-of-range numbers are errors (the schema's bounds: factor
// in [0, 1], IOR >= 1, thicknesses >= 0), not clamped: a film's hue depends on every one of them.
void readIridescence(const tinygltf::Value& ext, const std::string& place, TextureTable& textures,
                     Material& m) {
  const auto number = [&](const char* key, float fallback, float lo, float hi) {
    if (!ext.IsObject() || !ext.Has(key)) return fallback;
    const tinygltf::Value& v = ext.Get(key);
    const double x = v.IsNumber() ? v.GetNumberAsDouble() : std::nan("");
    if (!(x >= lo && x <= hi))
      throw InputError(textures.file(), place + "." + key,
                       "must be a number in [" + formatBound(lo) + ", " + formatBound(hi) + "]");
    return float(x);
  };
  const float inf = std::numeric_limits<float>::max();
  m.iridescenceFactor = number("iridescenceFactor", 0.f, 0.f, 1.f);
  m.iridescenceIor = number("iridescenceIor", 1.3f, 1.f, inf);
  m.iridescenceThicknessMinimum = number("iridescenceThicknessMinimum", 100.f, 0.f, inf);
  m.iridescenceThicknessMaximum = number("iridescenceThicknessMaximum", 400.f, 0.f, inf);
  m.iridescenceTexture = textures.dataTexture(ext, "iridescenceTexture", place);
  m.iridescenceThicknessTexture = textures.dataTexture(ext, "iridescenceThicknessTexture", place);
}

Material convertMaterial(const tinygltf::Material& src, const std::string& place,
                         TextureTable& textures) {
  const tinygltf::PbrMetallicRoughness& pbr = src.pbrMetallicRoughness;
  Material m;
  m.name = src.name.empty() ? place : src.name;
  m.fromGltfPbr = true;
  m.model = ShadingModel::Gltf;

  const vec4 base = pbr.baseColorFactor.size() >= 4
                        ? vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                               float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]))
                        : vec4(1.f);
  const vec2 textured = textures.meanRoughnessMetallic(
      pbr.metallicRoughnessTexture, place + ".pbrMetallicRoughness.metallicRoughnessTexture");
  const float metallic = std::clamp(float(pbr.metallicFactor) * textured.y, 0.f, 1.f);
  const float roughness = std::clamp(float(pbr.roughnessFactor) * textured.x, 0.f, 1.f);

  if (const tinygltf::Value* ext = extension(src, "KHR_materials_ior")) {
    m.ior = valueNumber(*ext, "ior", 1.5f);
    // Checked here, before the F0 formula below divides by ior + 1: a negative value would
    // surface as a non-finite ks, naming the wrong field.
    if (!(m.ior >= 0.f) || !std::isfinite(m.ior))
      throw InputError(textures.file(), place + ".extensions.KHR_materials_ior.ior",
                       "must be positive, or 0 (the extension's infinite IOR)");
    // The extension's schema has a minimum of 1, and 0 as a special case (the specular-glossiness
    // compatibility mode: an infinite IOR, Fresnel 1 at every angle; validate.cpp). Between them
    // the value is used as given (a bubble in water is n < 1 relative to its outside), and said.
    if (m.ior > 0.f && m.ior < 1.f)
      textures.warn(place + ".extensions.KHR_materials_ior.ior",
                    formatBound(m.ior) + " is below the extension's minimum of 1; used as given");
  }
  float transmission = 0.f;
  if (const tinygltf::Value* ext = extension(src, "KHR_materials_transmission"))
    transmission = std::clamp(valueNumber(*ext, "transmissionFactor", 0.f), 0.f, 1.f);
  if (const tinygltf::Value* ext = extension(src, "KHR_materials_volume")) {
    m.thickness = valueNumber(*ext, "thicknessFactor", 0.f);
    m.attenuationColor = valueVec3(ext->Get("attenuationColor"), vec3(1.f));
    m.attenuationDistance = valueNumber(*ext, "attenuationDistance", 0.f);
  }
  if (const tinygltf::Value* ext = extension(src, "KHR_materials_specular")) {
    m.specularWeight = std::clamp(valueNumber(*ext, "specularFactor", 1.f), 0.f, 1.f);
    m.specularTint = glm::max(valueVec3(ext->Get("specularColorFactor"), vec3(1.f)), vec3(0.f));
  }
  if (const tinygltf::Value* ext = extension(src, "KHR_materials_iridescence"))
    readIridescence(*ext, place + ".extensions.KHR_materials_iridescence", textures, m);
  float emissiveStrength = 1.f;
  if (const tinygltf::Value* ext = extension(src, "KHR_materials_emissive_strength"))
    emissiveStrength = valueNumber(*ext, "emissiveStrength", 1.f);

  const LectureCoefficients k =
      gltfPbrToLecture(vec3(base), metallic, roughness, transmission, m.ior);
  m.color = k.color;
  m.ka = 0.f;  // metallic-roughness has no ambient term; A_G is still added by the shading
  m.kd = k.kd;
  m.ks = k.ks;
  m.specularColor = k.specularColor;
  m.exponent = k.exponent;
  m.kps = k.kps;
  m.mirrorColor = k.mirrorColor;
  m.kt = k.kt;
  m.transmitColor = k.transmitColor;
  // The inputs, for per-hit mapping of textured materials (engine/rt/surface_point.cpp).
  m.baseColorFactor = base;
  m.metallicFactor = std::clamp(float(pbr.metallicFactor), 0.f, 1.f);
  m.roughnessFactor = std::clamp(float(pbr.roughnessFactor), 0.f, 1.f);
  m.transmissionFactor = transmission;
  m.metallicRoughnessTexture = textures.dataTexture(
      pbr.metallicRoughnessTexture, place + ".pbrMetallicRoughness.metallicRoughnessTexture");
  m.occlusionTexture = textures.dataTexture(src.occlusionTexture, place + ".occlusionTexture");
  m.occlusionStrength = std::clamp(float(src.occlusionTexture.strength), 0.f, 1.f);
  m.normalTexture = textures.dataTexture(src.normalTexture, place + ".normalTexture");
  m.normalScale = float(src.normalTexture.scale);
  m.emission = toVec3(src.emissiveFactor, vec3(0.f)) * emissiveStrength;
  m.alpha = base.w;
  m.alphaMode = src.alphaMode == "MASK"    ? AlphaMode::Mask
                : src.alphaMode == "BLEND" ? AlphaMode::Blend
                                           : AlphaMode::Opaque;
  m.alphaCutoff = float(src.alphaCutoff);
  m.doubleSided = src.doubleSided;
  m.colorTexture =
      textures.colorTexture(pbr.baseColorTexture, place + ".pbrMetallicRoughness.baseColorTexture");
  m.emissionTexture = textures.colorTexture(src.emissiveTexture, place + ".emissiveTexture");
  if (m.emissionTexture >= 0 && m.emission == vec3(0.f)) m.emissionTexture = -1;
  return m;
}

}  // namespace

void convertMaterials(const tinygltf::Model& model, const DecodedImages& decoded,
                      const std::string& file, Scene& scene) {
  TextureTable textures(model, decoded, file, scene);
  for (std::size_t i = 0; i < model.materials.size(); ++i)
    scene.materials.push_back(
        convertMaterial(model.materials[i], "materials[" + std::to_string(i) + "]", textures));
}

}  // namespace diptych::gltf
