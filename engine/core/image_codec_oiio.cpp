// The OpenImageIO side of engine/core/image_codec.h, built as the module diptych_image_codec
// (engine/CMakeLists.txt), never into the engine library itself: nothing else in the engine
// includes OpenImageIO. Its messages are readImage's and writeImage's, which add the file name.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/image_codec.h"

namespace diptych::image_codec {
namespace {

// A refusal inside the module, turned into Codec's false and message at its boundary.
struct Failure {
  explicit Failure(std::string text) : message(std::move(text)) {}
  std::string message;
};

Image readFrom(OIIO::ImageInput* in) {
  if (!in) throw Failure("cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    throw Failure("image has no pixels");
  // A header may claim any size; refuse before allocating (docs/robustness.md).
  if (spec.width > kMaxImageSide || spec.height > kMaxImageSide || spec.nchannels > 64 ||
      std::uint64_t(spec.width) * std::uint64_t(spec.height) * std::uint64_t(spec.nchannels) >
          kMaxImageValues)
    throw Failure("image is " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                  "x" + std::to_string(spec.nchannels) + "; the limit is " +
                  std::to_string(kMaxImageSide) + " per side, 64 channels and " +
                  std::to_string(kMaxImageValues) + " values");
  if (spec.deep) throw Failure("deep images are not supported");
  // A volume (depth > 1, e.g. a 3D TIFF) would decode depth times the values allocated here.
  if (spec.depth > 1)
    throw Failure("image is a volume of depth " + std::to_string(spec.depth) +
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
  if (!ok) throw Failure("cannot decode image: " + in->geterror());
  in->close();
  return img;
}

bool read(const std::string& name, const void* data, std::size_t size, Image& out,
          std::string& error) {
  try {
    if (data) {
      // Declared before the input that reads through it, so it outlives it.
      OIIO::Filesystem::IOMemReader reader(data, size);
      auto in = OIIO::ImageInput::open(name, nullptr, &reader);
      out = readFrom(in.get());
    } else {
      auto in = OIIO::ImageInput::open(name);
      out = readFrom(in.get());
    }
    return true;
  } catch (const Failure& f) {
    error = f.message;
    return false;
  }
}

bool writeEncoded(const std::string& path, const Image& encoded, StoredFormat format,
                  std::string& error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "no image writer for this extension";
    return false;
  }
  OIIO::ImageSpec spec(encoded.width, encoded.height, encoded.channels,
                       format == StoredFormat::Float  ? OIIO::TypeDesc::FLOAT
                       : format == StoredFormat::Half ? OIIO::TypeDesc::HALF
                                                      : OIIO::TypeDesc::UINT8);
  if (format == StoredFormat::Byte) spec.attribute("oiio:ColorSpace", "sRGB");
  if (!out->open(path, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, encoded.pixels.data()) ||
      !out->close()) {
    error = "cannot write image: " + out->geterror();
    return false;
  }
  return true;
}

bool displayEncoded(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return false;
  const OIIO::TypeDesc format = in->spec().format;
  const std::string space = in->spec().get_string_attribute("oiio:ColorSpace");
  in->close();
  // Integer data is display-encoded unless the file says it is linear.
  return !format.is_floating_point() && space != "Linear" && space != "linear";
}

const Codec kCodec{kVersion, read, writeEncoded, displayEncoded};

}  // namespace
}  // namespace diptych::image_codec

extern "C" __attribute__((visibility("default"))) const diptych::image_codec::Codec*
diptychImageCodec() {
  return &diptych::image_codec::kCodec;
}
