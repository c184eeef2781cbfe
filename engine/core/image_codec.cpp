#include "engine/core/image_codec.h"

#include <cstdlib>
#include <mutex>
#include <string>

#include "engine/core/error.h"

#ifndef DIPTYCH_IMAGE_CODEC_STATIC
#include <dlfcn.h>
#endif

namespace diptych::image_codec {

#ifdef DIPTYCH_IMAGE_CODEC_STATIC

const Codec& codec() {
  return *diptychImageCodec();
}

#else

namespace {

// The module's path: DIPTYCH_IMAGE_CODEC, else the one this build made (only this object knows
// the build folder, so every other object stays independent of where the checkout lives).
std::string modulePath() {
  if (const char* path = std::getenv("DIPTYCH_IMAGE_CODEC"); path && *path) return path;
  return DIPTYCH_IMAGE_CODEC_MODULE;
}

const Codec* load(std::string& error) {
  const std::string path = modulePath();
  // RTLD_LOCAL: OpenImageIO's libraries resolve among themselves, not in every later lookup of
  // the process. The handle is kept for the process's life.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* reason = dlerror();
    // dlerror's text names the file.
    error = std::string("cannot load the image codec module: ") +
            (reason ? reason : path + ": unknown reason");
    return nullptr;
  }
  using Entry = const Codec* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(handle, "diptychImageCodec"));
  const Codec* table = entry ? entry() : nullptr;
  if (!table || table->version != kVersion || !table->read || !table->writeEncoded ||
      !table->displayEncoded) {
    error = "the image codec " + path + " is not this build's (rebuild diptych_image_codec)";
    return nullptr;
  }
  return table;
}

}  // namespace

const Codec& codec() {
  static std::once_flag once;
  static const Codec* table = nullptr;
  static std::string error;
  std::call_once(once, [] { table = load(error); });
  if (!table) throw Error(error);
  return *table;
}

#endif

}  // namespace diptych::image_codec
