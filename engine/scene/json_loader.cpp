// The Diptych JSON scene format (docs/scene-format.md): camera, ambient, environment, named
// materials with the lecture's coefficients, lights, and objects (tessellated analytic shapes,
// explicit polygon meshes, included glTF files). Every error names the JSON path.
#include <map>

#include "engine/core/input_file.h"
#include "engine/core/json_text.h"

#include "engine/scene/environment_sky.h"
#include "engine/scene/gltf_pbr.h"
#include "engine/scene/json_reader.h"
#include "engine/scene/json_sdf.h"
#include "engine/scene/load.h"
#include "engine/scene/primitives.h"
#include "engine/scene/validate.h"

namespace diptych {
namespace {

using jsonread::JsonObject;
using jsonread::toNumber;
using jsonread::toVector2;
using jsonread::toVector3;
using nlohmann::json;

// Tessellation beyond this is a typo, not a wish (a 4096 x 4096 sphere is 33M triangles).
constexpr int kMaxSegments = 4096;

struct Context {
  std::string file;
  std::filesystem::path folder;  // relative paths in the file are relative to this
  std::map<std::string, int> materialIndex;
  bool jsonCamera = false;
  // Files read through resolvePath (Scene::sourceFiles); mutable because readers take ctx const.
  mutable std::vector<std::string> files;
};

std::string indexed(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

float positive(JsonObject& o, const std::string& key, float fallback) {
  const float v = o.number(key, fallback);
  if (!(v > 0.f)) o.fail(key, "must be positive (is " + std::to_string(v) + ")");
  return v;
}

int segmentCount(JsonObject& o, const std::string& key, int fallback, int minimum) {
  const int n = o.integer(key).value_or(fallback);
  if (n < minimum || n > kMaxSegments)
    o.fail(key,
           "must be between " + std::to_string(minimum) + " and " + std::to_string(kMaxSegments));
  return n;
}

// "segments": n or [a, b].
ivec2 segmentPair(JsonObject& o, const std::string& key, ivec2 fallback, ivec2 minimum) {
  const json* v = o.find(key);
  if (!v) return fallback;
  ivec2 out;
  if (v->is_number_integer()) {
    out = ivec2(v->get<int>());
  } else if (v->is_array() && v->size() == 2 && (*v)[0].is_number_integer() &&
             (*v)[1].is_number_integer()) {
    out = ivec2((*v)[0].get<int>(), (*v)[1].get<int>());
  } else {
    o.fail(key, "expected an integer or [integer, integer]");
  }
  if (glm::any(glm::lessThan(out, minimum)) || glm::any(glm::greaterThan(out, ivec2(kMaxSegments))))
    o.fail(key,
           "must be between " + std::to_string(minimum.x) + " and " + std::to_string(kMaxSegments));
  // Refused before tessellating: a 4096 x 4096 grid is 33M triangles (validate.h kMaxTriangles).
  if (2 * std::size_t(out.x) * std::size_t(out.y) > kMaxTriangles)
    o.fail(key, "[" + std::to_string(out.x) + ", " + std::to_string(out.y) + "] makes more than " +
                    std::to_string(kMaxTriangles) + " triangles");
  return out;
}

std::filesystem::path resolvePath(const Context& ctx, JsonObject& o, const std::string& key,
                                  const std::string& relative) {
  const std::filesystem::path p = ctx.folder / relative;
  if (!std::filesystem::exists(p)) o.fail(key, "file not found: " + p.string());
  ctx.files.push_back(p.string());
  return p;
}

Image readImageAt(const Context& ctx, JsonObject& o, const std::string& key,
                  const std::string& relative) {
  const std::filesystem::path p = resolvePath(ctx, o, key, relative);
  try {
    return readImage(p);
  } catch (const InputError& e) {
    o.fail(key, e.what());
  }
}

// "transform": {"translate", "rotate" (degrees about x, then y, then z), "scale"} or
// {"matrix": 16 numbers, column-major as in glTF}. M = T * Rz * Ry * Rx * S.
mat4 readTransform(JsonObject& parent, const Context& ctx) {
  auto t = parent.object("transform");
  if (!t) return mat4(1.f);
  mat4 m(1.f);
  if (const json* matrix = t->find("matrix")) {
    if (t->has("translate") || t->has("rotate") || t->has("scale"))
      t->fail("matrix", "give either matrix or translate/rotate/scale, not both");
    if (!matrix->is_array() || matrix->size() != 16)
      t->fail("matrix", "expected 16 numbers (column-major)");
    for (int i = 0; i < 16; ++i)
      m[i / 4][i % 4] = toNumber((*matrix)[i], indexed(t->pathOf("matrix"), i), ctx.file);
  } else {
    m = glm::translate(m, t->vector3("translate", vec3(0.f)));
    const vec3 r = glm::radians(t->vector3("rotate", vec3(0.f)));
    m = glm::rotate(m, r.z, vec3(0, 0, 1));
    m = glm::rotate(m, r.y, vec3(0, 1, 0));
    m = glm::rotate(m, r.x, vec3(1, 0, 0));
    if (const json* s = t->find("scale"))
      m = glm::scale(m, s->is_number() ? vec3(toNumber(*s, t->pathOf("scale"), ctx.file))
                                       : toVector3(*s, t->pathOf("scale"), ctx.file));
  }
  t->rejectUnknownKeys();
  if (glm::determinant(mat3(m)) == 0.f) t->fail("", "transform is singular (zero scale?)");
  return m;
}

// "bump": {"texture": FILE | "amplitude": A, "frequency": [fu, fv], "k", "delta"}: the lecture's
// height field, a greyscale image (first channel, read linear) or the procedural sinusoid.
BumpMap readBump(JsonObject o, const Context& ctx, Scene& scene) {
  BumpMap b;
  if (auto file = o.string("texture")) {
    if (o.has("amplitude") || o.has("frequency"))
      o.fail("texture", "give either a texture or amplitude/frequency, not both");
    Texture t;
    t.name = *file;
    t.image = readImageAt(ctx, o, "texture", *file);
    b.texture = int(scene.textures.size());
    scene.textures.push_back(std::move(t));
  } else {
    b.amplitude = o.number("amplitude", b.amplitude);
    if (const json* f = o.find("frequency"))
      b.frequency = toVector2(*f, o.pathOf("frequency"), ctx.file);
  }
  b.k = o.number("k", b.k);
  b.delta = positive(o, "delta", b.delta);
  if (b.delta > 0.25f) o.fail("delta", "must be at most 0.25 (uv units)");
  o.rejectUnknownKeys();
  return b;
}

// "checker_texture": a checkerboard *image* made here (docs/scene-format.md): `texels` per side
// (power of two or not), `cells` squares per side alternating a and b (linear colours), sampled
// with repeat wrap and trilinear minification like any image texture (mip chain included),
// unlike the procedural `checker`, which is evaluated exactly at each point.
Texture readCheckerTexture(JsonObject c, const std::string& name) {
  const int texels = c.integer("texels").value_or(512);
  const int cells = c.integer("cells").value_or(8);
  if (texels < 1 || texels > 8192) c.fail("texels", "must be between 1 and 8192");
  if (cells < 1 || cells > texels) c.fail("cells", "must be between 1 and texels");
  const vec3 a = c.vector3("a", vec3(1.f)), b = c.vector3("b", vec3(0.f));
  c.rejectUnknownKeys();
  Texture t;
  t.name = name + ".checker_texture";
  t.image = Image(texels, texels, 4, 1.f);
  for (int y = 0; y < texels; ++y) {
    for (int x = 0; x < texels; ++x) {
      const bool odd = ((long(x) * cells / texels) + (long(y) * cells / texels)) % 2 != 0;
      const vec3 col = odd ? b : a;
      for (int k = 0; k < 3; ++k) t.image.at(x, y, k) = col[k];
    }
  }
  return t;
}

Material readMaterial(JsonObject o, const std::string& name, const Context& ctx, Scene& scene) {
  Material m;
  m.name = name;
  m.color = o.vector3("color", m.color);
  m.ka = o.number("ka", m.ka);
  m.kd = o.number("kd", m.kd);
  m.ks = o.number("ks", m.ks);
  m.exponent = o.number("exponent", m.exponent);
  m.specularColor = o.vector3("specular_color", m.specularColor);
  m.kps = o.number("kps", m.kps);
  m.mirrorColor = o.vector3("mirror_color", m.mirrorColor);
  m.kt = o.number("kt", m.kt);
  m.transmitColor = o.vector3("transmit_color", m.transmitColor);
  m.emission = o.vector3("emission", m.emission);
  m.ior = o.number("ior", m.ior);
  // KHR_materials_volume (both models): Beer-Lambert inside; thickness 0 = thin-walled.
  m.thickness = o.number("thickness", m.thickness);
  m.attenuationColor = o.vector3("attenuation_color", m.attenuationColor);
  m.attenuationDistance = o.number("attenuation_distance", m.attenuationDistance);
  m.alpha = o.number("alpha", m.alpha);
  // Default true, unlike glTF's false: a JSON scene shows both sides unless it says otherwise
  // (the flag had no effect before single-sided culling, so no JSON scene changes).
  m.doubleSided = o.boolean("double_sided", true);
  m.castsShadows = o.boolean("casts_shadows", m.castsShadows);
  // The glTF model's inputs (docs/materials.md): "model": "gltf" shades with pbr.glsl.
  if (auto model = o.string("model")) {
    const auto parsed = parseShadingModel(*model);
    if (!parsed) o.fail("model", "expected lecture or gltf, got '" + *model + "'");
    m.model = *parsed;
  }
  m.baseColorFactor = vec4(o.vector3("base_color", vec3(m.baseColorFactor)), m.alpha);
  m.metallicFactor = o.number("metallic", m.metallicFactor);
  m.roughnessFactor = o.number("roughness", m.roughnessFactor);
  m.transmissionFactor = o.number("transmission", m.transmissionFactor);
  for (const char* key : {"metallic", "roughness", "transmission"})
    if (o.has(key) && !(o.number(key, 0.f) >= 0.f && o.number(key, 0.f) <= 1.f))
      o.fail(key, "must be in [0, 1]");
  if (m.model == ShadingModel::Gltf) {
    // As for a glTF file: the lecture coefficients from the glTF mapping, for --shading lecture
    // and for k_ps / k_t, which say whether the reflection / transmission signals exist.
    for (const char* key : {"color", "ka", "kd", "ks", "exponent", "specular_color", "kps",
                            "mirror_color", "kt", "transmit_color"})
      if (o.has(key)) o.fail(key, "is a lecture-model key; this material has \"model\": \"gltf\"");
    const LectureCoefficients k = gltfPbrToLecture(vec3(m.baseColorFactor), m.metallicFactor,
                                                   m.roughnessFactor, m.transmissionFactor, m.ior);
    m.fromGltfPbr = true;  // mapped, as a glTF file's: remapsPerTexel applies
    m.color = k.color, m.kd = k.kd, m.ks = k.ks, m.exponent = k.exponent;
    m.specularColor = k.specularColor, m.kps = k.kps, m.mirrorColor = k.mirrorColor;
    m.kt = k.kt, m.transmitColor = k.transmitColor;
  }
  if (auto bump = o.object("bump")) m.bump = readBump(std::move(*bump), ctx, scene);
  if (auto c = o.object("checker")) {
    Checker checker;
    checker.colorA = c->vector3("a", checker.colorA);
    checker.colorB = c->vector3("b", checker.colorB);
    checker.scale = positive(*c, "scale", checker.scale);
    c->rejectUnknownKeys();
    m.checker = checker;
  }
  if (auto c = o.object("checker_texture")) {
    if (m.checker) o.fail("checker_texture", "give either checker or checker_texture, not both");
    scene.textures.push_back(readCheckerTexture(std::move(*c), name));
    m.colorTexture = int(scene.textures.size()) - 1;
  }
  for (const char* key :
       {"ka", "kd", "ks", "exponent", "kps", "kt", "thickness", "attenuation_distance"})
    if (o.has(key) && o.number(key, 0.f) < 0.f) o.fail(key, "must not be negative");
  if (!(m.ior > 0.f)) o.fail("ior", "must be positive");
  if (m.alpha < 0.f || m.alpha > 1.f) o.fail("alpha", "must be in [0, 1]");
  o.rejectUnknownKeys();
  return m;
}

Light readLight(JsonObject o) {
  Light l;
  const std::string type = o.requiredString("type");
  l.name = o.string("name").value_or(o.path());
  l.color = o.vector3("color", l.color);
  l.intensity = o.number("intensity", l.intensity);
  if (l.intensity < 0.f) o.fail("intensity", "must not be negative");
  l.castsShadows = o.boolean("casts_shadows", true);
  auto direction = [&](const char* key) {
    const vec3 d = o.requiredVector3(key);
    if (glm::length(d) == 0.f) o.fail(key, "must not be the zero vector");
    return glm::normalize(d);
  };
  if (type == "point" || type == "spot") {
    l.type = type == "point" ? LightType::Point : LightType::Spot;
    l.position = o.requiredVector3("position");
    l.range = o.number("range", 0.f);
    if (l.range < 0.f) o.fail("range", "must not be negative");
    if (l.type == LightType::Spot) {
      l.direction = direction("direction");
      l.innerConeAngle = glm::radians(o.number("inner_cone", 0.f));
      l.outerConeAngle = glm::radians(o.number("outer_cone", 45.f));
      if (!(l.outerConeAngle > 0.f && l.outerConeAngle <= glm::radians(90.f)))
        o.fail("outer_cone", "must be in (0, 90] degrees");
      if (l.innerConeAngle < 0.f || l.innerConeAngle > l.outerConeAngle)
        o.fail("inner_cone", "must be in [0, outer_cone] degrees");
    }
  } else if (type == "directional") {
    l.type = LightType::Directional;
    l.direction = direction("direction");
  } else if (type == "quad") {
    l.type = LightType::QuadArea;
    l.position = o.requiredVector3("position");
    l.edgeU = o.requiredVector3("edge_u");
    l.edgeV = o.requiredVector3("edge_v");
    const vec3 n = glm::cross(l.edgeU, l.edgeV);
    if (glm::length(n) == 0.f) o.fail("edge_v", "edge_u and edge_v span no area");
    l.direction = glm::normalize(n);  // emits on the side of cross(edge_u, edge_v)
  } else if (type == "disc") {
    l.type = LightType::DiscArea;
    l.position = o.requiredVector3("position");
    l.direction = direction("normal");
    l.radius = positive(o, "radius", 0.f);
  } else if (type == "sphere") {
    l.type = LightType::SphereArea;
    l.position = o.requiredVector3("position");
    l.radius = positive(o, "radius", 0.f);
  } else {
    o.fail("type",
           "unknown light type '" + type + "' (point, directional, spot, quad, disc, sphere)");
  }
  o.rejectUnknownKeys();
  return l;
}

// "vertices": [[x,y,z], ...], "faces": [[i, j, k, ...], ...] (polygons, fan-triangulated,
// counter-clockwise from the front), optional "normals" and "uvs" per vertex.
Mesh readPolygonMesh(JsonObject& o, const Context& ctx) {
  Mesh mesh;
  auto list = [&](const char* key, bool required) -> const json* {
    const json* v = o.find(key);
    if (!v && required) o.fail(key, "required array is missing");
    if (v && !v->is_array()) o.fail(key, "expected an array");
    return v;
  };
  const json& vertices = *list("vertices", true);
  for (std::size_t i = 0; i < vertices.size(); ++i)
    mesh.positions.push_back(toVector3(vertices[i], indexed(o.pathOf("vertices"), i), ctx.file));
  if (const json* normals = list("normals", false)) {
    for (std::size_t i = 0; i < normals->size(); ++i)
      mesh.normals.push_back(toVector3((*normals)[i], indexed(o.pathOf("normals"), i), ctx.file));
    if (mesh.normals.size() != mesh.positions.size()) o.fail("normals", "needs one per vertex");
  }
  if (const json* uvs = list("uvs", false)) {
    for (std::size_t i = 0; i < uvs->size(); ++i)
      mesh.uvs.push_back(toVector2((*uvs)[i], indexed(o.pathOf("uvs"), i), ctx.file));
    if (mesh.uvs.size() != mesh.positions.size()) o.fail("uvs", "needs one per vertex");
  }
  const json& faces = *list("faces", true);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const std::string place = indexed(o.pathOf("faces"), f);
    if (!faces[f].is_array() || faces[f].size() < 3)
      throw InputError(ctx.file, place, "a face needs at least 3 vertex indices");
    std::vector<std::uint32_t> poly;
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      const json& v = faces[f][k];
      if (!v.is_number_integer())
        throw InputError(ctx.file, indexed(place, k),
                         "expected an integer vertex index, found " + describeJson(v));
      if (v.get<long long>() < 0 || v.get<long long>() >= (long long)mesh.positions.size())
        throw InputError(ctx.file, indexed(place, k),
                         "vertex index " + describeJson(v) + " is out of range (" +
                             std::to_string(mesh.positions.size()) + " vertices)");
      poly.push_back(v.get<std::uint32_t>());
    }
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      mesh.indices.insert(mesh.indices.end(), {poly[0], poly[k], poly[k + 1]});
  }
  return mesh;
}

Mesh readShape(JsonObject& o, const std::string& type, const Context& ctx) {
  const bool quadric = type == "sphere" || type == "disc" || type == "cylinder" || type == "cone";
  if (!quadric && o.has("geometry"))
    o.fail("geometry", "only sphere, disc, cylinder and cone have an analytic form");
  if (type == "plane") {
    const json* size = o.find("size");
    const vec2 extent = size ? toVector2(*size, o.pathOf("size"), ctx.file) : vec2(1.f);
    if (!(extent.x > 0.f && extent.y > 0.f)) o.fail("size", "must be positive");
    return makePlane(extent, segmentPair(o, "segments", ivec2(1), ivec2(1)));
  }
  if (type == "quad") {
    const json* corners = o.find("corners");
    if (!corners || !corners->is_array() || corners->size() != 4)
      o.fail("corners", "expected 4 corner points [[x,y,z], ...]");
    std::array<vec3, 4> p;
    for (int i = 0; i < 4; ++i)
      p[i] = toVector3((*corners)[i], indexed(o.pathOf("corners"), i), ctx.file);
    return makeQuad(p);
  }
  if (type == "box") {
    const vec3 size = o.vector3("size", vec3(1.f));
    if (!(size.x > 0.f && size.y > 0.f && size.z > 0.f)) o.fail("size", "must be positive");
    return makeBox(size);
  }
  if (quadric) {
    AnalyticShape shape;
    shape.radius = positive(o, "radius", 1.f);
    Mesh mesh;
    if (type == "sphere") {
      shape.type = ShapeType::Sphere;
      const ivec2 seg = segmentPair(o, "segments", ivec2(64, 32), ivec2(3, 2));
      mesh = makeUvSphere(shape.radius, seg.x, seg.y);
    } else if (type == "disc") {
      shape.type = ShapeType::Disc;
      mesh = makeDisc(shape.radius, segmentCount(o, "segments", 64, 3));
    } else {
      shape.type = type == "cylinder" ? ShapeType::Cylinder : ShapeType::Cone;
      shape.height = positive(o, "height", 1.f);
      const int slices = segmentCount(o, "segments", 64, 3);
      shape.capped = o.boolean("capped", true);
      mesh = type == "cylinder" ? makeCylinder(shape.radius, shape.height, slices, shape.capped)
                                : makeCone(shape.radius, shape.height, slices, shape.capped);
    }
    // "geometry": "analytic" -> ray tracers intersect the exact shape, rasterizers draw the
    // "segments" tessellation; "tessellated" (the default) -> both use the triangles.
    const std::string geometry = o.string("geometry").value_or("tessellated");
    if (geometry == "analytic")
      mesh.analytic = shape;
    else if (geometry != "tessellated")
      o.fail("geometry", "must be \"analytic\" or \"tessellated\" (is \"" + geometry + "\")");
    return mesh;
  }
  if (type == "mesh") return readPolygonMesh(o, ctx);
  if (type == "sdf") return readSdfObject(o);
  o.fail("type", "unknown object type '" + type +
                     "' (plane, quad, box, sphere, disc, cylinder, cone, mesh, sdf, gltf)");
}

int lookupMaterial(const Context& ctx, JsonObject& o, const std::string& key,
                   const std::string& name) {
  auto it = ctx.materialIndex.find(name);
  if (it == ctx.materialIndex.end()) o.fail(key, "unknown material '" + name + "'");
  return it->second;
}

// Appends an included glTF scene: its materials and textures (re-indexed, or replaced by
// overrides), meshes, instances under `transform`, lights and camera when asked for.
void includeGltf(JsonObject& o, const mat4& transform, const Context& ctx, Scene& scene) {
  const std::string relative = o.requiredString("file");
  const std::filesystem::path path = resolvePath(ctx, o, "file", relative);
  const bool useCamera = o.boolean("use_camera", true);
  const bool useLights = o.boolean("use_lights", true);
  const std::optional<std::string> allMaterial = o.string("material");
  std::map<std::string, int> overrides;
  if (auto table = o.object("material_overrides")) {
    const json& raw = *o.find("material_overrides");
    for (auto it = raw.begin(); it != raw.end(); ++it) {
      const std::string ours = table->requiredString(it.key());
      overrides[it.key()] = lookupMaterial(ctx, *table, it.key(), ours);
    }
  }
  Scene part;
  try {
    part = loadGltfUnvalidated(path);
  } catch (const InputError& e) {
    o.fail("file", e.what());
  }
  for (const auto& [gltfName, ours] : overrides) {
    bool found = false;
    for (const Material& m : part.materials) found = found || m.name == gltfName;
    if (!found)
      o.fail("material_overrides." + gltfName, "'" + relative + "' has no material of that name");
  }
  const int textureBase = int(scene.textures.size());
  const int materialBase = int(scene.materials.size());
  const int meshBase = int(scene.meshes.size());
  for (std::string& f : part.sourceFiles)
    if (f != path.string()) ctx.files.push_back(std::move(f));
  for (Texture& t : part.textures) scene.textures.push_back(std::move(t));
  for (Material m : part.materials) {
    if (m.colorTexture >= 0) m.colorTexture += textureBase;
    if (m.emissionTexture >= 0) m.emissionTexture += textureBase;
    for (int* t : {&m.metallicRoughnessTexture, &m.occlusionTexture, &m.normalTexture,
                   &m.iridescenceTexture, &m.iridescenceThicknessTexture})
      if (*t >= 0) *t += textureBase;
    scene.materials.push_back(std::move(m));
  }
  const int allIndex = allMaterial ? lookupMaterial(ctx, o, "material", *allMaterial) : -2;
  for (Mesh mesh : part.meshes) {
    if (allIndex != -2) {
      mesh.material = allIndex;
    } else if (mesh.material >= 0) {
      auto it = overrides.find(part.materials[mesh.material].name);
      mesh.material = it != overrides.end() ? it->second : mesh.material + materialBase;
    }
    mesh.name = o.path() + " (" + relative + ") " + mesh.name;
    scene.meshes.push_back(std::move(mesh));
  }
  for (Instance inst : part.instances) {
    inst.mesh += meshBase;
    inst.transform = transform * inst.transform;
    scene.instances.push_back(std::move(inst));
  }
  const mat3 linear(transform);
  auto moveDirection = [&](const vec3& d) {
    const vec3 moved = linear * d;
    return glm::length(moved) > 0.f ? glm::normalize(moved) : d;
  };
  if (useLights) {
    for (Light l : part.lights) {
      l.position = vec3(transform * vec4(l.position, 1.f));
      l.direction = moveDirection(l.direction);
      scene.lights.push_back(std::move(l));
    }
  }
  if (useCamera && part.hasCamera && !ctx.jsonCamera && !scene.hasCamera) {
    scene.camera = part.camera;
    scene.camera.position = vec3(transform * vec4(part.camera.position, 1.f));
    scene.camera.target = vec3(transform * vec4(part.camera.target, 1.f));
    scene.camera.up = moveDirection(part.camera.up);
    scene.hasCamera = true;
  }
  scene.warnings.insert(scene.warnings.end(), part.warnings.begin(), part.warnings.end());
}

void readObject(JsonObject o, Context& ctx, Scene& scene) {
  const std::string type = o.requiredString("type");
  const mat4 transform = readTransform(o, ctx);
  // "motion": [dx, dy, dz], the world-space displacement over the shutter (Instance::motion);
  // a glTF file's instances all move by it.
  const vec3 motion = o.vector3("motion", vec3(0.f));
  const std::size_t firstInstance = scene.instances.size();
  if (type == "gltf") {
    includeGltf(o, transform, ctx, scene);
  } else {
    Mesh mesh = readShape(o, type, ctx);
    const std::string name = o.string("name").value_or(type);
    mesh.name = o.path() + " '" + name + "'";
    if (auto material = o.string("material"))
      mesh.material = lookupMaterial(ctx, o, "material", *material);
    scene.meshes.push_back(std::move(mesh));
    scene.instances.push_back({name, int(scene.meshes.size()) - 1, transform});
  }
  for (std::size_t i = firstInstance; i < scene.instances.size(); ++i)
    scene.instances[i].motion = motion;
  o.rejectUnknownKeys();
}

void readCamera(JsonObject o, Scene& scene) {
  Camera& c = scene.camera;
  c.position = o.requiredVector3("position");
  c.target = o.requiredVector3("target");
  c.up = o.vector3("up", c.up);
  const float fov = o.number("fov", 45.f);
  if (!(fov > 0.f && fov < 180.f)) o.fail("fov", "must be in (0, 180) degrees");
  c.verticalFov = glm::radians(fov);
  c.aperture = o.number("aperture", 0.f);
  if (c.aperture < 0.f) o.fail("aperture", "must not be negative");
  c.focusDistance = o.number("focus_distance", glm::length(c.target - c.position));
  if (!(c.focusDistance > 0.f)) o.fail("focus_distance", "must be positive");
  // Without near/far they are fitted to the scene's bounds by loadScene (0 marks "fit").
  const bool given = o.has("near") || o.has("far");
  c.znear = given ? o.number("near", c.znear) : 0.f;
  c.zfar = given ? o.number("far", c.zfar) : 0.f;
  if (given && !(c.znear > 0.f && c.zfar > c.znear)) o.fail("near", "need 0 < near < far");
  if (c.position == c.target) o.fail("target", "equals position");
  if (glm::length(glm::cross(c.target - c.position, c.up)) == 0.f)
    o.fail("up", "is zero or parallel to the viewing direction");
  o.rejectUnknownKeys();
  scene.hasCamera = true;
}

// "sky": the procedural sky of environment_sky.h, baked once at load into an equirect.
void readSky(JsonObject o, Environment& env) {
  SkyParams p;
  p.zenith = o.vector3("zenith", p.zenith);
  p.horizon = o.vector3("horizon", p.horizon);
  p.ground = o.vector3("ground", p.ground);
  p.gradientExponent = o.number("gradient_exponent", p.gradientExponent);
  p.sunDirection = o.vector3("sun_direction", p.sunDirection);
  p.sunColor = o.vector3("sun_color", p.sunColor);
  p.sunRadius = glm::radians(o.number("sun_radius_deg", glm::degrees(p.sunRadius)));
  p.sunRadiance = o.number("sun_radiance", p.sunRadiance);
  p.glow = o.number("glow", p.glow);
  p.glowWidth = glm::radians(o.number("glow_width_deg", glm::degrees(p.glowWidth)));
  p.width = o.integer("width").value_or(p.width);
  for (const auto& [key, v] : {std::pair{"zenith", p.zenith},
                               {"horizon", p.horizon},
                               {"ground", p.ground},
                               {"sun_color", p.sunColor}})
    if (!(glm::all(glm::greaterThanEqual(v, vec3(0.f))) && glm::all(glm::lessThan(v, vec3(1e6f)))))
      o.fail(key, "expected components in [0, 1e6)");
  if (!(glm::length(p.sunDirection) > 0.f)) o.fail("sun_direction", "must not be zero");
  if (!(p.gradientExponent > 0.f && p.gradientExponent <= 100.f))
    o.fail("gradient_exponent", "expected a value in (0, 100]");
  if (!(p.sunRadius >= 0.f && p.sunRadius <= glm::radians(45.f)))
    o.fail("sun_radius_deg", "expected a value in [0, 45]");
  if (!(p.glowWidth > 0.f && p.glowWidth <= glm::pi<float>()))
    o.fail("glow_width_deg", "expected a value in (0, 180]");
  if (!(p.sunRadiance >= 0.f && p.sunRadiance < 1e6f)) o.fail("sun_radiance", "expected [0, 1e6)");
  if (!(p.glow >= 0.f && p.glow < 1e6f)) o.fail("glow", "expected [0, 1e6)");
  if (p.width < 16 || p.width > 8192) o.fail("width", "expected an integer in [16, 8192]");
  o.rejectUnknownKeys();
  const float intensity = env.intensity;
  const vec3 color = env.color;
  env = bakeSky(p);
  env.intensity = intensity;
  env.color = color;
}

void readEnvironment(JsonObject o, const Context& ctx, Scene& scene) {
  Environment& env = scene.environment;
  env.color = o.vector3("color", env.color);
  env.intensity = o.number("intensity", 1.f);
  if (env.intensity < 0.f) o.fail("intensity", "must not be negative");
  const auto equirect = o.string("equirect");
  const json* cube = o.find("cube");
  if (equirect && cube) o.fail("cube", "give either equirect or cube, not both");
  if (auto sky = o.object("sky")) {
    if (equirect || cube) o.fail("sky", "give one of sky, equirect or cube");
    readSky(std::move(*sky), env);
  } else if (equirect) {
    env.type = EnvironmentType::Equirect;
    env.equirect = readImageAt(ctx, o, "equirect", *equirect);
    env.source = (ctx.folder / *equirect).string();
  } else if (cube) {
    if (!cube->is_array() || cube->size() != 6)
      o.fail("cube", "expected 6 image paths in the order +x, -x, +y, -y, +z, -z");
    env.type = EnvironmentType::Cube;
    for (int f = 0; f < 6; ++f) {
      const std::string key = "cube[" + std::to_string(f) + "]";
      if (!(*cube)[f].is_string()) o.fail(key, "expected an image path");
      env.cubeFaces[f] = readImageAt(ctx, o, key, (*cube)[f].get<std::string>());
      const Image& face = env.cubeFaces[f];
      if (face.width != face.height || face.width != env.cubeFaces[0].width)
        o.fail(key, "cube faces must be square and all the same size");
      env.source += (f ? ", " : "") + (ctx.folder / (*cube)[f].get<std::string>()).string();
    }
  }
  o.rejectUnknownKeys();
}

json parseFile(const std::filesystem::path& path) {
  return parseJsonText(readInputFile(path, kMaxJsonFileBytes), path.string());
}

}  // namespace

Scene loadJsonSceneUnvalidated(const std::filesystem::path& path) {
  Context ctx{path.string(), path.parent_path(), {}, false};
  const json document = parseFile(path);
  JsonObject top(document, "", ctx.file);
  Scene scene;
  scene.sourcePath = ctx.file;
  top.string("description");
  scene.ambient = top.vector3("ambient", vec3(0.f));
  if (auto materials = top.object("materials")) {
    const json& raw = *top.find("materials");
    for (auto it = raw.begin(); it != raw.end(); ++it) {
      auto material = materials->object(it.key());
      ctx.materialIndex[it.key()] = int(scene.materials.size());
      scene.materials.push_back(readMaterial(std::move(*material), it.key(), ctx, scene));
    }
  }
  if (auto camera = top.object("camera")) {
    readCamera(std::move(*camera), scene);
    ctx.jsonCamera = true;
  }
  if (auto environment = top.object("environment"))
    readEnvironment(std::move(*environment), ctx, scene);
  auto array = [&](const char* key) -> const json* {
    const json* v = top.find(key);
    if (v && !v->is_array()) top.fail(key, "expected an array");
    return v;
  };
  if (const json* lights = array("lights"))
    for (std::size_t i = 0; i < lights->size(); ++i)
      scene.lights.push_back(readLight(JsonObject((*lights)[i], indexed("lights", i), ctx.file)));
  if (const json* objects = array("objects"))
    for (std::size_t i = 0; i < objects->size(); ++i)
      readObject(JsonObject((*objects)[i], indexed("objects", i), ctx.file), ctx, scene);
  top.rejectUnknownKeys();
  scene.sourceFiles.push_back(ctx.file);
  scene.sourceFiles.insert(scene.sourceFiles.end(), ctx.files.begin(), ctx.files.end());
  return scene;
}

Light parseLightJson(const std::string& text, const std::string& where) {
  json value;
  try {
    value = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(where, "", std::string("malformed JSON: ") + e.what());
  }
  return readLight(JsonObject(value, "light", where));
}

Camera readCameraFile(const std::filesystem::path& path, const glm::dvec3& worldOrigin) {
  const json document = parseFile(path);
  JsonObject top(document, "", path.string());
  auto camera = top.object("camera");
  if (!camera) top.fail("camera", "missing: expected a \"camera\" object as in a JSON scene");
  Scene scene;  // readCamera's checks, unchanged; other keys (a whole scene file) are ignored
  readCamera(std::move(*camera), scene);
  Camera c = scene.camera;
  c.position = vec3(glm::dvec3(c.position) - worldOrigin);
  c.target = vec3(glm::dvec3(c.target) - worldOrigin);
  return c;
}

}  // namespace diptych
