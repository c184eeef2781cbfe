#pragma once
// Decoding the G-buffer hits texel shared by every pass that reads gbuffer.hits:
// RGBA32UI = (instance + 1, primitive, floatBits(u), floatBits(v)); x == 0 is background.
#include <bit>
#include <optional>

#include "engine/graph/cpu_image.h"
#include "engine/rt/surface_point.h"

namespace diptych {

inline std::optional<SurfaceHit> hitsTexel(const CpuImage& hits, int x, int y) {
  const std::uint32_t id = hits.u(x, y, 0);
  if (id == 0) return std::nullopt;
  return SurfaceHit{int(id - 1), hits.u(x, y, 1), std::bit_cast<float>(hits.u(x, y, 2)),
                    std::bit_cast<float>(hits.u(x, y, 3))};
}

}  // namespace diptych
