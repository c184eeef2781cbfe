#include "engine/core/image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/exr_header.h"
#include "engine/core/input_file.h"
#include "engine/core/png_chunks.h"
#include "engine/core/tonemap.h"

namespace diptych {
namespace {

Image readFrom(OIIO::ImageInput* in, const std::string& name) {
  if (!in) throw InputError(name, "", "cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw InputError(name, "", "image has no pixels");
  // A header may claim any size; refuse before allocating (docs/robustness.md).
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide || spec.nchannels > 64 ||
      std::uint64_t(spec.width) * std::uint64_t(spec.height) * std::uint64_t(spec.nchannels) >
          kMaxImageValues)
    throw InputError(name, "",
                     "image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                         "x" + std::to_string(spec.nchannels) + "; the limit is " +
                         std::to_string(kMaxImageSide) + " per side, 64 channels and " +
                         std::to_string(kMaxImageValues) + " values");
  if (spec.deep) throw InputError(name, "", "deep images are not supported");
  // A volume (depth > 1, e.g. a 3D TIFF) would decode depth times the values allocated here.
  if (spec.depth > 1)
    throw InputError(name, "",
                     "image is a volume of depth " + std::to_string(spec.depth) +
                         "; only 2D images are supported");
  Image img(spec.width, spec.height, spec.nchannels);
  bool ok = false;
  if (!spec.channelformats.empty()) {
    // Channels of different formats (EXR): only OpenImageIO's converting read handles them.
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.pixels.data());
  } else if (spec.format == OIIO::TypeDesc::FLOAT) {
    // Already float (HDR, float EXR/TIFF): a native read, for the same 64 MB reason as below.
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UNKNOWN, img.pixels.data());
  } else if (spec.format == OIIO::TypeDesc::UINT8) {
    // 8-bit (PNG, JPEG; most textures): the native bytes through a 256-entry table of
    // k * (1.f / 255), the float OpenImageIO's convert_type<uint8_t, float> (fmath.h) gives for
    // k, so the values are its values, bit for bit; one load per value instead of its
    // convert_to_float (a tenth of loading a textured glTF, perf).
    std::vector<unsigned char> native(spec.image_bytes(true));
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UNKNOWN, native.data());
    if (ok) {
      std::array<float, 256> value;
      for (std::size_t k = 0; k < value.size(); ++k) value[k] = float(k) * (1.f / 255.f);
      for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = value[native[i]];
    }
  } else {
    // Native bytes, then our own conversion: OpenImageIO 2.4's converting read_scanlines
    // allocates a 64 MB chunk whatever the image's size (imageinput.cpp, "around 64 MB"), which
    // was most of the time a small image took to read under ASan (perf, fuzz_image).
    std::vector<std::byte> native(spec.image_bytes(true));
    ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UNKNOWN, native.data()) &&
         OIIO::convert_pixel_values(spec.format, native.data(), OIIO::TypeDesc::FLOAT,
                                    img.pixels.data(), int(img.pixels.size()));
  }
  if (!ok) throw InputError(name, "", "cannot decode image: " + in->geterror());
  in->close();
  return img;
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
  auto in = OIIO::ImageInput::open(path.string());
  return readFrom(in.get(), path.string());
}

Image readImageFromMemory(const std::string& name, const void* data, std::size_t size) {
  std::string problem = exrHeaderProblem(data, size);
  if (problem.empty()) problem = pngChunkProblem(data, size);
  if (!problem.empty()) throw InputError(name, "", problem);
  OIIO::Filesystem::IOMemReader reader(data, size);
  auto in = OIIO::ImageInput::open(name, nullptr, &reader);
  return readFrom(in.get(), name);
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

  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) throw Error(path.string() + ": no image writer for this extension");
  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       linearFormat ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::UINT8);
  if (ext == ".exr") spec.set_format(OIIO::TypeDesc::FLOAT);
  if (!linearFormat) spec.attribute("oiio:ColorSpace", "sRGB");

  std::vector<float> encoded = image.pixels;
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
  if (!out->open(path.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, encoded.data()) ||
      !out->close())
    throw Error(path.string() + ": cannot write image: " + out->geterror());
}

}  // namespace diptych
