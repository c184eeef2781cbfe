#include "engine/gl/objects.h"

#include <array>

#include "engine/core/check.h"
#include "engine/core/error.h"

namespace diptych::gl {

namespace detail {
void deleteTexture(GLuint id) {
  glDeleteTextures(1, &id);
}
void deleteFramebuffer(GLuint id) {
  glDeleteFramebuffers(1, &id);
}
void deleteBuffer(GLuint id) {
  glDeleteBuffers(1, &id);
}
void deleteVertexArray(GLuint id) {
  glDeleteVertexArrays(1, &id);
}
void deleteProgram(GLuint id) {
  glDeleteProgram(id);
}
void deleteQuery(GLuint id) {
  glDeleteQueries(1, &id);
}
}  // namespace detail

const FormatInfo& formatInfo(TextureFormat format) {
  // Normalized and half formats transfer as GL_FLOAT: the driver converts exactly (8-bit unorm
  // and half values are all representable in float32).
  static const std::array<FormatInfo, 9> table{{
      {"R32F", GL_R32F, GL_RED, GL_FLOAT, 1, false, false},
      {"RG32F", GL_RG32F, GL_RG, GL_FLOAT, 2, false, false},
      {"RGBA32F", GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, false, false},
      {"RGBA16F", GL_RGBA16F, GL_RGBA, GL_FLOAT, 4, false, false},
      {"R32UI", GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 1, true, false},
      {"RGBA32UI", GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 4, true, false},
      {"RGBA8", GL_RGBA8, GL_RGBA, GL_FLOAT, 4, false, false},
      {"SRGB8_ALPHA8", GL_SRGB8_ALPHA8, GL_RGBA, GL_FLOAT, 4, false, false},
      {"D32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 1, false, true},
  }};
  DIPTYCH_CHECK(std::size_t(format) < table.size(),
                "texture format " + std::to_string(int(format)) + " has no entry");
  return table[std::size_t(format)];
}

namespace {

void checkSize(int width, int height, int layers, int levels) {
  if (width <= 0 || height <= 0 || layers <= 0 || levels <= 0) {
    throw Error("texture size must be positive: " + std::to_string(width) + "x" +
                std::to_string(height) + ", " + std::to_string(layers) + " layers, " +
                std::to_string(levels) + " levels");
  }
}

// Integer textures are incomplete with linear filtering (GL 4.5 §8.17), and depth/ids should
// never be blended, so those sample nearest; the rest filter linearly (trilinear with mips).
void setDefaultSampling(GLuint id, const FormatInfo& info, int levels) {
  const bool nearest = info.integer || info.depth;
  const GLint mag = nearest ? GL_NEAREST : GL_LINEAR;
  const GLint min = nearest ? (levels > 1 ? GL_NEAREST_MIPMAP_NEAREST : GL_NEAREST)
                            : (levels > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, mag);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, min);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
}

}  // namespace

// The one place a texture is created: storage of the kind's shape, default sampling, metadata.
Texture Texture::create(TextureKind kind, TextureFormat format, int width, int height, int layers,
                        int levels) {
  checkSize(width, height, layers, levels);
  static constexpr GLenum kTargets[] = {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY, GL_TEXTURE_CUBE_MAP};
  Texture t;
  GLuint id = 0;
  glCreateTextures(kTargets[int(kind)], 1, &id);
  t.handle_ = GlHandle<detail::deleteTexture>(id);
  const GLenum internal = formatInfo(format).internalFormat;
  if (kind == TextureKind::Tex2DArray)
    glTextureStorage3D(id, levels, internal, width, height, layers);
  else  // 2D and cube: a cube's six faces come with 2D storage
    glTextureStorage2D(id, levels, internal, width, height);
  setDefaultSampling(id, formatInfo(format), levels);
  t.format_ = format;
  t.kind_ = kind;
  t.width_ = width, t.height_ = height, t.layers_ = layers, t.levels_ = levels;
  return t;
}

Texture Texture::create2D(TextureFormat format, int width, int height, int levels) {
  return create(TextureKind::Tex2D, format, width, height, 1, levels);
}

Texture Texture::create2DArray(TextureFormat format, int width, int height, int layers,
                               int levels) {
  return create(TextureKind::Tex2DArray, format, width, height, layers, levels);
}

Texture Texture::createCube(TextureFormat format, int size, int levels) {
  return create(TextureKind::Cube, format, size, size, 6, levels);
}

void Texture::setLabel(std::string_view label) const {
  glObjectLabel(GL_TEXTURE, id(), GLsizei(label.size()), label.data());
}

Framebuffer Framebuffer::create() {
  Framebuffer f;
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  f.handle_ = GlHandle<detail::deleteFramebuffer>(id);
  return f;
}

namespace {
void attach(GLuint fbo, GLenum attachment, const Texture& texture, int level, int layer) {
  if (layer < 0) {
    glNamedFramebufferTexture(fbo, attachment, texture.id(), level);
  } else {
    glNamedFramebufferTextureLayer(fbo, attachment, texture.id(), level, layer);
  }
}
}  // namespace

void Framebuffer::attachColor(int index, const Texture& texture, int level, int layer) {
  if (index < 0 || index >= 8) throw Error("colour attachment index out of range");
  attach(id(), GL_COLOR_ATTACHMENT0 + index, texture, level, layer);
  colorMask_ |= 1u << index;
  // Fragment output location i writes colour attachment i; gaps are GL_NONE.
  std::array<GLenum, 8> buffers{};
  int count = 0;
  for (int i = 0; i < 8; ++i) {
    buffers[i] = (colorMask_ >> i) & 1u ? GL_COLOR_ATTACHMENT0 + i : GL_NONE;
    if (buffers[i] != GL_NONE) count = i + 1;
  }
  glNamedFramebufferDrawBuffers(id(), count, buffers.data());
}

void Framebuffer::attachDepth(const Texture& texture, int level, int layer) {
  attach(id(), GL_DEPTH_ATTACHMENT, texture, level, layer);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id());
}

std::string_view Framebuffer::statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_COMPLETE:
      return "GL_FRAMEBUFFER_COMPLETE";
    case GL_FRAMEBUFFER_UNDEFINED:
      return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER:
      return "GL_FRAMEBUFFER_INCOMPLETE_DRAW_BUFFER";
    case GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER:
      return "GL_FRAMEBUFFER_INCOMPLETE_READ_BUFFER";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
      return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default:
      return "unknown framebuffer status";
  }
}

void Framebuffer::checkComplete(std::string_view label) const {
  const GLenum status = glCheckNamedFramebufferStatus(id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw Error("framebuffer '" + std::string(label) +
                "' is incomplete: " + std::string(statusName(status)));
  }
}

Buffer Buffer::create(std::size_t bytes, const void* data) {
  Buffer b;
  GLuint id = 0;
  glCreateBuffers(1, &id);
  b.handle_ = GlHandle<detail::deleteBuffer>(id);
  b.size_ = std::max<std::size_t>(bytes, 4);
  // A zero-sized store is an error in GL; a 4-byte store keeps empty inputs bindable. Data is
  // given only when it fills the request exactly.
  glNamedBufferStorage(id, GLsizeiptr(b.size_), bytes == b.size_ ? data : nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  return b;
}

void Buffer::upload(std::size_t offset, std::size_t bytes, const void* data) {
  if (offset + bytes > size_) throw Error("buffer upload out of range");
  glNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::download(std::size_t offset, std::size_t bytes, void* data) const {
  if (offset + bytes > size_) throw Error("buffer download out of range");
  glGetNamedBufferSubData(id(), GLintptr(offset), GLsizeiptr(bytes), data);
}

void Buffer::bindBase(GLenum target, GLuint index) const {
  glBindBufferBase(target, index, id());
}

BufferTexture BufferTexture::create(const Buffer& buffer, GLenum internalFormat,
                                    std::size_t texelBytes, std::string_view label) {
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  const std::size_t texels = buffer.size() / texelBytes;
  if (texels > std::size_t(maxTexels)) {
    throw Error("scene data '" + std::string(label) + "' has " + std::to_string(texels) +
                " texels; this GL reads at most " + std::to_string(maxTexels) +
                " from one buffer texture (GL_MAX_TEXTURE_BUFFER_SIZE)");
  }
  BufferTexture t;
  GLuint id = 0;
  glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
  t.handle_ = GlHandle<detail::deleteTexture>(id);
  glTextureBuffer(id, internalFormat, buffer.id());
  glObjectLabel(GL_TEXTURE, id, GLsizei(label.size()), label.data());
  return t;
}

void BufferTexture::bind(GLuint unit) const {
  glBindTextureUnit(unit, id());
}

VertexArray VertexArray::create() {
  VertexArray v;
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  v.handle_ = GlHandle<detail::deleteVertexArray>(id);
  return v;
}

void VertexArray::bind() const {
  glBindVertexArray(id());
}

void Program::use() const {
  glUseProgram(id());
}
GLint Program::location(const char* name) const {
  return glGetUniformLocation(id(), name);
}
void Program::set(const char* n, int v) const {
  glProgramUniform1i(id(), location(n), v);
}
void Program::set(const char* n, std::uint32_t v) const {
  glProgramUniform1ui(id(), location(n), v);
}
void Program::set(const char* n, float v) const {
  glProgramUniform1f(id(), location(n), v);
}
void Program::set(const char* n, const vec2& v) const {
  glProgramUniform2fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const ivec2& v) const {
  glProgramUniform2iv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const vec3& v) const {
  glProgramUniform3fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const vec4& v) const {
  glProgramUniform4fv(id(), location(n), 1, glm::value_ptr(v));
}
void Program::set(const char* n, const mat4& v) const {
  glProgramUniformMatrix4fv(id(), location(n), 1, GL_FALSE, glm::value_ptr(v));
}

TimerQuery TimerQuery::create() {
  TimerQuery q;
  GLuint id = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &id);
  q.handle_ = GlHandle<detail::deleteQuery>(id);
  return q;
}

void TimerQuery::begin() const {
  glBeginQuery(GL_TIME_ELAPSED, id());
}
void TimerQuery::end() const {
  glEndQuery(GL_TIME_ELAPSED);
}

bool TimerQuery::available() const {
  GLint ready = 0;
  glGetQueryObjectiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
  return ready != 0;
}

std::optional<double> TimerQuery::tryMilliseconds() const {
  if (!available()) return std::nullopt;
  return milliseconds();
}

double TimerQuery::milliseconds() const {
  GLuint64 ns = 0;
  glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &ns);
  return double(ns) * 1e-6;
}

}  // namespace diptych::gl
