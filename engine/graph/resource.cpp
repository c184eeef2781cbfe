#include "engine/graph/resource.h"

#include <fmt/format.h>

#include <algorithm>

#include "engine/core/error.h"

namespace diptych {

const char* domainName(Domain d) {
  return d == Domain::Gl ? "gl" : "cpu";
}

const char* formatName(Format f) {
  switch (f) {
    case Format::R32F:
      return "R32F";
    case Format::RG32F:
      return "RG32F";
    case Format::RGBA32F:
      return "RGBA32F";
    case Format::R32UI:
      return "R32UI";
    case Format::RGBA32UI:
      return "RGBA32UI";
    case Format::D32F:
      return "D32F";
  }
  return "?";
}

int formatChannels(Format f) {
  switch (f) {
    case Format::RG32F:
      return 2;
    case Format::RGBA32F:
    case Format::RGBA32UI:
      return 4;
    default:
      return 1;
  }
}

bool formatIsInteger(Format f) {
  return f == Format::R32UI || f == Format::RGBA32UI;
}

std::string describe(const ResourceDesc& d) {
  return fmt::format("{} {}x{}x{}", formatName(d.format), d.width, d.height, d.layers);
}

void Surface::fill(const vec4& value) {
  // Encode one texel, then repeat it: default nodes fill whole frames every frame.
  const int channels = formatChannels(desc.format);
  std::uint32_t texel[4];
  for (int c = 0; c < channels; ++c)
    texel[c] = formatIsInteger(desc.format) ? std::uint32_t(value[c])
                                            : std::bit_cast<std::uint32_t>(value[c]);
  for (std::size_t i = 0; i < words.size(); i += std::size_t(channels))
    std::copy(texel, texel + channels, words.begin() + std::ptrdiff_t(i));
}

Image Surface::toImage(int layer) const {
  if (formatIsInteger(desc.format)) throw Error("cannot convert an integer surface to an image");
  const int channels = formatChannels(desc.format);
  Image img(desc.width, desc.height, channels);
  for (int y = 0; y < desc.height; ++y)
    for (int x = 0; x < desc.width; ++x)
      for (int c = 0; c < channels; ++c) img.at(x, y, c) = f(x, y, c, layer);
  return img;
}

}  // namespace diptych
