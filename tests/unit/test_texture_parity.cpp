// GL vs CPU texture sampling parity, per sampler mode: shaders/gl/scene_textures.glsl (a compute
// shader on OSMesa/llvmpipe, reading the textures engine/gl/scene_textures.cpp uploads) against
// engine/shading/texture_sampling.cpp on the same random (uv, lambda, footprint), for every wrap
// pair, every glTF min filter and both mag filters, on power-of-two and odd-sized images. Both
// read the same mip chain (engine/scene/mip_chain.h), so they must agree to float rounding:
// |gpu - cpu| <= 1e-5 per channel (texel values are in [0, 1]).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/gl/debug.h"
#include "engine/gl/scene_textures.h"
#include "engine/gl/shader.h"
#include "engine/scene/mip_chain.h"
#include "engine/shading/texture_sampling.h"
#include "gl_test_context.h"
#include "tests/support/test_paths.h"

namespace diptych {
namespace DIPTYCH_UNITY_ID {

Texture randomTexture(int w, int h, WrapMode s, WrapMode t, FilterMode min, FilterMode mag,
                      std::mt19937& rng) {
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  Texture tex;
  tex.name = std::to_string(w) + "x" + std::to_string(h);
  tex.image = Image(w, h, 4);
  for (float& v : tex.image.pixels) v = unit(rng);
  tex.mips = buildMipChain(tex.image);
  tex.wrapS = s, tex.wrapT = t, tex.minFilter = min, tex.magFilter = mag;
  return tex;
}

TEST(TextureParity, GlSamplersMatchCpuPerSamplerMode) {
  gl::testing::osmesaContext();
  std::mt19937 rng(7);
  Scene scene;
  const WrapMode wraps[] = {WrapMode::Repeat, WrapMode::ClampToEdge, WrapMode::MirroredRepeat};
  const FilterMode mins[] = {FilterMode::Nearest,
                             FilterMode::Linear,
                             FilterMode::NearestMipmapNearest,
                             FilterMode::LinearMipmapNearest,
                             FilterMode::NearestMipmapLinear,
                             FilterMode::LinearMipmapLinear};
  int k = 0;
  for (WrapMode s : wraps)
    for (WrapMode t : wraps)
      for (FilterMode min : mins) {
        const bool odd = (k++ % 2) != 0;  // alternate 16x8 and 13x7 (odd: the NPOT chain)
        scene.textures.push_back(randomTexture(odd ? 13 : 16, odd ? 7 : 8, s, t, min,
                                               k % 3 ? FilterMode::Linear : FilterMode::Nearest,
                                               rng));
      }
  const gl::GlSceneTextures uploaded = gl::uploadTextures(scene);

  constexpr int kPerTexture = 64;
  const int count = int(scene.textures.size()) * kPerTexture;
  std::uniform_real_distribution<float> uvs(-2.f, 3.f), lods(-1.f, 5.f), grads(-0.6f, 0.6f);
  std::vector<float> in;
  for (int c = 0; c < count; ++c) {
    in.insert(in.end(), {float(c / kPerTexture), uvs(rng), uvs(rng), lods(rng), grads(rng) / 4.f,
                         grads(rng) / 4.f, grads(rng), grads(rng)});
  }
  const gl::Buffer inputs = gl::Buffer::create(in.size() * 4, in.data());
  const gl::Buffer outputs = gl::Buffer::create(std::size_t(count) * 9 * 16);
  const gl::Program program = gl::loadProgram(
      {std::filesystem::path(DIPTYCH_TESTS_DIR) / "unit/shaders/texture_parity.comp"});
  program.use();
  program.set("uCount", count);
  uploaded.bind();
  inputs.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  outputs.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  gl::glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
  gl::glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> out(std::size_t(count) * 36);
  gl::glGetNamedBufferSubData(outputs.id(), 0, GLsizeiptr(out.size() * 4), out.data());

  int worst = 0;
  float worstError = 0.f;
  for (int c = 0; c < count; ++c) {
    const float* r = &in[std::size_t(c) * 8];
    const Texture& tex = scene.textures[std::size_t(r[0])];
    const vec2 uv(r[1], r[2]), dx(r[4], r[5]), dy(r[6], r[7]);
    const float lambda = r[3];
    vec4 expected[9];
    expected[0] = sampleTextureLod(tex, uv, lambda);
    for (int m = 0; m < 6; ++m)
      expected[1 + m] = sampleFiltered(tex, uv, lambda, (m & 1) != 0, MipSelect(m >> 1));
    expected[7] = sampleAnisotropic(tex, uv, dx, dy, 8);
    expected[8] = vec4(lodFromGradients(tex, dx, dy), 0.f, 0.f, 0.f);
    for (int j = 0; j < 9; ++j) {
      for (int ch = 0; ch < 4; ++ch) {
        const float gpu = out[(std::size_t(c) * 9 + std::size_t(j)) * 4 + std::size_t(ch)];
        const float err = std::fabs(gpu - expected[j][ch]);
        if (err > worstError) worstError = err, worst = c;
        EXPECT_LE(err, 1e-5f) << "texture " << tex.name << " case " << c << " output " << j
                              << " channel " << ch << " uv (" << uv.x << ", " << uv.y << ") lambda "
                              << lambda;
      }
    }
  }
  std::cout << count << " cases x 9 lookups; worst |gpu - cpu| = " << worstError << " (case "
            << worst << ")\n";
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych
