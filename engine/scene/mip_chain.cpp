#include "engine/scene/mip_chain.h"

#include <algorithm>
#include <cmath>

namespace diptych {
namespace {

// Weights of source texels [first, first + weights.size()) in destination texel j along one
// axis: the overlap of each source texel with [j * ratio, (j + 1) * ratio), divided by ratio.
struct Taps {
  int first = 0;
  std::vector<double> weights;
};

std::vector<Taps> axisTaps(int source, int dest) {
  std::vector<Taps> taps(static_cast<std::size_t>(dest));
  const double ratio = double(source) / double(dest);
  for (int j = 0; j < dest; ++j) {
    const double lo = j * ratio, hi = (j + 1) * ratio;
    Taps& t = taps[std::size_t(j)];
    t.first = int(std::floor(lo));
    for (int s = t.first; s < source && double(s) < hi; ++s) {
      const double overlap = std::min(hi, double(s + 1)) - std::max(lo, double(s));
      if (overlap > 0.0)
        t.weights.push_back(overlap / ratio);
      else if (t.weights.empty())
        ++t.first;  // touches only at its edge
    }
  }
  return taps;
}

}  // namespace

Image downsampleBox(const Image& level) {
  if (level.empty()) return {};
  const int w = std::max(1, level.width / 2), h = std::max(1, level.height / 2);
  const std::vector<Taps> tx = axisTaps(level.width, w), ty = axisTaps(level.height, h);
  Image out(w, h, level.channels);
  std::vector<double> sum(std::size_t(level.channels));
  for (int y = 0; y < h; ++y) {
    const Taps& ry = ty[std::size_t(y)];
    for (int x = 0; x < w; ++x) {
      const Taps& rx = tx[std::size_t(x)];
      std::fill(sum.begin(), sum.end(), 0.0);
      for (std::size_t b = 0; b < ry.weights.size(); ++b) {
        for (std::size_t a = 0; a < rx.weights.size(); ++a) {
          const double wgt = ry.weights[b] * rx.weights[a];
          const int sx = rx.first + int(a), sy = ry.first + int(b);
          for (int c = 0; c < level.channels; ++c) sum[std::size_t(c)] += wgt * level.at(sx, sy, c);
        }
      }
      for (int c = 0; c < level.channels; ++c) out.at(x, y, c) = float(sum[std::size_t(c)]);
    }
  }
  return out;
}

std::vector<Image> buildMipChain(const Image& level0) {
  std::vector<Image> levels;
  for (;;) {
    const Image& previous = levels.empty() ? level0 : levels.back();
    if (previous.empty() || (previous.width <= 1 && previous.height <= 1)) break;
    Image next = downsampleBox(previous);  // before push_back, which may move `previous`
    levels.push_back(std::move(next));
  }
  return levels;
}

}  // namespace diptych
