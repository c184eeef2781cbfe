// Reading images for comparison: every metric works on linear values.
#include "engine/core/error.h"
#include "engine/core/image_codec.h"
#include "engine/metrics/metrics.h"

namespace diptych {

Image readLinearImage(const std::filesystem::path& path) {
  Image image = readImage(path);  // throws InputError naming the file
  // readImage returns integer formats as stored (display-encoded); ask the file which it was.
  if (!image_codec::codec().displayEncoded(path.string())) return image;
  const bool hasAlpha = image.channels == 2 || image.channels == 4;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const bool isAlpha = hasAlpha && int(i % image.channels) == image.channels - 1;
    if (!isAlpha) image.pixels[i] = srgbToLinear(image.pixels[i]);
  }
  return image;
}

}  // namespace diptych
