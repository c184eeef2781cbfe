#include "engine/core/log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace diptych {
spdlog::logger& log() {
  static std::shared_ptr<spdlog::logger> logger = [] {
    auto l = spdlog::stderr_color_mt("diptych");
    l->set_pattern("[%l] %v");
    l->set_level(spdlog::level::warn);
    return l;
  }();
  return *logger;
}
void setLogLevel(spdlog::level::level_enum level) {
  log().set_level(level);
}
}  // namespace diptych
