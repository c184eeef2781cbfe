#include "engine/graph/resource.h"

#include <fmt/format.h>

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

bool formatIsInteger(Format f) {
  return f == Format::R32UI || f == Format::RGBA32UI;
}

std::string describe(const ResourceDesc& d) {
  return fmt::format("{} {}x{}x{}", formatName(d.format), d.width, d.height, d.layers);
}

}  // namespace diptych
