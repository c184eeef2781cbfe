#include "engine/graph/cpu_image.h"

#include <algorithm>

#include "engine/core/error.h"

namespace diptych {

void CpuImage::fill(const vec4& value) {
  // Encode one texel, then repeat it: default nodes fill whole frames every frame.
  const int channels = formatChannels(desc.format);
  std::uint32_t texel[4];
  for (int c = 0; c < channels; ++c)
    texel[c] = formatIsInteger(desc.format) ? std::uint32_t(value[c])
                                            : std::bit_cast<std::uint32_t>(value[c]);
  for (std::size_t i = 0; i < words.size(); i += std::size_t(channels))
    std::copy(texel, texel + channels, words.begin() + std::ptrdiff_t(i));
}

Image CpuImage::toImage(int layer) const {
  if (formatIsInteger(desc.format)) throw Error("cannot convert an integer CPU image to an image");
  const int channels = formatChannels(desc.format);
  Image img(desc.width, desc.height, channels);
  for (int y = 0; y < desc.height; ++y)
    for (int x = 0; x < desc.width; ++x)
      for (int c = 0; c < channels; ++c) img.at(x, y, c) = f(x, y, c, layer);
  return img;
}

}  // namespace diptych
