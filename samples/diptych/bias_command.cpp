#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "samples/diptych/bias/report.h"
#include "samples/diptych/bias/study.h"
#include "samples/diptych/contact_option.h"
#include "samples/diptych/parse_size.h"
#include "samples/diptych/sweep_command.h"

namespace diptych::cli {
namespace {

struct BiasCli {
  BiasStudyOptions options;
  std::string size = "320x240", out = "shadow-bias";
};

// One row per curve: predicted = (w/2) tan(theta) (or the mode's 1/2); model = where the
// per-pixel model's acne drops below 1% (constant bias); acne<1% = where the measured one does.
void printBiasSummary(const nlohmann::json& summary) {
  std::printf("%-15s %-20s %10s %10s %10s %7s %10s %8s %8s %8s %8s\n", "mode", "curve", "predicted",
              "model", "acne<1%", "ratio", "best", "miscl.", "acne", "p-pan", "leak");
  for (const auto& m : summary["modes"])
    for (const auto& c : m["curves"]) {
      std::string curve = std::to_string(c["resolution"].get<int>());
      if (c["elevation"].is_number()) curve += "@" + c["elevation"].dump() + "deg";
      if (c["filter"] != "none") curve += " " + c["filter"].get<std::string>();
      const auto& b = c["best"];
      // "-": no such number (no amount for none, no closed-form threshold, never crossed).
      auto text = [](const nlohmann::json& v, const char* format) {
        return v.is_number() && v.get<double>() > 0
                   ? fmt::format(fmt::runtime(format), v.get<double>())
                   : std::string("-");
      };
      std::printf("%-15s %-20s %10s %10s %10s %7s %10s %8s %8s %8s %8s\n",
                  m["mode"].get<std::string>().c_str(), curve.c_str(),
                  text(c["predicted_threshold"], "{:.4g}").c_str(),
                  text(c.value("predicted_crossing_1pct", nlohmann::json()), "{:.4g}").c_str(),
                  text(c["acne_crossing_1pct"], "{:.4g}").c_str(),
                  text(c["crossing_over_predicted"], "{:.2f}").c_str(),
                  text(b["amount"], "{:.4g}").c_str(),
                  fmt::format("{:.2f}%", 100 * b["misclassified"].get<double>()).c_str(),
                  fmt::format("{:.2f}%", 100 * b["acne_rate"].get<double>()).c_str(),
                  fmt::format("{:.2f}%", 100 * b["peter_panning_rate"].get<double>()).c_str(),
                  fmt::format("{:.2f}%", 100 * b["light_leak_rate"].get<double>()).c_str());
    }
}

}  // namespace

void addShadowBiasCommand(CLI::App& app, int& exitCode) {
  auto c = std::make_shared<BiasCli>();
  c->options.scene = std::string(DIPTYCH_SAMPLES_DIR) + "/scenes/shadow-sphere-sun.json";
  CLI::App* cmd = app.add_subcommand(
      "shadow-bias",
      "Sweep every shadow-map bias mode against rt_shadows: acne, peter-panning and leak curves "
      "beside the analytic thresholds, best bias per mode, report.html (docs/shadow-bias.md)");
  cmd->add_option("scene", c->options.scene,
                  "Scene; default: samples/scenes/shadow-sphere-sun.json");
  cmd->add_option("--modes", c->options.modes, "Bias modes")->delimiter(',')->capture_default_str();
  cmd->add_option("--resolutions", c->options.resolutions, "Shadow-map resolutions")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--elevations", c->options.elevations,
                  "Sun elevations, degrees (a directional light only)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--filters", c->options.filters, "Filters (none, pcf, poisson, pcss)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--points", c->options.points, "Amounts per mode (log spaced)")
      ->capture_default_str();
  cmd->add_option("--receiver", c->options.receiver, "Measure only this object's pixels");
  cmd->add_option("--light", c->options.light, "The light studied")->capture_default_str();
  addContactOption(cmd, c->options.contact);
  cmd->add_option("--frames", c->options.frames, "Measured frames per point")
      ->capture_default_str();
  cmd->add_option("--warmup", c->options.warmup, "Warm-up frames per point")->capture_default_str();
  cmd->add_option("--size", c->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--out", c->out, "Output folder (resumed when it holds this study)")
      ->capture_default_str();
  cmd->callback([c, &exitCode] {
    std::tie(c->options.width, c->options.height) = parseSize(c->size, 8192);
    c->options.out = c->out;
    const nlohmann::json summary = runBiasStudy(c->options);
    writeBiasReport(c->options.out, summary);
    printBiasSummary(summary);
    std::printf("wrote %s/report.html, summary.json, summary.csv, plots/\n", c->out.c_str());
    exitCode = 0;
  });
}

}  // namespace diptych::cli
