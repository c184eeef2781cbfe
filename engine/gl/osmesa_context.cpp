// OSMesa context (llvmpipe). This file includes <GL/osmesa.h>, which pulls in <GL/gl.h>, so it
// makes no GL calls itself: GlContext::initialize() does them through the loader.
#include <GL/osmesa.h>

#include <vector>

#include "engine/core/error.h"
#include "engine/gl/context.h"

namespace diptych::gl {
namespace {

class OsmesaContext final : public GlContext {
 public:
  OsmesaContext(int width, int height)
      : width_(width), height_(height), buffer_(std::size_t(width) * height) {
    // Depth 0: we render into our own FBOs; the owned RGBA buffer only makes the context current.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              0,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              4,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              5,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) {
      throw Error("OSMesaCreateContextAttribs failed to create an OpenGL 4.5 core context");
    }
    makeCurrentNative();
    initialize();
  }
  ~OsmesaContext() override {
    if (context_) OSMesaDestroyContext(context_);
  }

  void* getProcAddress(const char* name) const override {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
  }
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string_view name() const override { return "osmesa"; }

 protected:
  void makeCurrentNative() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
      throw Error("OSMesaMakeCurrent failed");
    }
  }

 private:
  int width_, height_;
  std::vector<std::uint32_t> buffer_;  // RGBA8 pixels
  OSMesaContext context_ = nullptr;
};

}  // namespace

std::unique_ptr<GlContext> createOsmesaContext(int width, int height) {
  return std::make_unique<OsmesaContext>(width, height);
}

}  // namespace diptych::gl
