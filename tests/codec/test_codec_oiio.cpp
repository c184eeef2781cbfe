// readImage against OpenImageIO's own 8-bit conversion, bit for bit. A test executable of its own
// (diptych_codec_tests): it links OpenImageIO, which the engine loads as a module
// (engine/core/image_codec.h) and the other test executables never load at start.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "engine/core/image.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

std::uint32_t bits(float v) {
  return std::bit_cast<std::uint32_t>(v);
}

std::filesystem::path scratch() {
  const std::filesystem::path dir = ::diptych::testing::scratchDir("diptych_test_codec");
  std::filesystem::create_directories(dir);
  return dir;
}

// Writes an 8-bit image holding every byte value (then random bytes) with OpenImageIO itself.
std::vector<unsigned char> writeBytes(const std::filesystem::path& path, int w, int h, int n) {
  std::vector<unsigned char> bytes(std::size_t(w) * h * n);
  std::mt19937 rng(11);
  for (std::size_t i = 0; i < bytes.size(); ++i)
    bytes[i] = i < 256 ? (unsigned char)(i) : (unsigned char)(rng() & 255u);
  auto out = OIIO::ImageOutput::create(path.string());
  EXPECT_TRUE(out && out->open(path.string(), OIIO::ImageSpec(w, h, n, OIIO::TypeDesc::UINT8)));
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, bytes.data()));
  out->close();
  return bytes;
}

// readImage converts 8-bit images itself: the floats are OpenImageIO's own conversion of the
// bytes it reads (convert_pixel_values, what readImage used before), bit for bit, for 1 to 4
// channels and every byte value, PNG and JPEG.
TEST(SrgbTable, ReadImageOf8BitIsOpenImageIOsConversionBitForBit) {
  const std::pair<const char*, int> files[] = {{"png", 1}, {"png", 2}, {"png", 3},
                                               {"png", 4}, {"jpg", 1}, {"jpg", 3}};
  for (const auto& [ext, n] : files) {
    const std::filesystem::path png =
        scratch() / ("all_bytes_" + std::to_string(n) + "." + std::string(ext));
    const std::vector<unsigned char> bytes = writeBytes(png, 29, 13, n);
    const Image read = readImage(png);
    ASSERT_EQ(read.pixels.size(), bytes.size());
    // The native read (PNG's reader associates alpha in the bytes), then OpenImageIO converts.
    auto in = OIIO::ImageInput::open(png.string());
    ASSERT_TRUE(in);
    std::vector<unsigned char> native(bytes.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, n, OIIO::TypeDesc::UNKNOWN, native.data()));
    if (std::string(ext) == "png") {
      EXPECT_EQ(native == bytes, n % 2 == 1);  // alpha changes
    }
    std::vector<float> oiio(bytes.size());
    ASSERT_TRUE(OIIO::convert_pixel_values(OIIO::TypeDesc::UINT8, native.data(),
                                           OIIO::TypeDesc::FLOAT, oiio.data(), int(oiio.size())));
    for (std::size_t i = 0; i < oiio.size(); ++i)
      ASSERT_EQ(bits(read.pixels[i]), bits(oiio[i])) << png << ", value " << i;
  }
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
