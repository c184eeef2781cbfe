// The 8-bit sRGB decode table (engine/core/srgb_table.h) and the glTF texture decode that uses
// it (engine/scene/gltf/materials.cpp): every float must be the one srgbToLinear gives.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>

#include "engine/core/image.h"
#include "engine/core/srgb_table.h"
#include "engine/scene/load.h"
#include "tests/support/random_image.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

std::uint32_t bits(float v) {
  return std::bit_cast<std::uint32_t>(v);
}

TEST(SrgbTable, EveryEntryIsTheFunctionOfItsByteValue) {
  const float* table = SrgbByteDecoder::instance().dividedTable();
  for (int k = 0; k < 256; ++k) {
    const float divided = float(k) / 255.f, multiplied = float(k) * (1.f / 255.f);
    EXPECT_EQ(bits(table[k]), bits(srgbToLinear(divided))) << k;
    EXPECT_EQ(bits(srgbToLinearFromByteValue(divided)), bits(srgbToLinear(divided))) << k;
    EXPECT_EQ(bits(srgbToLinearFromByteValue(multiplied)), bits(srgbToLinear(multiplied))) << k;
  }
}

// Values that are not 8-bit ones (their neighbours, 16-bit values, out of range, -0, inf, NaN)
// take the direct call and so give the same bits too.
TEST(SrgbTable, OtherValuesGiveTheFunctionsBits) {
  std::vector<float> values = {-0.f,
                               -1.f,
                               1.5f,
                               255.f,
                               std::numeric_limits<float>::infinity(),
                               -std::numeric_limits<float>::infinity(),
                               std::numeric_limits<float>::denorm_min()};
  for (int k = 0; k < 256; ++k) {
    const float v = float(k) / 255.f;
    values.push_back(std::nextafter(v, 2.f));
    values.push_back(std::nextafter(v, -1.f));
  }
  for (int k = 0; k < 65536; k += 7) values.push_back(float(k) * (1.f / 65535.f));
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);
  for (int i = 0; i < 10000; ++i) values.push_back(unit(rng));
  for (float v : values) EXPECT_EQ(bits(srgbToLinearFromByteValue(v)), bits(srgbToLinear(v))) << v;
  EXPECT_TRUE(std::isnan(srgbToLinearFromByteValue(std::numeric_limits<float>::quiet_NaN())));
}

std::filesystem::path scratch() {
  const std::filesystem::path dir = ::diptych::testing::scratchDir("diptych_test_srgb_table");
  std::filesystem::create_directories(dir);
  return dir;
}

using ::diptych::testing::randomImage;

// readImage's 8-bit values are ones the table knows (else the fast path would never be taken).
TEST(SrgbTable, ReadImageGivesByteValuesTheTableKnows) {
  const std::filesystem::path png = scratch() / "bytes.png";
  writeImage(png, randomImage(37, 11, 4, 5));
  const Image read = readImage(png);
  for (float v : read.pixels) {
    const int k = int(std::lround(v * 255.f));
    ASSERT_TRUE(k >= 0 && k <= 255) << v;
    EXPECT_TRUE(bits(v) == bits(float(k) / 255.f) || bits(v) == bits(float(k) * (1.f / 255.f)))
        << v;
  }
}

// A glTF's colour textures (base colour, emissive) decode sRGB; data textures stay as read. The
// loaded floats are the direct decode of readImage's values, bit for bit (RGB and RGBA PNGs).
TEST(SrgbTable, GltfTexturesAreTheDirectDecodeBitForBit) {
  const std::filesystem::path dir = scratch();
  writeImage(dir / "rgba.png", randomImage(67, 33, 4, 7));
  writeImage(dir / "rgb.png", randomImage(40, 24, 3, 8));
  const std::string positions = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA";
  std::ofstream(dir / "textured.gltf") << R"({"asset": {"version": "2.0"},
    "images": [{"uri": "rgba.png"}, {"uri": "rgb.png"}],
    "textures": [{"source": 0}, {"source": 1}],
    "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0},
                                            "metallicRoughnessTexture": {"index": 1}},
                   "emissiveTexture": {"index": 1}, "emissiveFactor": [1, 1, 1]}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" +
                                              positions + R"("}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0,0,0], "max": [1,1,0]}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
    "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}]})";
  const Scene scene = loadScene(dir / "textured.gltf");
  ASSERT_EQ(scene.textures.size(), 3u);  // rgba as colour, rgb as data and as colour
  int colour = 0;
  for (const Texture& t : scene.textures) {
    const Image source = readImage(dir / (t.image.width == 67 ? "rgba.png" : "rgb.png"));
    ASSERT_EQ(t.image.width, source.width);
    ASSERT_EQ(t.image.height, source.height);
    ASSERT_EQ(t.image.channels, 4);
    colour += t.srgbSource ? 1 : 0;
    for (int y = 0; y < source.height; ++y)
      for (int x = 0; x < source.width; ++x)
        for (int c = 0; c < 4; ++c) {
          const float v = c < source.channels ? source.at(x, y, c) : 1.f;
          const float expected = t.srgbSource && c < 3 ? srgbToLinear(v) : v;
          ASSERT_EQ(bits(t.image.at(x, y, c)), bits(expected))
              << t.name << " texel " << x << "," << y << " channel " << c;
        }
  }
  EXPECT_EQ(colour, 2);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
