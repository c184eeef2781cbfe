#pragma once
// Move-only RAII wrappers over GL 4.5 direct-state-access objects. Each owns one GL name and
// deletes it on destruction; a moved-from or default object holds 0 and owns nothing. They must
// be destroyed while their context is current (the frame graph's pool owns them).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "engine/core/math.h"
#include "engine/gl/loader.h"

namespace diptych::gl {

// Owns a GL name; Deleter is a function `void(GLuint)`.
template <void (*Deleter)(GLuint)>
class GlHandle {
 public:
  GlHandle() = default;
  explicit GlHandle(GLuint id) : id_(id) {}
  GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
  GlHandle& operator=(GlHandle&& o) noexcept {
    if (this != &o) {
      reset();
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlHandle(const GlHandle&) = delete;
  GlHandle& operator=(const GlHandle&) = delete;
  ~GlHandle() { reset(); }
  GLuint get() const { return id_; }
  void reset() {
    if (id_) Deleter(std::exchange(id_, 0));
  }

 private:
  GLuint id_ = 0;
};

namespace detail {
void deleteTexture(GLuint id);
void deleteFramebuffer(GLuint id);
void deleteBuffer(GLuint id);
void deleteVertexArray(GLuint id);
void deleteProgram(GLuint id);
void deleteQuery(GLuint id);
}  // namespace detail

// Texture formats the engine uses. Readback/upload (transfer.h) moves one 32-bit word per
// component: float bits for float, half and normalized formats, uint for integer formats.
enum class TextureFormat {
  R32F,
  RG32F,
  RGBA32F,
  RGBA16F,
  R32UI,
  RGBA32UI,
  RGBA8,
  SRGB8_ALPHA8,
  D32F
};

struct FormatInfo {
  std::string_view name;  // "RGBA32F"
  GLenum internalFormat;  // sized, for glTextureStorage*
  GLenum pixelFormat;     // client format for transfers (GL_RGBA, GL_RGBA_INTEGER, ...)
  GLenum pixelType;       // client type for transfers (GL_FLOAT or GL_UNSIGNED_INT)
  int components;
  bool integer;
  bool depth;
};
const FormatInfo& formatInfo(TextureFormat format);

enum class TextureKind { Tex2D, Tex2DArray, Cube };

class Texture {
 public:
  Texture() = default;
  static Texture create2D(TextureFormat format, int width, int height, int levels = 1);
  static Texture create2DArray(TextureFormat format, int width, int height, int layers,
                               int levels = 1);
  static Texture createCube(TextureFormat format, int size, int levels = 1);

  GLuint id() const { return handle_.get(); }
  explicit operator bool() const { return id() != 0; }
  TextureFormat format() const { return format_; }
  TextureKind kind() const { return kind_; }
  int width() const { return width_; }
  int height() const { return height_; }
  int layers() const { return layers_; }  // 1 for 2D, 6 for cube
  int levels() const { return levels_; }
  void setLabel(std::string_view label) const;

 private:
  static Texture create(TextureKind kind, TextureFormat format, int width, int height, int layers,
                        int levels);
  GlHandle<detail::deleteTexture> handle_;
  TextureFormat format_ = TextureFormat::RGBA8;
  TextureKind kind_ = TextureKind::Tex2D;
  int width_ = 0, height_ = 0, layers_ = 0, levels_ = 0;
};

class Framebuffer {
 public:
  Framebuffer() = default;
  static Framebuffer create();
  GLuint id() const { return handle_.get(); }
  // Attach a level (and, for arrays and cubes, a layer/face; -1 attaches all layers: layered).
  void attachColor(int index, const Texture& texture, int level = 0, int layer = -1);
  void attachDepth(const Texture& texture, int level = 0, int layer = -1);
  // Draw buffers = the colour attachments made so far, in index order.
  void bind() const;
  // Throws Error "framebuffer 'LABEL' is incomplete: GL_FRAMEBUFFER_INCOMPLETE_..." unless
  // complete.
  void checkComplete(std::string_view label) const;
  // GL_FRAMEBUFFER_COMPLETE, GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT, ... for a status.
  static std::string_view statusName(GLenum status);

 private:
  GlHandle<detail::deleteFramebuffer> handle_;
  std::uint32_t colorMask_ = 0;  // bit i set when colour attachment i is attached
};

class Buffer {
 public:
  Buffer() = default;
  // Immutable storage of `bytes` (at least 4, so that an empty scene still binds), optionally
  // initialised; GL_DYNAMIC_STORAGE_BIT so that upload() works.
  static Buffer create(std::size_t bytes, const void* data = nullptr);
  GLuint id() const { return handle_.get(); }
  std::size_t size() const { return size_; }
  void upload(std::size_t offset, std::size_t bytes, const void* data);
  void download(std::size_t offset, std::size_t bytes, void* data) const;
  void bindBase(GLenum target, GLuint index) const;  // e.g. GL_SHADER_STORAGE_BUFFER, binding

 private:
  GlHandle<detail::deleteBuffer> handle_;
  std::size_t size_ = 0;
};

// A read-only typed view of a whole Buffer (GL 4.5 core, 8.1 glTextureBuffer), read in GLSL by
// texelFetch on a samplerBuffer. The scene's data reaches shaders this way rather than as SSBOs:
// llvmpipe runs each SSBO load as a loop over its SIMD lanes with a bounds test per lane, and a
// buffer texel fetch as one gather (docs/gl.md, "Scene data"); GPUs read both at the same speed.
// The buffer must outlive the view.
class BufferTexture {
 public:
  BufferTexture() = default;
  // Texels of `internalFormat` (GL_RGBA32F, GL_RGB32UI, ...), `texelBytes` each; throws an Error
  // naming `label` when their count exceeds the driver's GL_MAX_TEXTURE_BUFFER_SIZE.
  static BufferTexture create(const Buffer& buffer, GLenum internalFormat, std::size_t texelBytes,
                              std::string_view label);
  GLuint id() const { return handle_.get(); }
  void bind(GLuint unit) const;

 private:
  GlHandle<detail::deleteTexture> handle_;
};

class VertexArray {
 public:
  VertexArray() = default;
  static VertexArray create();
  GLuint id() const { return handle_.get(); }
  void bind() const;

 private:
  GlHandle<detail::deleteVertexArray> handle_;
};

// A linked program (see shader.h for loading). Uniform setters look the name up each call and
// ignore names the linker removed (location -1), as GL itself does.
class Program {
 public:
  Program() = default;
  explicit Program(GLuint id) : handle_(id) {}
  GLuint id() const { return handle_.get(); }
  explicit operator bool() const { return id() != 0; }
  void use() const;
  GLint location(const char* name) const;
  void set(const char* name, int value) const;
  void set(const char* name, std::uint32_t value) const;
  void set(const char* name, float value) const;
  void set(const char* name, const vec2& value) const;
  void set(const char* name, const ivec2& value) const;
  void set(const char* name, const vec3& value) const;
  void set(const char* name, const vec4& value) const;
  void set(const char* name, const mat4& value) const;

 private:
  GlHandle<detail::deleteProgram> handle_;
};

// GL_TIME_ELAPSED timer query: begin() ... end(), then milliseconds() once available.
class TimerQuery {
 public:
  TimerQuery() = default;
  static TimerQuery create();
  GLuint id() const { return handle_.get(); }
  void begin() const;
  void end() const;
  bool available() const;
  // The elapsed GPU time if the result has arrived, without waiting.
  std::optional<double> tryMilliseconds() const;
  // Waits for the result (GL_QUERY_RESULT blocks until the GPU is done).
  double milliseconds() const;

 private:
  GlHandle<detail::deleteQuery> handle_;
};

}  // namespace diptych::gl
