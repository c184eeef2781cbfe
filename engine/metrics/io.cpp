// Reading images for comparison: every metric works on linear values.
#include <OpenImageIO/imageio.h>

#include "engine/core/error.h"
#include "engine/metrics/metrics.h"

namespace diptych {

Image readLinearImage(const std::filesystem::path& path) {
  Image image = readImage(path);  // throws InputError naming the file
  // readImage returns integer formats as stored (display-encoded); ask the file which it was.
  bool encoded = false;
  if (auto in = OIIO::ImageInput::open(path.string())) {
    const OIIO::TypeDesc format = in->spec().format;
    const std::string space = in->spec().get_string_attribute("oiio:ColorSpace");
    // Integer data is display-encoded unless the file says it is linear.
    encoded = !format.is_floating_point() && space != "Linear" && space != "linear";
    in->close();
  }
  if (!encoded) return image;
  const bool hasAlpha = image.channels == 2 || image.channels == 4;
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const bool isAlpha = hasAlpha && int(i % image.channels) == image.channels - 1;
    if (!isAlpha) image.pixels[i] = srgbToLinear(image.pixels[i]);
  }
  return image;
}

}  // namespace diptych
