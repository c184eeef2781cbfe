#include "engine/scene/mip_chain.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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

// The exact 2:1 case (both sides even): axisTaps gives every texel the taps {2j, 2j + 1} with
// weights {0.5, 0.5}, so each product weight is 0.25 (exact in double) and the general loop's
// sum is 0 + p(2x, 2y) + p(2x+1, 2y) + p(2x, 2y+1) + p(2x+1, 2y+1), each times 0.25, in that
// order. The same additions in the same order give the same double, hence the same float.
Image downsampleEven(const Image& level) {
  const int w = level.width / 2, h = level.height / 2, n = level.channels;
  Image out(w, h, n);
  const std::size_t rowValues = std::size_t(level.width) * std::size_t(n);
  tbb::parallel_for(tbb::blocked_range<int>(0, h), [&](const tbb::blocked_range<int>& rows) {
    for (int y = rows.begin(); y < rows.end(); ++y) {
      const float* top = level.pixels.data() + std::size_t(2 * y) * rowValues;
      const float* bottom = top + rowValues;
      float* dst = out.pixels.data() + std::size_t(y) * std::size_t(w) * std::size_t(n);
      for (int x = 0; x < w; ++x) {
        const std::size_t left = std::size_t(2 * x) * std::size_t(n), right = left + std::size_t(n);
        for (int c = 0; c < n; ++c) {
          double sum = 0.0;
          sum += 0.25 * top[left + std::size_t(c)];
          sum += 0.25 * top[right + std::size_t(c)];
          sum += 0.25 * bottom[left + std::size_t(c)];
          sum += 0.25 * bottom[right + std::size_t(c)];
          dst[std::size_t(x) * std::size_t(n) + std::size_t(c)] = float(sum);
        }
      }
    }
  });
  return out;
}

}  // namespace

Image downsampleBox(const Image& level) {
  if (level.empty()) return {};
  if (level.width % 2 == 0 && level.height % 2 == 0) return downsampleEven(level);
  return downsampleBoxAreaWeights(level);
}

Image downsampleBoxAreaWeights(const Image& level) {
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
