// GLFW window context (GLX under X11 or Xvfb). GLFW_INCLUDE_NONE keeps <GL/gl.h> out; GL calls go
// through the loader with glfwGetProcAddress.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <mutex>
#include <string>

#include "engine/core/error.h"
#include "engine/gl/context.h"
#include "engine/gl/glfw_window.h"

namespace diptych::gl {
namespace {

// glfwInit/glfwTerminate are process-wide; windows are counted so the last one terminates.
std::mutex glfwMutex;
int glfwWindows = 0;
thread_local std::string lastGlfwError;

void onGlfwError(int code, const char* description) {
  lastGlfwError = "GLFW error " + std::to_string(code) + ": " + description;
}

// glfwTerminate closes the X display, and libGLX_mesa then dlcloses swrast_dri.so, whose
// one-time driver allocations stay referenced only from its unmapped globals: LeakSanitizer
// reports them from an "<unknown module>" that no suppression matches (issue 7). Marking every
// library loaded with the first window RTLD_NODELETE keeps the driver mapped until exit, so its
// globals are scanned and tests/lsan_suppressions.txt applies (as tests/unit/test_gl_glfw.cpp
// does for the unit tests); a process that opens a second window also reuses the loaded driver.
void keepLoadedLibrariesUntilExit() {
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        if (info->dlpi_name && *info->dlpi_name)  // RTLD_NOLOAD: only what is already mapped
          if (void* handle = dlopen(info->dlpi_name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE))
            dlclose(handle);
        return 0;
      },
      nullptr);
}

class GlfwContext final : public GlContext {
 public:
  GlfwContext(int width, int height, bool visible) {
    {
      std::lock_guard lock(glfwMutex);
      glfwSetErrorCallback(onGlfwError);
      lastGlfwError.clear();
      if (glfwWindows == 0 && !glfwInit()) {
        const char* display = std::getenv("DISPLAY");
        throw Error("cannot initialize GLFW" +
                    std::string(display && *display ? " on DISPLAY=" + std::string(display)
                                                    : " (DISPLAY is not set; run under xvfb-run "
                                                      "or use the osmesa context)") +
                    ": " + lastGlfwError);
      }
      ++glfwWindows;
    }
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, GLFW_TRUE);
    glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
    window_ = glfwCreateWindow(width, height, "Diptych", nullptr, nullptr);
    if (!window_) {
      release();
      throw Error("cannot create a GLFW window with an OpenGL 4.5 core context: " + lastGlfwError);
    }
    try {
      makeCurrentNative();
      initialize();
      keepLoadedLibrariesUntilExit();
    } catch (...) {
      release();
      throw;
    }
  }
  ~GlfwContext() override { release(); }

  void* getProcAddress(const char* name) const override {
    return reinterpret_cast<void*>(glfwGetProcAddress(name));
  }
  int width() const override { return framebufferSize().first; }
  int height() const override { return framebufferSize().second; }
  std::string_view name() const override { return "glfw"; }
  void swapBuffers() override { glfwSwapBuffers(window_); }
  GLFWwindow* window() const { return window_; }

 protected:
  void makeCurrentNative() override { glfwMakeContextCurrent(window_); }

 private:
  std::pair<int, int> framebufferSize() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
  }
  void release() {
    std::lock_guard lock(glfwMutex);
    if (window_) {
      if (glfwGetCurrentContext() == window_) glfwMakeContextCurrent(nullptr);
      glfwDestroyWindow(window_);
      window_ = nullptr;
    }
    if (--glfwWindows == 0) glfwTerminate();
  }

  GLFWwindow* window_ = nullptr;
};

}  // namespace

GLFWwindow* glfwWindowOf(GlContext& context) {
  auto* glfw = dynamic_cast<GlfwContext*>(&context);
  return glfw ? glfw->window() : nullptr;
}

std::unique_ptr<GlContext> createGlfwContext(int width, int height, bool visible) {
  return std::make_unique<GlfwContext>(width, height, visible);
}

}  // namespace diptych::gl
