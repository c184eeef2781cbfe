#pragma once
// A float image with interleaved channels, read and written through OpenImageIO.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/math.h"
#include "engine/core/work_limit.h"

namespace diptych {

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<float> pixels;  // row 0 is the top row of the picture

  Image() = default;
  Image(int w, int h, int c, float fill = 0.f)
      : width(w), height(h), channels(c), pixels(std::size_t(w) * h * c, fill) {}
  bool empty() const { return pixels.empty(); }
  float& at(int x, int y, int c) { return pixels[(std::size_t(y) * width + x) * channels + c]; }
  float at(int x, int y, int c) const {
    return pixels[(std::size_t(y) * width + x) * channels + c];
  }
};

// How a linear image becomes 8-bit display values: multiply by 2^exposure, apply the operator,
// clamp to [0,1], then encode with the sRGB transfer function (IEC 61966-2-1). Operators
// (engine/core/tonemap.h, docs/materials.md): Clamp (none), Reinhard (L / (1 + L) on luminance,
// Reinhard et al. 2002, eq. 3), AcesFit (Narkowicz 2015 fit of the ACES RRT + ODT).
enum class ToneOperator { Clamp, Reinhard, AcesFit };
struct ToneMap {
  float exposure = 0.f;
  ToneOperator op = ToneOperator::Clamp;
};

// Largest image read: 32768 per side and 2^28 values (1 GiB as float).
constexpr int kMaxImageSide = 32768;
constexpr std::uint64_t kMaxImageValues =
    std::uint64_t(double(std::uint64_t(1) << 28) * kImageWorkLimitScale);

// Reads any format OpenImageIO knows (a regular file of at most kMaxBinaryFileBytes). Values are
// returned as stored (8-bit PNG/JPEG -> [0,1], still sRGB-encoded; HDR/EXR -> linear). Throws
// InputError naming the file on failure.
Image readImage(const std::filesystem::path& path);
// Decodes an in-memory encoded image (e.g. a PNG embedded in a .glb). `name` is used in errors.
Image readImageFromMemory(const std::string& name, const void* data, std::size_t size);

// .exr/.hdr are written linear as float/half; .png/.jpg are tone mapped and sRGB-encoded.
// Throws Error naming the file on failure.
void writeImage(const std::filesystem::path& path, const Image& image, ToneMap tone = {});

float srgbToLinear(float encoded);
float linearToSrgb(float linear);

}  // namespace diptych
