#pragma once
// The engine's one boundary with OpenImageIO. OpenImageIO brings about 260 shared libraries
// (OpenVDB, GDAL, FFmpeg's codecs, DICOM, ...) whose symbol relocations cost a process ~0.2 s of
// CPU at start (docs/benchmarks.md, session 26): most of a `diptych` process start and of every
// unit-test process. So it lives in a module of its own (image_codec_oiio.cpp, built as
// diptych_image_codec.so), loaded with dlopen the first time an image is read or written;
// processes that touch no image file never load it.
// The fuzz harnesses (tests/fuzz) link the module's source in statically instead
// (DIPTYCH_IMAGE_CODEC_STATIC): they instrument OpenImageIO's callers in-process.
#include <cstddef>
#include <string>

#include "engine/core/image.h"

namespace diptych::image_codec {

// The table's layout; the module and the engine must agree (checked at load).
inline constexpr int kVersion = 1;

// Stored formats writeEncoded can write.
enum class StoredFormat { Float, Half, Byte };

struct Codec {
  int version = kVersion;
  // Decodes a file (data == nullptr: `name` is its path) or an in-memory encoding (`name` for
  // messages) into `out`, values as stored (readImage's contract, engine/core/image.h), refusing
  // sizes above kMaxImageSide / kMaxImageValues before allocating. false: `error` holds the
  // message readImage reports after the file's name.
  bool (*read)(const std::string& name, const void* data, std::size_t size, Image& out,
               std::string& error) = nullptr;
  // Writes values already encoded for the format (writeImage's tone mapping and sRGB encoding
  // happen in the engine); Byte files are tagged sRGB. false: `error` holds the reason.
  bool (*writeEncoded)(const std::string& path, const Image& encoded, StoredFormat format,
                       std::string& error) = nullptr;
  // Whether the file's values are display-encoded: integer data not tagged linear. false when
  // the file cannot be opened (readLinearImage has read it first and reported that).
  bool (*displayEncoded)(const std::string& path) = nullptr;
};

// The loaded codec (thread-safe, loaded once). Throws Error naming the module's path and the
// loader's reason when it cannot be loaded (DIPTYCH_IMAGE_CODEC overrides the path).
const Codec& codec();

}  // namespace diptych::image_codec

// The module's one exported symbol.
extern "C" const diptych::image_codec::Codec* diptychImageCodec();
