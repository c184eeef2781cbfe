#include "engine/core/image.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/exr_header.h"
#include "engine/core/image_codec.h"
#include "engine/core/input_file.h"
#include "engine/core/png_chunks.h"
#include "engine/core/tonemap.h"

namespace diptych {
namespace {

// The codec's decode (a file, or data in memory), its refusal as an InputError naming `name`.
Image decoded(const std::string& name, const void* data, std::size_t size) {
  Image image;
  std::string error;
  if (!image_codec::codec().read(name, data, size, image, error)) throw InputError(name, "", error);
  return image;
}

std::string lowerExtension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

}  // namespace

Image readImage(const std::filesystem::path& path) {
  const std::uintmax_t size = checkInputFile(path, kMaxBinaryFileBytes);
  {
    std::ifstream file(path, std::ios::binary);
    std::string problem = exrHeaderProblem(file, size);
    if (problem.empty()) {
      file.clear();
      file.seekg(0);
      problem = pngChunkProblem(file, size);
    }
    if (!problem.empty()) throw InputError(path.string(), "", problem);
  }
  return decoded(path.string(), nullptr, 0);
}

Image readImageFromMemory(const std::string& name, const void* data, std::size_t size) {
  std::string problem = exrHeaderProblem(data, size);
  if (problem.empty()) problem = pngChunkProblem(data, size);
  if (!problem.empty()) throw InputError(name, "", problem);
  return decoded(name, data, size);
}

float srgbToLinear(float c) {
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float c) {
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.f / 2.4f) - 0.055f;
}

void writeImage(const std::filesystem::path& path, const Image& image, ToneMap tone) {
  if (image.empty()) throw Error(path.string() + ": refusing to write an empty image");
  const std::string ext = lowerExtension(path);
  const bool linearFormat = ext == ".exr" || ext == ".hdr";
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());

  const image_codec::StoredFormat format = ext == ".exr"  ? image_codec::StoredFormat::Float
                                           : linearFormat ? image_codec::StoredFormat::Half
                                                          : image_codec::StoredFormat::Byte;
  Image encodedImage = image;
  std::vector<float>& encoded = encodedImage.pixels;
  if (!linearFormat && image.channels >= 3) {
    // Colour: the tone map works on RGB triples (Reinhard scales by luminance).
    for (std::size_t p = 0; p < encoded.size(); p += image.channels) {
      const vec3 display = toneMapPixel(vec3(encoded[p], encoded[p + 1], encoded[p + 2]), tone);
      for (int c = 0; c < 3; ++c) encoded[p + c] = linearToSrgb(display[c]);
      for (int c = 3; c < image.channels; ++c)  // alpha stays linear, clamped
        encoded[p + c] = std::isfinite(encoded[p + c]) ? std::clamp(encoded[p + c], 0.f, 1.f) : 0.f;
    }
  } else if (!linearFormat) {
    const float scale = std::exp2(tone.exposure);
    const bool hasAlpha = image.channels == 2;
    for (std::size_t i = 0; i < encoded.size(); ++i) {
      const bool isAlpha = hasAlpha && int(i % image.channels) == image.channels - 1;
      float v = isAlpha ? encoded[i] : encoded[i] * scale;
      v = std::isfinite(v) ? std::clamp(v, 0.f, 1.f) : 0.f;
      encoded[i] = isAlpha ? v : linearToSrgb(v);
    }
  }
  std::string error;
  if (!image_codec::codec().writeEncoded(path.string(), encodedImage, format, error))
    throw Error(path.string() + ": " + error);
}

}  // namespace diptych
