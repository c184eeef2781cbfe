// Textures, framebuffers, buffers, transfers and timer queries on a real OSMesa context.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/gl/debug.h"
#include "engine/gl/loader.h"
#include "engine/gl/objects.h"
#include "engine/gl/shader.h"
#include "engine/gl/transfer.h"
#include "gl_test_context.h"

namespace diptych::gl {
namespace DIPTYCH_UNITY_ID {

class GlObjects : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::osmesaContext();
    errorsBefore_ = glDebugErrorCount();
  }
  void TearDown() override { EXPECT_EQ(glDebugErrorCount(), errorsBefore_) << "GL errors logged"; }

 private:
  std::uint64_t errorsBefore_ = 0;
};

TEST_F(GlObjects, ClearedRgba32fReadsBackExactly) {
  const Texture t = Texture::create2D(TextureFormat::RGBA32F, 5, 3);
  Framebuffer fbo = Framebuffer::create();
  fbo.attachColor(0, t);
  fbo.checkComplete("clear");
  // Values with no short decimal form, a denormal and a huge one: any conversion would show.
  const float value[4] = {0.1f, -2.5e-40f, 3.0e38f, std::bit_cast<float>(0x3F7FFFFFu)};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, value);
  const std::vector<float> back = readTextureFloats(t);
  ASSERT_EQ(back.size(), 5u * 3u * 4u);
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(back[i]), std::bit_cast<std::uint32_t>(value[i % 4]))
        << "component " << i;
  }
}

// Both readback paths: the driver packing rows top first (GL_MESA_pack_invert, which llvmpipe
// has) and the row flip on the CPU that other drivers get, forced here by installing a copy of
// the context's table without the extension.
TEST_F(GlObjects, ReadbackPutsTheTopRowFirstWithAndWithoutPackInvert) {
  const GlFunctionTable* own = installedGlFunctions();
  ASSERT_NE(own, nullptr);
  EXPECT_TRUE(own->packInvert) << "Mesa drivers have GL_MESA_pack_invert";
  GlFunctionTable withoutExtension = *own;
  withoutExtension.packInvert = false;
  const int w = 4, h = 3;
  const Texture t = Texture::create2D(TextureFormat::R32F, w, h);
  Framebuffer fbo = Framebuffer::create();
  fbo.attachColor(0, t);
  const float zero[4] = {0.f, 0.f, 0.f, 0.f}, one[4] = {1.f, 1.f, 1.f, 1.f};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
  // GL row 0 is the bottom row of the image: clear only it, through the scissor.
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, w, 1);
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, one);
  glDisable(GL_SCISSOR_TEST);
  for (const GlFunctionTable* table :
       {own, static_cast<const GlFunctionTable*>(&withoutExtension), own}) {
    installGlFunctions(table);
    const std::vector<float> back = readTextureFloats(t);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x)
        EXPECT_EQ(back[y * w + x], y == h - 1 ? 1.f : 0.f)
            << x << "," << y << (table->packInvert ? " (pack invert)" : " (CPU flip)");
    }
    // The inversion is pack state: it must not outlive the readback.
    GLint invert = -1;
    glGetIntegerv(0x8758 /* GL_PACK_INVERT_MESA */, &invert);
    EXPECT_EQ(invert, 0);
  }
  installGlFunctions(own);
}

TEST_F(GlObjects, Rgba32uiRoundTrip) {
  const int w = 7, h = 5;
  const Texture t = Texture::create2D(TextureFormat::RGBA32UI, w, h);
  std::vector<std::uint32_t> words(std::size_t(w) * h * 4);
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = std::uint32_t(i * 2654435761u);
  uploadTexture(t, words);
  EXPECT_EQ(readTexture(t), words);
}

TEST_F(GlObjects, EveryFormatRoundTripsOnArraysAndCubes) {
  struct Case {
    TextureFormat format;
    std::vector<std::uint32_t> texel;  // one texel's words, exactly representable in the format
  };
  const auto f = [](float x) { return std::bit_cast<std::uint32_t>(x); };
  const std::vector<Case> cases = {
      {TextureFormat::R32F, {f(-1.25e-7f)}},
      {TextureFormat::RG32F, {f(1e20f), f(-0.3f)}},
      {TextureFormat::RGBA32F, {f(1.f), f(2.f), f(3.f), f(4.f)}},
      {TextureFormat::RGBA16F, {f(0.5f), f(-2.f), f(1024.f), f(0.099975586f)}},
      {TextureFormat::R32UI, {0xDEADBEEFu}},
      {TextureFormat::RGBA32UI, {0u, 1u, 0xFFFFFFFFu, 12345u}},
      {TextureFormat::RGBA8, {f(0.f), f(1.f), f(51.f / 255.f), f(128.f / 255.f)}},
      {TextureFormat::SRGB8_ALPHA8, {f(0.f), f(1.f), f(51.f / 255.f), f(128.f / 255.f)}},
      {TextureFormat::D32F, {f(0.123456789f)}},
  };
  // Normalized formats come back as c / 255 computed by the driver, which may round the last
  // float bit differently from our c / 255.f: compare them as 8-bit codes.
  const auto comparable = [](TextureFormat format, std::vector<std::uint32_t> words) {
    if (format == TextureFormat::RGBA8 || format == TextureFormat::SRGB8_ALPHA8) {
      for (std::uint32_t& w : words)
        w = std::uint32_t(std::lround(std::bit_cast<float>(w) * 255.f));
    }
    return words;
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(formatInfo(c.format).name));
    const int w = 3, h = 2;
    std::vector<std::uint32_t> words;
    for (int i = 0; i < w * h; ++i) words.insert(words.end(), c.texel.begin(), c.texel.end());
    const Texture t2 = Texture::create2D(c.format, w, h);
    uploadTexture(t2, words);
    EXPECT_EQ(comparable(c.format, readTexture(t2)), comparable(c.format, words));
    const Texture array = Texture::create2DArray(c.format, w, h, 3);
    uploadTexture(array, words, 2);
    EXPECT_EQ(comparable(c.format, readTexture(array, 2)), comparable(c.format, words));
    if (c.format != TextureFormat::D32F) {
      const Texture cube = Texture::createCube(c.format, 2);
      words.resize(2 * 2 * c.texel.size());
      uploadTexture(cube, words, 4);
      EXPECT_EQ(comparable(c.format, readTexture(cube, 4)), comparable(c.format, words));
    }
  }
}

TEST_F(GlObjects, UploadRejectsWrongSizes) {
  const Texture t = Texture::create2D(TextureFormat::RGBA32F, 2, 2);
  EXPECT_THROW(uploadTexture(t, std::vector<std::uint32_t>(3)), Error);
  EXPECT_THROW(readTexture(t, 1), Error);
  EXPECT_THROW(Texture::create2D(TextureFormat::R32F, 0, 4), Error);
}

TEST_F(GlObjects, IncompleteFramebufferNamesTheStatus) {
  const Framebuffer empty = Framebuffer::create();
  try {
    empty.checkComplete("empty");
    FAIL() << "expected an incomplete framebuffer";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("'empty'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"),
              std::string::npos)
        << e.what();
  }
}

TEST_F(GlObjects, MismatchedLayeredAttachmentsAreIncomplete) {
  // A layered attachment next to a non-layered one: GL 4.5 §9.4.2 "incomplete layer targets".
  const Texture array = Texture::create2DArray(TextureFormat::RGBA8, 4, 4, 2);
  const Texture plain = Texture::create2D(TextureFormat::RGBA8, 4, 4);
  Framebuffer fbo = Framebuffer::create();
  fbo.attachColor(0, array);
  fbo.attachColor(1, plain);
  EXPECT_THROW(fbo.checkComplete("layers"), Error);
  EXPECT_EQ(Framebuffer::statusName(GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS),
            "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS");
}

TEST_F(GlObjects, BufferRoundTripAndMoveSemantics) {
  const std::vector<std::uint32_t> data = {1, 2, 3, 4, 5};
  Buffer a = Buffer::create(data.size() * 4, data.data());
  const GLuint id = a.id();
  Buffer b = std::move(a);
  EXPECT_EQ(a.id(), 0u);
  EXPECT_EQ(b.id(), id);
  std::vector<std::uint32_t> back(5);
  b.download(0, 20, back.data());
  EXPECT_EQ(back, data);
  const std::uint32_t nine = 9;
  b.upload(8, 4, &nine);
  b.download(0, 20, back.data());
  EXPECT_EQ(back[2], 9u);
  EXPECT_THROW(b.upload(20, 4, &nine), Error);
}

// A buffer texture reads its buffer's bytes as texels of its format, bit for bit, and knows its
// texel count: the scene's positions, indices and material records reach every GL pass this
// way (objects.h BufferTexture, shaders/gl/scene_buffers.glsl).
TEST_F(GlObjects, BufferTextureFetchesTheBufferBitForBit) {
  const std::vector<float> floats = {0.1f, -0.f, 3.0e38f, 1.f, -2.f, 1e-30f, 7.5f, 0.3f, -9.f};
  const std::vector<std::uint32_t> uints = {7, 0xFFFFFFFFu, 3, 4, 5, 0x80000000u};
  const Buffer floatBuffer = Buffer::create(floats.size() * 4, floats.data());
  const Buffer uintBuffer = Buffer::create(uints.size() * 4, uints.data());
  const BufferTexture floatTexels =
      BufferTexture::create(floatBuffer, GL_RGB32F, 12, "test.rgb32f");
  const BufferTexture uintTexels =
      BufferTexture::create(uintBuffer, GL_RGB32UI, 12, "test.rgb32ui");
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / "diptych_buffer_texture_test.comp";
  std::ofstream(file) << R"(layout(local_size_x = 1) in;
layout(binding = 0) uniform samplerBuffer uFloats;
layout(binding = 1) uniform usamplerBuffer uUints;
layout(std430, binding = 0) writeonly buffer Out { uint words[]; };
void main() {
  for (int t = 0; t < 3; ++t) {
    vec3 v = texelFetch(uFloats, t).xyz;
    for (int c = 0; c < 3; ++c) words[3 * t + c] = floatBitsToUint(v[c]);
  }
  for (int t = 0; t < 2; ++t) {
    uvec3 v = texelFetch(uUints, t).xyz;
    for (int c = 0; c < 3; ++c) words[9 + 3 * t + c] = v[c];
  }
  words[15] = uint(textureSize(uFloats));
  words[16] = uint(textureSize(uUints));
}
)";
  const Program program = loadProgram({file});
  std::filesystem::remove(file);
  const Buffer out = Buffer::create(17 * 4);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  floatTexels.bind(0);
  uintTexels.bind(1);
  program.use();
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::uint32_t> words(17);
  out.download(0, words.size() * 4, words.data());
  for (std::size_t i = 0; i < floats.size(); ++i)
    EXPECT_EQ(words[i], std::bit_cast<std::uint32_t>(floats[i])) << "float " << i;
  for (std::size_t i = 0; i < uints.size(); ++i) EXPECT_EQ(words[9 + i], uints[i]) << "uint " << i;
  EXPECT_EQ(words[15], 3u);
  EXPECT_EQ(words[16], 2u);
}

TEST_F(GlObjects, TimerQueryReportsMilliseconds) {
  const Texture t = Texture::create2D(TextureFormat::RGBA32F, 64, 64);
  Framebuffer fbo = Framebuffer::create();
  fbo.attachColor(0, t);
  const TimerQuery q = TimerQuery::create();
  q.begin();
  const float one[4] = {1.f, 1.f, 1.f, 1.f};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, one);
  q.end();
  const double ms = q.milliseconds();  // waits
  EXPECT_GE(ms, 0.0);
  EXPECT_TRUE(q.available());
  ASSERT_TRUE(q.tryMilliseconds().has_value());
  EXPECT_EQ(*q.tryMilliseconds(), ms);
}

}  // namespace DIPTYCH_UNITY_ID
}  // namespace diptych::gl
