#include "engine/graph/cpu_image.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
  // In parallel chunks: one thread's stores reach about half this machine's write bandwidth
  // (tests/bench/cpu_bandwidth.sh); chunks are whole texels so each starts at channel 0.
  const std::size_t texels = words.size() / std::size_t(channels);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, texels, 16384),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t t = r.begin(); t < r.end(); ++t)
                        std::copy(texel, texel + channels,
                                  words.begin() + std::ptrdiff_t(t * std::size_t(channels)));
                    });
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
