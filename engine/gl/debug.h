#pragma once
// GL debug output routed to diptych::log(), prefixed with the label of the pass running on this
// thread. Frame-graph passes wrap their GL work in a ScopedGlLabel so that a driver message
// names the pass that caused it:
//   ScopedGlLabel label("gbuffer");   // messages read "[gl gbuffer] ..."
// Output is synchronous (GL_DEBUG_OUTPUT_SYNCHRONOUS), so a message arrives on the thread and
// inside the call that caused it, while the label is still in scope.
#include <cstdint>
#include <string>
#include <string_view>

namespace diptych::gl {

class ScopedGlLabel {
 public:
  explicit ScopedGlLabel(std::string_view label);
  ~ScopedGlLabel();
  ScopedGlLabel(const ScopedGlLabel&) = delete;
  ScopedGlLabel& operator=(const ScopedGlLabel&) = delete;

 private:
  std::string previous_;
};

// The innermost active label on this thread ("" when none).
const std::string& currentGlLabel();

// Number of GL_DEBUG_TYPE_ERROR messages received on this thread so far; tests compare it
// before and after GL work to assert that the work raised no GL error.
std::uint64_t glDebugErrorCount();

// Enables GL_DEBUG_OUTPUT on the current context with the logging callback (called by
// GlContext::initialize()).
void enableDebugOutput();

}  // namespace diptych::gl
