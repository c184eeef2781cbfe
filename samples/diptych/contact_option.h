#pragma once
// `--contact` of `sweep` and `shadow-bias`: the world distance under which an exactly shadowed
// pixel's occluder counts as touching it (peter-panning vs light leak, docs/shadow-bias.md).
#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace diptych::cli {

inline void addContactOption(CLI::App* cmd, double& contact) {
  cmd->add_option("--contact", contact,
                  "Contact distance, world units (default 1e-3 x the scene's diagonal)")
      ->check(CLI::Validator(
          [](std::string& v) {
            double d = -1;
            try {
              d = std::stod(v);
            } catch (const std::exception&) {
            }
            return d >= 0 && std::isfinite(d) ? std::string()
                                              : "'" + v + "' is not a finite distance >= 0";
          },
          "WORLD"));
}

}  // namespace diptych::cli
