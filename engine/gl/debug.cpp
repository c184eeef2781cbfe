#include "engine/gl/debug.h"

#include <cstring>

#include "engine/core/log.h"
#include "engine/gl/loader.h"

namespace diptych::gl {
namespace {

thread_local std::string activeLabel;
thread_local std::uint64_t errorCount = 0;

const char* sourceName(GLenum source) {
  switch (source) {
    case GL_DEBUG_SOURCE_API:
      return "api";
    case GL_DEBUG_SOURCE_WINDOW_SYSTEM:
      return "window-system";
    case GL_DEBUG_SOURCE_SHADER_COMPILER:
      return "shader-compiler";
    case GL_DEBUG_SOURCE_THIRD_PARTY:
      return "third-party";
    case GL_DEBUG_SOURCE_APPLICATION:
      return "application";
    default:
      return "other";
  }
}

const char* typeName(GLenum type) {
  switch (type) {
    case GL_DEBUG_TYPE_ERROR:
      return "error";
    case GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR:
      return "deprecated";
    case GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR:
      return "undefined-behavior";
    case GL_DEBUG_TYPE_PORTABILITY:
      return "portability";
    case GL_DEBUG_TYPE_PERFORMANCE:
      return "performance";
    case GL_DEBUG_TYPE_MARKER:
      return "marker";
    default:
      return "other";
  }
}

void APIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                             const GLchar* message, const void*) {
  const std::string_view text(message, length >= 0 ? std::size_t(length) : std::strlen(message));
  // Errors are errors; undefined behaviour of high severity is a warning; the rest (performance
  // hints, shader-compiler chatter, notifications) is debug detail.
  spdlog::level::level_enum level = spdlog::level::debug;
  if (type == GL_DEBUG_TYPE_ERROR) {
    level = spdlog::level::err;
    ++errorCount;
  } else if (severity == GL_DEBUG_SEVERITY_HIGH) {
    level = spdlog::level::warn;
  }
  log().log(level, "[gl {}] {} {} #{}: {}", activeLabel.empty() ? "-" : activeLabel,
            sourceName(source), typeName(type), id, text);
}

}  // namespace

ScopedGlLabel::ScopedGlLabel(std::string_view label) : previous_(std::move(activeLabel)) {
  activeLabel = std::string(label);
}

ScopedGlLabel::~ScopedGlLabel() {
  activeLabel = std::move(previous_);
}

const std::string& currentGlLabel() {
  return activeLabel;
}

std::uint64_t glDebugErrorCount() {
  return errorCount;
}

void enableDebugOutput() {
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(onDebugMessage, nullptr);
  // Every message is delivered; the callback picks the log level.
  glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

}  // namespace diptych::gl
