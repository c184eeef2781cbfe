#pragma once
// The engine's logger (spdlog, to stderr). Verbosity is set once by the program.
#include <spdlog/spdlog.h>

namespace diptych {
spdlog::logger& log();
void setLogLevel(spdlog::level::level_enum level);
}  // namespace diptych
