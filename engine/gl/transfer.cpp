#include "engine/gl/transfer.h"

#include <algorithm>
#include <cstring>

#include "engine/core/error.h"

namespace diptych::gl {
namespace {

struct LevelSize {
  int width, height;
};

LevelSize levelSize(const Texture& t, int level) {
  if (level < 0 || level >= t.levels()) {
    throw Error("texture level " + std::to_string(level) + " out of range (" +
                std::to_string(t.levels()) + " levels)");
  }
  return {std::max(1, t.width() >> level), std::max(1, t.height() >> level)};
}

void checkLayer(const Texture& t, int layer) {
  if (layer < 0 || layer >= t.layers()) {
    throw Error("texture layer " + std::to_string(layer) + " out of range (" +
                std::to_string(t.layers()) + " layers)");
  }
}

// GL_MESA_pack_invert's pixel-store parameter (its spec; glcorearb.h has no vendor extensions).
constexpr GLenum kPackInvertMesa = 0x8758;

// Reverses the row order in place: top-first <-> bottom-first.
void flipRows(std::span<std::uint32_t> words, std::size_t rowWords, int rows) {
  for (int top = 0, bottom = rows - 1; top < bottom; ++top, --bottom) {
    std::swap_ranges(words.begin() + std::ptrdiff_t(top * rowWords),
                     words.begin() + std::ptrdiff_t((top + 1) * rowWords),
                     words.begin() + std::ptrdiff_t(bottom * rowWords));
  }
}

}  // namespace

std::size_t texelWordCount(const Texture& t, int level) {
  const LevelSize s = levelSize(t, level);
  return std::size_t(s.width) * s.height * formatInfo(t.format()).components;
}

void readTextureInto(const Texture& t, std::span<std::uint32_t> words, int layer, int level) {
  checkLayer(t, layer);
  const LevelSize s = levelSize(t, level);
  const FormatInfo& f = formatInfo(t.format());
  if (words.size() != texelWordCount(t, level))
    throw Error("texture readback into " + std::to_string(words.size()) + " words; the level has " +
                std::to_string(texelWordCount(t, level)));
  // Rows of 32-bit words are always 4-byte aligned, which is the default pack alignment; set
  // it anyway since it is global state another pass may have changed.
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  const int zoffset = t.kind() == TextureKind::Tex2D ? 0 : layer;
  // Where the driver can pack top row first (Mesa), it writes the rows in the CPU order as it
  // copies them, instead of a second pass over the image here (a 640x480 RGBA32UI G-buffer is
  // 4.9 MB swapped row by row). The state is reset at once: it applies to every later pack.
  const GlFunctionTable* functions = installedGlFunctions();
  const bool invert = functions && functions->packInvert;
  if (invert) glPixelStorei(kPackInvertMesa, GL_TRUE);
  glGetTextureSubImage(t.id(), level, 0, 0, zoffset, s.width, s.height, 1, f.pixelFormat,
                       f.pixelType, GLsizei(words.size() * 4), words.data());
  if (invert)
    glPixelStorei(kPackInvertMesa, GL_FALSE);
  else
    flipRows(words, std::size_t(s.width) * f.components, s.height);
}

std::vector<std::uint32_t> readTexture(const Texture& t, int layer, int level) {
  std::vector<std::uint32_t> words(texelWordCount(t, level));
  readTextureInto(t, words, layer, level);
  return words;
}

void uploadTexture(const Texture& t, std::span<const std::uint32_t> words, int layer, int level) {
  checkLayer(t, layer);
  const LevelSize s = levelSize(t, level);
  const FormatInfo& f = formatInfo(t.format());
  if (words.size() != texelWordCount(t, level)) {
    throw Error("texture upload of " + std::to_string(words.size()) + " words to a " +
                std::to_string(s.width) + "x" + std::to_string(s.height) + " " +
                std::string(f.name) + " level needs " + std::to_string(texelWordCount(t, level)));
  }
  // GL's rows are bottom first: copied in that order in one pass (no unpack-side inversion
  // exists to spare the copy).
  const std::size_t rowWords = std::size_t(s.width) * f.components;
  std::vector<std::uint32_t> flipped(words.size());
  for (int row = 0; row < s.height; ++row)
    std::copy_n(words.begin() + std::ptrdiff_t(std::size_t(row) * rowWords), rowWords,
                flipped.begin() + std::ptrdiff_t(std::size_t(s.height - 1 - row) * rowWords));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  if (t.kind() == TextureKind::Tex2D) {
    glTextureSubImage2D(t.id(), level, 0, 0, s.width, s.height, f.pixelFormat, f.pixelType,
                        flipped.data());
  } else {
    // DSA treats a cube map as 6 layers (GL 4.5 §8.6, TextureSubImage3D on TEXTURE_CUBE_MAP).
    glTextureSubImage3D(t.id(), level, 0, 0, layer, s.width, s.height, 1, f.pixelFormat,
                        f.pixelType, flipped.data());
  }
}

std::vector<float> readTextureFloats(const Texture& t, int layer, int level) {
  const std::vector<std::uint32_t> words = readTexture(t, layer, level);
  std::vector<float> values(words.size());
  std::memcpy(values.data(), words.data(), words.size() * 4);
  return values;
}

void uploadTextureFloats(const Texture& t, const std::vector<float>& values, int layer, int level) {
  std::vector<std::uint32_t> words(values.size());
  std::memcpy(words.data(), values.data(), values.size() * 4);
  uploadTexture(t, words, layer, level);
}

}  // namespace diptych::gl
