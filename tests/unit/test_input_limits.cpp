// Hostile input (docs/robustness.md): the file checks, the JSON depth limit and bounded value
// descriptions, the FLIP ppd range, the final NaN/Inf check on output images.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/exr_header.h"
#include "engine/core/image.h"
#include "engine/core/image_check.h"
#include "engine/core/input_file.h"
#include "engine/core/json_text.h"
#include "engine/core/png_chunks.h"
#include "engine/metrics/metrics.h"
#include "tests/support/test_paths.h"

namespace fs = std::filesystem;

namespace DIPTYCH_UNITY_ID {
using namespace diptych;

// The message of the InputError `f` throws ("" when it throws nothing).
template <typename F>
std::string errorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string nested(int depth) {
  return std::string(std::size_t(depth), '[') + std::string(std::size_t(depth), ']');
}

TEST(InputFile, ReadsARegularFileAndRefusesEverythingElse) {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_input_file");
  std::ofstream(dir / "ok.json") << "{\"a\": 1}";
  EXPECT_EQ(readInputFile(dir / "ok.json", 100), "{\"a\": 1}");

  EXPECT_NE(errorOf([&] { readInputFile(dir / "ok.json", 4); }).find("the limit is 4"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readInputFile(dir / "missing.json", 100); }).find("file not found"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { readInputFile(dir, 100); }).find("is a directory"), std::string::npos);
  EXPECT_NE(errorOf([&] { readInputFile("/dev/zero", 100); }).find("not a regular file"),
            std::string::npos);
  // A link is judged by its target: a link to /dev/zero is refused, a link to a file is read.
  fs::create_symlink("/dev/zero", dir / "zero.json");
  const std::string viaLink = errorOf([&] { readInputFile(dir / "zero.json", 100); });
  EXPECT_NE(viaLink.find("zero.json"), std::string::npos) << viaLink;
  EXPECT_NE(viaLink.find("not a regular file"), std::string::npos) << viaLink;
  fs::create_symlink(dir / "ok.json", dir / "link.json");
  EXPECT_EQ(readInputFile(dir / "link.json", 100), "{\"a\": 1}");
  // A FIFO would block the open() itself. (The scratch folder starts empty, so no earlier
  // run's FIFO or links are there: scratchDir.)
  ASSERT_EQ(mkfifo((dir / "fifo").c_str(), 0600), 0);
  EXPECT_NE(errorOf([&] { readInputFile(dir / "fifo", 100); }).find("not a regular file"),
            std::string::npos);
}

TEST(JsonText, DepthIsLimitedAtParseTimeAndStringsDoNotCount) {
  EXPECT_NO_THROW(parseJsonText(nested(kMaxJsonDepth), "f.json"));
  const std::string deep = errorOf([] { parseJsonText(nested(kMaxJsonDepth + 1), "f.json"); });
  EXPECT_NE(deep.find("f.json: byte 256: JSON nested deeper than 256"), std::string::npos) << deep;
  EXPECT_NO_THROW(parseJsonText("{\"a\": \"" + std::string(1000, '[') + "\\\"\"}", "f.json"));
  EXPECT_NE(errorOf([] { parseJsonText("{\"a\": ", "f.json"); }).find("malformed JSON"),
            std::string::npos);
}

TEST(JsonText, DescriptionsAreShortAndNeverRecurse) {
  // nlohmann's parser itself is iterative; dump() of this value would overflow the stack.
  const nlohmann::json deep = nlohmann::json::parse(nested(100000));
  EXPECT_EQ(describeJson(deep), "an array of 1 elements");
  EXPECT_EQ(describeJson(nlohmann::json::object({{"a", 1}, {"b", 2}})), "an object of 2 keys");
  EXPECT_EQ(describeJson(nlohmann::json(-3)), "-3");
  EXPECT_EQ(describeJson(nlohmann::json("short")), "\"short\"");
  const std::string longText = describeJson(nlohmann::json(std::string(100000, 'a')));
  EXPECT_LT(longText.size(), 80u);
  EXPECT_NE(longText.find("(100000 bytes)"), std::string::npos);
  // Cutting inside a UTF-8 sequence must not throw (dump() would, on invalid UTF-8).
  std::string euros;
  for (int i = 0; i < 30; ++i) euros += "\xE2\x82\xAC";
  EXPECT_NO_THROW(describeJson(nlohmann::json(euros)));
}

TEST(FlipPixelsPerDegree, OutsideTheDocumentedRangeIsAnInputError) {
  Image a(8, 8, 3, 0.25f), b(8, 8, 3, 0.5f);
  MetricOptions options;
  options.metrics = {"flip"};
  for (double ppd : {0.0, 0.5, 1001.0, 1e9, 1e12, std::numeric_limits<double>::quiet_NaN()}) {
    options.flipPixelsPerDegree = ppd;
    EXPECT_NE(errorOf([&] { computeMetrics(a, b, options); }).find("pixels per degree"),
              std::string::npos)
        << ppd;
  }
  for (double ppd : {kMinFlipPpd, 67.0, kMaxFlipPpd}) {
    options.flipPixelsPerDegree = ppd;
    const double mean = computeMetrics(a, b, options).at("flip_mean");
    EXPECT_TRUE(mean > 0 && mean <= 1) << ppd << ": " << mean;
  }
}

TEST(ImageCheck, CountsNaNAndInfAndNamesTheFirstPixel) {
  Image img(4, 3, 3, 0.5f);
  EXPECT_EQ(findNonFinite(img).count, 0u);
  EXPECT_NO_THROW(requireFinite(img, "out"));
  img.at(2, 1, 1) = std::numeric_limits<float>::quiet_NaN();
  img.at(3, 2, 0) = std::numeric_limits<float>::infinity();
  const NonFiniteValues bad = findNonFinite(img);
  EXPECT_EQ(bad.count, 2u);
  EXPECT_EQ(bad.x, 2);
  EXPECT_EQ(bad.y, 1);
  try {
    requireFinite(img, "render: output 'shade.color'");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'shade.color': 2 NaN/Inf values (first at pixel 2, 1)"),
              std::string::npos)
        << e.what();
  }
}

// An EXR attribute declaring more bytes than the file holds is refused before OpenEXR allocates
// it (fuzz_image's finding: a 588-byte file made OpenEXR allocate gigabytes). A valid EXR passes
// the same check and reads; data that is not EXR is left to its reader.
TEST(ExrHeader, AnAttributeLargerThanTheFileIsRefusedBeforeOpening) {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_exr_header");
  fs::create_directories(dir);
  const fs::path good = dir / "good.exr";
  Image image(4, 3, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i) * 0.1f;
  writeImage(good, image);
  EXPECT_EQ(readImage(good).pixels, image.pixels);

  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  EXPECT_EQ(exrHeaderProblem(bytes.data(), bytes.size()), "");
  // "channels\0chlist\0" is followed by the attribute's int32 size: make it 2^31 - 1.
  const std::size_t at = bytes.find(std::string("channels\0chlist\0", 16));
  ASSERT_NE(at, std::string::npos);
  const std::size_t sizeAt = at + 16;
  for (int b = 0; b < 4; ++b) bytes[sizeAt + b] = char(b == 3 ? 0x7f : 0xff);
  const fs::path bad = dir / "bad.exr";
  std::ofstream(bad, std::ios::binary) << bytes;
  const std::string message = errorOf([&] { readImage(bad); });
  EXPECT_NE(message.find("bad.exr"), std::string::npos) << message;
  EXPECT_NE(message.find("attribute 'channels' (chlist) at byte " + std::to_string(at)),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("declares 2147483647 bytes"), std::string::npos) << message;
  EXPECT_NE(errorOf([&] { readImageFromMemory("mem.exr", bytes.data(), bytes.size()); }), "");

  // Truncated inside the header, and a negative size.
  EXPECT_NE(exrHeaderProblem(bytes.data(), at + 5).find("unterminated"), std::string::npos);
  for (int b = 0; b < 4; ++b) bytes[sizeAt + b] = char(0xff);
  EXPECT_NE(exrHeaderProblem(bytes.data(), bytes.size()).find("declares -1 bytes"),
            std::string::npos);
  // Not EXR: nothing to say.
  const std::string png = "\x89PNG\r\n\x1a\n";
  EXPECT_EQ(exrHeaderProblem(png.data(), png.size()), "");

  // The fuzz finding itself (its first byte is the harness's extension selector).
  std::ifstream in(
      fs::path(DIPTYCH_TESTS_DIR) / "fuzz/regressions/image/exr-opaque-attribute-timeout",
      std::ios::binary);
  std::string found(std::istreambuf_iterator<char>(in), {});
  ASSERT_GT(found.size(), 1u);
  EXPECT_NE(exrHeaderProblem(found.data() + 1, found.size() - 1), "");
}

// A PNG cut anywhere after its signature is refused with a named error before OpenImageIO reads
// it (its read callback leaks a string on every short read; the ASan suite reports that leak if
// the check is gone), a PNG whose chunk declares more than 2^31 - 1 bytes likewise, and a whole
// PNG passes the check and reads.
TEST(PngChunks, ATruncatedPngIsRefusedBeforeOpeningAndAWholeOneReads) {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_png_chunks");
  fs::create_directories(dir);
  const fs::path good = dir / "good.png";
  Image image(5, 4, 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float(i % 7) / 6.f;
  writeImage(good, image);
  EXPECT_EQ(readImage(good).width, 5);

  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_GT(bytes.size(), 8u + 25u + 12u);  // signature, IHDR, IEND at least
  EXPECT_EQ(pngChunkProblem(bytes.data(), bytes.size()), "");
  for (std::size_t cut = 8; cut < bytes.size(); ++cut) {
    const std::string problem = pngChunkProblem(bytes.data(), cut);
    EXPECT_NE(problem.find("PNG is truncated"), std::string::npos) << "cut at " << cut;
  }
  // Cut inside IHDR's data: the message names the chunk, its offset and what is missing.
  EXPECT_EQ(pngChunkProblem(bytes.data(), 20),
            "PNG is truncated: chunk 'IHDR' at byte 8 needs 25 bytes, the file has 12 left");
  const fs::path cut = dir / "cut.png";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const std::string message = errorOf([&] { readImage(cut); });
  EXPECT_NE(message.find("cut.png"), std::string::npos) << message;
  EXPECT_NE(message.find("PNG is truncated"), std::string::npos) << message;
  EXPECT_NE(errorOf([&] { readImageFromMemory("mem.png", bytes.data(), bytes.size() / 2); }), "");

  // IHDR's length field made 0x80000000.
  std::string huge = bytes;
  huge[8] = char(0x80);
  EXPECT_EQ(
      pngChunkProblem(huge.data(), huge.size()),
      "PNG chunk 'IHDR' at byte 8 declares 2147483661 bytes, more than the format's 2^31 - 1");
  // Not PNG: nothing to say.
  const std::string exr = "\x76\x2f\x31\x01";
  EXPECT_EQ(pngChunkProblem(exr.data(), exr.size()), "");
}

// A volume image (depth > 1: a DDS volume texture here) is refused with a named error before
// decoding: its depth x width x height values used to be decoded into a width x height buffer.
TEST(ImageRead, AVolumeImageIsRefusedBeforeDecoding) {
  const fs::path dir = ::diptych::testing::scratchDir("diptych_volume_image");
  fs::create_directories(dir);
  const fs::path path = dir / "volume.dds";
  const std::uint32_t w = 4, h = 3, d = 5;
  // DDS header (Microsoft's DDS_HEADER): CAPS|HEIGHT|WIDTH|PIXELFORMAT|DEPTH, an uncompressed
  // 32-bit RGBA pixel format, caps TEXTURE|COMPLEX, caps2 VOLUME; then w*h*d texels.
  std::vector<std::uint32_t> header = {124, 0x1 | 0x2 | 0x4 | 0x1000 | 0x800000, h, w, w * 4, d, 0};
  header.resize(7 + 11, 0);  // reserved
  for (std::uint32_t v : {32u, 0x41u, 0u, 32u, 0xff0000u, 0xff00u, 0xffu, 0xff000000u})
    header.push_back(v);
  for (std::uint32_t v : {0x1008u, 0x200000u, 0u, 0u, 0u}) header.push_back(v);
  {
    std::ofstream out(path, std::ios::binary);
    out.write("DDS ", 4);
    out.write(reinterpret_cast<const char*>(header.data()),
              std::streamsize(header.size() * sizeof(std::uint32_t)));
    const std::vector<char> texels(std::size_t(w * h * d * 4), char(0x40));
    out.write(texels.data(), std::streamsize(texels.size()));
  }
  const std::string message = errorOf([&] { readImage(path); });
  EXPECT_NE(message.find("volume.dds"), std::string::npos) << message;
  EXPECT_NE(message.find("volume of depth 5"), std::string::npos) << message;
}
}  // namespace DIPTYCH_UNITY_ID
