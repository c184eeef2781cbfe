#include "engine/graph/gl_backend.h"

#include <algorithm>
#include <bit>

#include "engine/core/check.h"
#include "engine/core/error.h"
#include "engine/gl/loader.h"
#include "engine/gl/transfer.h"

namespace diptych {

gl::TextureFormat toGlFormat(Format f) {
  switch (f) {
    case Format::R32F:
      return gl::TextureFormat::R32F;
    case Format::RG32F:
      return gl::TextureFormat::RG32F;
    case Format::RGBA32F:
      return gl::TextureFormat::RGBA32F;
    case Format::R32UI:
      return gl::TextureFormat::R32UI;
    case Format::RGBA32UI:
      return gl::TextureFormat::RGBA32UI;
    case Format::D32F:
      return gl::TextureFormat::D32F;
  }
  throw Error("unknown resource format");
}

GlBackend::GlBackend() = default;
GlBackend::~GlBackend() = default;

int GlBackend::createTexture(const ResourceDesc& d) {
  const gl::TextureFormat f = toGlFormat(d.format);
  textures_.push_back(d.layers > 1 ? gl::Texture::create2DArray(f, d.width, d.height, d.layers)
                                   : gl::Texture::create2D(f, d.width, d.height));
  descs_.push_back(d);
  return int(textures_.size() - 1);
}

std::size_t GlBackend::checked(int handle) const {
  DIPTYCH_CHECK(
      handle >= 0 && std::size_t(handle) < textures_.size(),
      "GL texture handle " + std::to_string(handle) + " of " + std::to_string(textures_.size()));
  return std::size_t(handle);
}

void GlBackend::readback(int handle, CpuImage& into) {
  const ResourceDesc& d = descs_[checked(handle)];
  if (!(into.desc == d))
    throw Error("readback into a CPU image of another description: " + describe(into.desc));
  const std::size_t layerWords = std::size_t(d.width) * d.height * formatChannels(d.format);
  for (int layer = 0; layer < d.layers; ++layer)
    gl::readTextureInto(textures_[handle],
                        std::span(into.words).subspan(std::size_t(layer) * layerWords, layerWords),
                        layer);
}

void GlBackend::upload(const CpuImage& from, int handle) {
  const ResourceDesc& d = descs_[checked(handle)];
  if (!(from.desc == d))
    throw Error("upload from a CPU image of another description: " + describe(from.desc));
  const std::size_t layerWords = std::size_t(d.width) * d.height * formatChannels(d.format);
  for (int layer = 0; layer < d.layers; ++layer)
    gl::uploadTexture(textures_[handle],
                      std::span(from.words).subspan(std::size_t(layer) * layerWords, layerWords),
                      layer);
}

void GlBackend::fill(int handle, const vec4& value) {
  const ResourceDesc& d = descs_[checked(handle)];
  const gl::FormatInfo& info = gl::formatInfo(toGlFormat(d.format));
  std::uint32_t words[4];
  for (int c = 0; c < 4; ++c)
    words[c] = formatIsInteger(d.format) ? std::uint32_t(value[c])
                                         : std::bit_cast<std::uint32_t>(value[c]);
  gl::glClearTexImage(textures_[handle].id(), 0, info.pixelFormat, info.pixelType, words);
}

void GlBackend::beginTimer(std::size_t slot) {
  while (timers_.size() <= slot) timers_.push_back(gl::TimerQuery::create());
  timers_[slot].begin();
}
void GlBackend::endTimer() {
  gl::glEndQuery(GL_TIME_ELAPSED);
  // Submit the node's commands now; glFlush does not wait. The GL then works while the CPU
  // goes on, and llvmpipe, which records a query's end when it rasterizes the scene holding
  // it, times the node's own work: without the flush a readback's query ended at the next
  // frame's first flush and read as most of a frame (measured 999 ms on a 1069 ms frame).
  gl::glFlush();
}
void GlBackend::finish() {
  gl::glFinish();
}

double GlBackend::timerMs(std::size_t slot) const {
  DIPTYCH_CHECK(slot < timers_.size(), "timer query " + std::to_string(slot) + " never started");
  return timers_[slot].milliseconds();
}

}  // namespace diptych
