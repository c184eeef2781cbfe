#pragma once
// The lecture's mipmap (Ureña, Informática Gráfica, Tema 5, 1.1 "Mipmaps"): M_0 is the image and
//   M_{i+1}[j, k] = 1/4 (M_i[2j, 2k] + M_i[2j+1, 2k] + M_i[2j, 2k+1] + M_i[2j+1, 2k+1]).
// Built here once per texture and read by both the CPU sampler (engine/shading/texture_sampling)
// and the GL upload (engine/gl/shading_buffers), so both sides filter the same texels.
//
// Non-power-of-two sizes: level sizes follow OpenGL (4.5 core, 8.14.3): w_{i+1} = max(1,
// floor(w_i / 2)), down to 1x1, so the chain has floor(log2(max(w, h))) + 1 levels. Texel j of
// level i+1 is the area-weighted mean of level i over the interval it covers, [j w_i / w_{i+1},
// (j+1) w_i / w_{i+1}): exactly the lecture's average of two texels when w_i is even, and for an
// odd w_i a box of 2 + 1/w_{i+1} texels whose edge texels count fractionally, so no texel is
// dropped and every level keeps the image's mean. A side of 1 stays 1 (the other side halves).
#include <vector>

#include "engine/core/image.h"

namespace diptych {

// Level i+1 from level i (any channel count; an empty image gives an empty image). Even sides
// take a fast path (rows in parallel) that adds the same products in the same order as
// downsampleBoxAreaWeights, so the two agree bit for bit.
Image downsampleBox(const Image& level);
// The general area-weighted path for any sizes (what downsampleBox does for odd sides).
Image downsampleBoxAreaWeights(const Image& level);

// Levels 1..n of the chain (level 0, the image itself, is not copied); empty for a 1x1 or empty
// image.
std::vector<Image> buildMipChain(const Image& level0);

}  // namespace diptych
