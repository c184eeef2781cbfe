// The JSON scene format, the primitive tessellations, validation, and small hand-written glTF
// files (written to a temp folder here; shared assets are tested in tests/shared_scenes).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "engine/core/error.h"
#include "engine/scene/environment.h"
#include "engine/scene/load.h"
#include "engine/scene/primitives.h"
#include "engine/scene/validate.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

fs::path tempDir() {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_test_scene_json");
  fs::create_directories(dir);
  return dir;
}

fs::path writeFile(const std::string& name, const std::string& text) {
  const fs::path p = tempDir() / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Loads `text` as a scene file and returns the error text ("" if it loaded).
std::string loadError(const std::string& name, const std::string& text) {
  try {
    loadScene(writeFile(name, text));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every triangle's geometric normal agrees with its vertex normals (winding is CCW from the
// side the normals point to), and vertex normals are unit length.
void expectConsistentWinding(const Mesh& m) {
  ASSERT_EQ(m.normals.size(), m.positions.size());
  for (const vec3& n : m.normals) EXPECT_NEAR(glm::length(n), 1.f, 1e-5f);
  for (std::size_t t = 0; t < m.indices.size(); t += 3) {
    const vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
               c = m.positions[m.indices[t + 2]];
    const vec3 g = glm::cross(b - a, c - a);
    if (glm::length(g) < 1e-9f) continue;
    const vec3 avg =
        m.normals[m.indices[t]] + m.normals[m.indices[t + 1]] + m.normals[m.indices[t + 2]];
    EXPECT_GT(glm::dot(g, avg), 0.f) << m.name << " triangle " << t / 3;
  }
}

Aabb boundsOf(const Mesh& m) {
  Aabb box;
  for (const vec3& p : m.positions) box.extend(p);
  return box;
}

TEST(Primitives, TriangleCountsNormalsAndBounds) {
  const Mesh plane = makePlane({4.f, 2.f}, {3, 2});
  EXPECT_EQ(plane.triangleCount(), 12u);
  expectConsistentWinding(plane);
  EXPECT_EQ(boundsOf(plane).lo, vec3(-2.f, 0.f, -1.f));
  EXPECT_EQ(boundsOf(plane).hi, vec3(2.f, 0.f, 1.f));
  EXPECT_EQ(plane.normals[0], vec3(0, 1, 0));

  const Mesh box = makeBox({1.f, 2.f, 3.f});
  EXPECT_EQ(box.triangleCount(), 12u);
  expectConsistentWinding(box);
  EXPECT_EQ(boundsOf(box).hi, vec3(0.5f, 1.f, 1.5f));
  for (std::size_t i = 0; i < box.positions.size(); ++i)  // flat normals point outward
    EXPECT_GT(glm::dot(box.normals[i], box.positions[i]), 0.f);

  const Mesh sphere = makeUvSphere(2.f, 16, 8);
  EXPECT_EQ(sphere.triangleCount(), 2u * 16 * 7);
  expectConsistentWinding(sphere);
  for (std::size_t i = 0; i < sphere.positions.size(); ++i) {
    EXPECT_NEAR(glm::length(sphere.positions[i]), 2.f, 1e-5f);
    EXPECT_NEAR(glm::dot(sphere.normals[i], sphere.positions[i] / 2.f), 1.f, 1e-5f);
  }

  const Mesh disc = makeDisc(1.5f, 12);
  EXPECT_EQ(disc.triangleCount(), 12u);
  expectConsistentWinding(disc);
  EXPECT_NEAR(boundsOf(disc).hi.x, 1.5f, 1e-6f);

  const Mesh cylinder = makeCylinder(1.f, 2.f, 10, true);
  EXPECT_EQ(cylinder.triangleCount(), 40u);
  expectConsistentWinding(cylinder);
  EXPECT_NEAR(boundsOf(cylinder).lo.y, -1.f, 1e-6f);

  const Mesh cone = makeCone(1.f, 2.f, 10, true);
  EXPECT_EQ(cone.triangleCount(), 20u);
  expectConsistentWinding(cone);
  EXPECT_NEAR(boundsOf(cone).hi.y, 1.f, 1e-6f);

  const Mesh quad = makeQuad({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
  EXPECT_EQ(quad.triangleCount(), 2u);
  expectConsistentWinding(quad);
  EXPECT_EQ(quad.normals[0], vec3(0, 0, 1));
}

TEST(SceneJson, FullSceneParsesEveryBlock) {
  const fs::path p = writeFile("full.json", R"({
    "description": "everything",
    "camera": {"position": [0, 1, 5], "target": [0, 1, 0], "up": [0, 1, 0], "fov": 60,
               "aperture": 0.1, "focus_distance": 5},
    "ambient": [0.1, 0.1, 0.1],
    "environment": {"color": [0.2, 0.3, 0.4], "intensity": 2},
    "materials": {
      "red": {"color": [1, 0, 0], "ka": 0.1, "kd": 0.8, "ks": 0.3, "exponent": 50,
              "specular_color": [1, 1, 0.5], "kps": 0.2, "mirror_color": [0.9, 0.9, 0.9],
              "kt": 0.1, "transmit_color": [1, 1, 1], "emission": [0, 0, 0], "ior": 1.33,
              "double_sided": true},
      "check": {"checker": {"a": [1, 0, 0], "b": [1, 1, 0], "scale": 8}}
    },
    "lights": [
      {"type": "point", "position": [0, 5, 0], "intensity": 10, "color": [1, 1, 1]},
      {"type": "directional", "direction": [0, -2, 0], "intensity": 3},
      {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "inner_cone": 10,
       "outer_cone": 30},
      {"type": "quad", "position": [0, 4, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1]},
      {"type": "disc", "position": [0, 4, 0], "normal": [0, -1, 0], "radius": 0.5},
      {"type": "sphere", "position": [2, 4, 0], "radius": 0.25}
    ],
    "objects": [
      {"type": "plane", "size": [10, 10], "segments": 4, "material": "check"},
      {"type": "sphere", "radius": 0.5, "segments": [32, 16], "material": "red",
       "transform": {"translate": [0, 1, 0], "rotate": [0, 90, 0], "scale": 2}},
      {"type": "box", "size": [1, 1, 1], "transform": {"matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 3,0,0,1]}},
      {"type": "disc", "radius": 1},
      {"type": "cylinder", "radius": 0.5, "height": 2, "segments": 8},
      {"type": "cone", "radius": 0.5, "height": 1, "segments": 8, "capped": false},
      {"type": "quad", "corners": [[0,0,0], [1,0,0], [1,1,0], [0,1,0]]},
      {"type": "mesh", "name": "tri+quad", "vertices": [[0,0,0],[1,0,0],[1,1,0],[0,1,0],[2,0,0]],
       "faces": [[0,1,2,3],[1,4,2]]}
    ]
  })");
  const Scene s = loadScene(p);
  EXPECT_TRUE(s.hasCamera);
  EXPECT_NEAR(s.camera.verticalFov, glm::radians(60.f), 1e-6f);
  EXPECT_FLOAT_EQ(s.camera.aperture, 0.1f);
  EXPECT_EQ(s.ambient, vec3(0.1f));
  EXPECT_EQ(s.environment.type, EnvironmentType::Color);
  EXPECT_FLOAT_EQ(s.environment.intensity, 2.f);
  ASSERT_EQ(s.materials.size(), 2u);  // in key order: "check", "red"
  const Material& red = s.materials[1];
  EXPECT_EQ(red.name, "red");
  EXPECT_FLOAT_EQ(red.ks, 0.3f);
  EXPECT_FLOAT_EQ(red.exponent, 50.f);
  EXPECT_FLOAT_EQ(red.ior, 1.33f);
  EXPECT_TRUE(red.doubleSided);
  ASSERT_TRUE(s.materials[0].checker.has_value());
  EXPECT_FLOAT_EQ(s.materials[0].checker->scale, 8.f);
  ASSERT_EQ(s.lights.size(), 6u);
  EXPECT_EQ(s.lights[1].direction, vec3(0, -1, 0));  // normalised
  EXPECT_NEAR(s.lights[2].outerConeAngle, glm::radians(30.f), 1e-6f);
  EXPECT_EQ(s.lights[3].type, LightType::QuadArea);
  EXPECT_EQ(s.lights[3].direction, vec3(0, -1, 0));  // cross(x, z) = -y
  EXPECT_EQ(s.lights[5].type, LightType::SphereArea);
  ASSERT_EQ(s.instances.size(), 8u);
  EXPECT_EQ(s.meshes[s.instances[0].mesh].triangleCount(), 32u);
  EXPECT_EQ(s.meshes[s.instances[0].mesh].material, 0);
  // Sphere: scale 2 then rotate then translate -> world radius 1 around (0, 1, 0).
  const Instance& sphere = s.instances[1];
  for (const vec3& p : s.meshes[sphere.mesh].positions)
    EXPECT_NEAR(glm::length(vec3(sphere.transform * vec4(p, 1.f)) - vec3(0, 1, 0)), 1.f, 1e-5f);
  EXPECT_EQ(vec3(s.instances[2].transform[3]), vec3(3, 0, 0));
  EXPECT_EQ(s.meshes[s.instances[7].mesh].triangleCount(), 3u);  // quad fan (2) + triangle
  EXPECT_EQ(s.meshes[s.instances[1].mesh].material, 1);
  EXPECT_EQ(s.meshes[s.instances[3].mesh].material, -1);  // default material
}

TEST(SceneJson, SceneWithOnlyAnAreaLightAndNoCameraLoads) {
  const Scene s = loadScene(writeFile("area_only.json", R"({
    "lights": [{"type": "quad", "position": [0, 2, 0], "edge_u": [1, 0, 0], "edge_v": [0, 0, 1]}],
    "objects": [{"type": "box"}]})"));
  EXPECT_FALSE(s.hasCamera);  // framed from the bounds
  EXPECT_EQ(s.lights.size(), 1u);
}

struct BrokenCase {
  const char* name;
  const char* json;
  std::vector<const char*> parts;  // substrings the error must contain (besides the file name)
};

TEST(SceneJson, BrokenScenesNameFileAndJsonPath) {
  const std::vector<BrokenCase> cases = {
      {"malformed", R"({"objects": [ {"type": "box" ]})", {"malformed JSON"}},
      {"unknown_top_key", R"({"objcts": []})", {"objcts", "unknown key"}},
      {"unknown_object_key",
       R"({"objects": [{"type": "sphere", "raduis": 1}]})",
       {"objects[0].raduis", "unknown key"}},
      {"unknown_material",
       R"({"materials": {"glass": {}},
         "objects": [{"type": "box"}, {"type": "box"}, {"type": "box", "material": "glas"}]})",
       {"objects[2].material", "unknown material 'glas'"}},
      // nlohmann rejects an overflowing literal while parsing, so only the file is named.
      {"overflow_is_infinite",
       R"({"objects": [{"type": "sphere", "radius": 1e999}]})",
       {"number overflow", "1e999"}},
      {"float_overflow",
       R"({"objects": [{"type": "sphere", "radius": 1e300}]})",
       {"objects[0].radius", "non-finite"}},
      {"negative_radius",
       R"({"objects": [{"type": "box"}, {"type": "sphere", "radius": -1}]})",
       {"objects[1].radius", "positive"}},
      {"missing_include",
       R"({"objects": [{"type": "gltf", "file": "nope.glb"}]})",
       {"objects[0].file", "file not found", "nope.glb"}},
      {"wrong_type_vector", R"({"ambient": "grey"})", {"ambient", "expected an array of 3"}},
      {"wrong_type_number",
       R"({"materials": {"m": {"kd": "one"}}})",
       {"materials.m.kd", "expected a number"}},
      {"wrong_type_bool",
       R"({"materials": {"m": {"double_sided": 1}}})",
       {"materials.m.double_sided", "true or false"}},
      {"bad_fov",
       R"({"camera": {"position": [0,0,5], "target": [0,0,0], "fov": 180}})",
       {"camera.fov", "(0, 180)"}},
      {"unknown_light_type", R"({"lights": [{"type": "laser"}]})", {"lights[0].type", "laser"}},
      {"face_index_out_of_range",
       R"({"objects": [{"type": "mesh", "vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,3]]}]})",
       {"objects[0].faces[0][2]", "out of range"}},
      {"negative_kd", R"({"materials": {"m": {"kd": -0.5}}})", {"materials.m.kd", "negative"}},
      {"top_level_array", R"([1, 2, 3])", {"expected an object"}},
      {"mixed_transform",
       R"({"objects": [{"type": "box", "transform": {"matrix": [1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1], "scale": 2}}]})",
       {"objects[0].transform.matrix", "not both"}},
  };
  for (const BrokenCase& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string file = std::string(c.name) + ".json";
    const std::string error = loadError(file, c.json);
    ASSERT_FALSE(error.empty()) << "loaded, but should have failed";
    EXPECT_NE(error.find(file), std::string::npos) << error;
    for (const char* part : c.parts) EXPECT_NE(error.find(part), std::string::npos) << error;
  }
}

TEST(SceneJson, EverySampleSceneLoads) {
  const fs::path dir = fs::path(DIPTYCH_SAMPLES_DIR) / "scenes";
  int count = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene s = loadScene(entry.path());
    EXPECT_TRUE(s.hasCamera);
    EXPECT_FALSE(s.lights.empty());
    EXPECT_FALSE(s.instances.empty());
    EXPECT_TRUE(s.warnings.empty());
    for (const Mesh& m : s.meshes) {
      if (!m.normals.empty()) expectConsistentWinding(m);
    }
    ++count;
  }
  EXPECT_GE(count, 4);
}

TEST(SceneJson, CornellBlocksFaceOutward) {
  const Scene s = loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "cornell.json");
  int blocks = 0;
  for (const Mesh& m : s.meshes) {
    if (m.name.find("block") == std::string::npos) continue;
    ++blocks;
    vec3 centre(0.f);
    for (const vec3& p : m.positions) centre += p / float(m.positions.size());
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
      const vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                 c = m.positions[m.indices[t + 2]];
      EXPECT_GT(glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.f - centre), 0.f)
          << m.name << " triangle " << t / 3;
    }
  }
  EXPECT_EQ(blocks, 2);
}

TEST(SceneJson, ShadowSphereMatchesTheAnalyticSetup) {
  const Scene s = loadScene(fs::path(DIPTYCH_SAMPLES_DIR) / "scenes" / "shadow-sphere.json");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].position, vec3(0, 10, 0));
  const float H = 10.f, c = 2.f, r = 1.f;
  EXPECT_NEAR(H * r / std::sqrt((H - c) * (H - c) - r * r), 1.25988f, 1e-5f);
}

TEST(Validation, ZeroNormalsAreRecomputedWithAWarning) {
  Scene s;
  s.sourcePath = "memory.json";
  Mesh m = makeQuad({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
  m.name = "objects[0] 'quad'";
  m.normals[2] = vec3(0.f);
  s.meshes.push_back(m);
  s.instances.push_back({"quad", 0, mat4(1.f)});
  validateScene(s);
  EXPECT_EQ(s.meshes[0].normals[2], vec3(0, 0, 1));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("objects[0] 'quad': 1 zero-length normals"), std::string::npos);

  s.meshes[0].positions[1].x = std::nanf("");
  try {
    validateScene(s);
    FAIL() << "NaN accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("memory.json: objects[0] 'quad' positions[1]"),
              std::string::npos)
        << e.what();
  }
}

// Texels and vertex attributes are scanned for Inf and NaN (of either sign) by their exponent
// bits; the largest and smallest finite floats pass, and the first bad element is named.
TEST(Validation, NonFiniteTexelsAndUvsAreNamedByIndex) {
  Scene s;
  s.sourcePath = "memory.json";
  Mesh m = makeQuad({vec3(0, 0, 0), vec3(1, 0, 0), vec3(1, 1, 0), vec3(0, 1, 0)});
  m.name = "objects[0] 'quad'";
  s.meshes.push_back(m);
  s.instances.push_back({"quad", 0, mat4(1.f)});
  Texture t;
  t.name = "tex";
  t.image = Image(8, 8, 4, std::numeric_limits<float>::max());
  t.image.pixels[7] = -std::numeric_limits<float>::max();
  t.image.pixels[9] = std::numeric_limits<float>::denorm_min();
  t.image.pixels[10] = -0.f;
  s.textures.push_back(t);
  validateScene(s);  // all finite

  const auto error = [](Scene scene) -> std::string {
    try {
      validateScene(scene);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const float bad[] = {std::numeric_limits<float>::infinity(),
                       -std::numeric_limits<float>::infinity(), std::nanf(""), -std::nanf("")};
  for (float v : bad) {
    Scene texel = s;
    texel.textures[0].image.pixels[201] = v;
    texel.textures[0].image.pixels[250] = v;
    EXPECT_NE(error(texel).find("textures[0] 'tex' pixels[201]"), std::string::npos)
        << v << ": " << error(texel);
    Scene uv = s;
    uv.meshes[0].uvs[3].y = v;
    EXPECT_NE(error(uv).find("objects[0] 'quad' uvs[3]"), std::string::npos)
        << v << ": " << error(uv);
  }
}

// A one-triangle glTF with the buffer inline as a data URI: positions (3 x vec3 float) then
// three UNSIGNED_SHORT indices (+2 bytes padding). `indexBytes` replaces the index data.
std::string tinyGltf(const std::string& extra, const std::string& indexBase64 = "AAABAAIAAAA=") {
  // Positions (0,0,0) (1,0,0) (0,1,0) as little-endian floats, base64.
  const std::string positions = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
  return R"({"asset": {"version": "2.0"}, )" + extra +
         R"("buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" +
         positions + R"("}, {"byteLength": 8, "uri": "data:application/octet-stream;base64,)" +
         indexBase64 + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 1, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0,0,0], "max": [1,1,0]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    "meshes": [{"name": "tri", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}]})";
}

TEST(SceneGltf, TinyFilesLoadAndFailByName) {
  const std::string nodes = R"("scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"mesh": 0, "translation": [1, 2, 3]}], )";
  const Scene ok = loadScene(writeFile("tri.gltf", tinyGltf(nodes)));
  ASSERT_EQ(ok.meshes.size(), 1u);
  EXPECT_EQ(ok.meshes[0].triangleCount(), 1u);
  EXPECT_EQ(vec3(ok.instances[0].transform[3]), vec3(1, 2, 3));

  // Index 3 (bytes 03 00) in a 3-vertex mesh.
  const std::string outOfRange = loadError("bad_index.gltf", tinyGltf(nodes, "AAABAAMAAAA="));
  EXPECT_NE(outOfRange.find("meshes[0].primitives[0].indices"), std::string::npos) << outOfRange;
  EXPECT_NE(outOfRange.find("out of range"), std::string::npos) << outOfRange;

  const std::string cycle =
      loadError("cycle.gltf", tinyGltf(R"("scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}, {"children": [2]}, {"children": [1]}], )"));
  EXPECT_NE(cycle.find("node cycle: nodes[1] -> nodes[2] -> nodes[1]"), std::string::npos) << cycle;
  const std::string shared =
      loadError("shared_child.gltf", tinyGltf(R"("scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "children": [1]}, {"children": []}, {"children": [1]}], )"));
  EXPECT_NE(shared.find("nodes[2].children: node 1 already has parent nodes[0]"), std::string::npos)
      << shared;

  const std::string required =
      loadError("required.gltf", tinyGltf(nodes + R"("extensionsUsed": ["KHR_materials_sheen"],
        "extensionsRequired": ["KHR_materials_sheen"], )"));
  EXPECT_NE(required.find("unsupported required extension KHR_materials_sheen"), std::string::npos)
      << required;

  // A JSON scene including the glTF with a transform and a material override for everything.
  const Scene included = loadScene(writeFile("include.json", R"({
    "materials": {"paint": {"color": [0, 0, 1]}},
    "objects": [{"type": "gltf", "file": "tri.gltf", "material": "paint",
                 "transform": {"translate": [10, 0, 0]}}]})"));
  ASSERT_EQ(included.instances.size(), 1u);
  EXPECT_EQ(vec3(included.instances[0].transform[3]), vec3(11, 2, 3));
  EXPECT_EQ(included.meshes[0].material, 0);
}

TEST(SceneGltf, IridescenceReadsDefaultsAndRefusesOutOfRangeValues) {
  const std::string nodes = R"("scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "extensionsUsed": ["KHR_materials_iridescence"],
    "extensionsRequired": ["KHR_materials_iridescence"], )";
  const auto withFilm = [&](const std::string& film) {
    return tinyGltf(nodes + R"("materials": [{"extensions": {"KHR_materials_iridescence": )" +
                    film + "}}], ");
  };
  const Scene defaults = loadScene(writeFile("film_defaults.gltf", withFilm("{}")));
  ASSERT_EQ(defaults.materials.size(), 1u);
  const Material& d = defaults.materials[0];
  EXPECT_EQ(d.iridescenceFactor, 0.f);
  EXPECT_FLOAT_EQ(d.iridescenceIor, 1.3f);
  EXPECT_EQ(d.iridescenceThicknessMinimum, 100.f);
  EXPECT_EQ(d.iridescenceThicknessMaximum, 400.f);
  EXPECT_EQ(d.iridescenceTexture, -1);
  EXPECT_EQ(d.iridescenceThicknessTexture, -1);

  const Scene set = loadScene(writeFile("film_set.gltf", withFilm(R"({"iridescenceFactor": 0.5,
    "iridescenceIor": 1.8, "iridescenceThicknessMinimum": 50, "iridescenceThicknessMaximum": 900})")));
  EXPECT_EQ(set.materials[0].iridescenceFactor, 0.5f);
  EXPECT_FLOAT_EQ(set.materials[0].iridescenceIor, 1.8f);
  EXPECT_EQ(set.materials[0].iridescenceThicknessMinimum, 50.f);
  EXPECT_EQ(set.materials[0].iridescenceThicknessMaximum, 900.f);

  const std::string place = "materials[0].extensions.KHR_materials_iridescence.";
  const std::pair<const char*, const char*> bad[] = {
      {R"({"iridescenceFactor": 1.5})", "iridescenceFactor"},
      {R"({"iridescenceIor": 0.5})", "iridescenceIor"},
      {R"({"iridescenceThicknessMinimum": -1})", "iridescenceThicknessMinimum"},
      {R"({"iridescenceThicknessMaximum": "thick"})", "iridescenceThicknessMaximum"},
      {R"({"iridescenceTexture": {"index": 7}})", "iridescenceTexture.index"}};
  for (const auto& [film, key] : bad) {
    const std::string error = loadError("film_bad.gltf", withFilm(film));
    EXPECT_NE(error.find("film_bad.gltf"), std::string::npos) << film << ": " << error;
    EXPECT_NE(error.find(place + key), std::string::npos) << film << ": " << error;
  }
}

TEST(Environment, SolidColourAndEquirectConvention) {
  Environment env;
  env.color = vec3(0.5f);
  env.intensity = 2.f;
  EXPECT_EQ(sampleEnvironment(env, vec3(0, 1, 0)), vec3(1.f));
  // Equirect 4 x 2 whose texels hold their own (x, y): +y is the top row, -x is u = 0 / 1.
  env.type = EnvironmentType::Equirect;
  env.intensity = 1.f;
  env.equirect = Image(4, 2, 3);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 4; ++x) {
      env.equirect.at(x, y, 0) = float(x);
      env.equirect.at(x, y, 1) = float(y);
    }
  EXPECT_NEAR(sampleEnvironment(env, vec3(0, 1, 0)).y, 0.f, 1e-6f);   // top row
  EXPECT_NEAR(sampleEnvironment(env, vec3(0, -1, 0)).y, 1.f, 1e-6f);  // bottom row
  // +x: u = 0.5 -> between texels 1 and 2 -> 1.5.
  EXPECT_NEAR(sampleEnvironment(env, vec3(1, 0, 0)).x, 1.5f, 1e-5f);
  vec2 st;
  EXPECT_EQ(cubeFace(vec3(1, 0, 0), st), 0);
  EXPECT_EQ(cubeFace(vec3(0, -1, 0), st), 3);
  EXPECT_EQ(cubeFace(vec3(0, 0, -1), st), 5);
  EXPECT_EQ(st, vec2(0.5f));
}
}  // namespace DIPTYCH_UNITY_ID
