#include "samples/diptych/sweep_command.h"

#include <cmath>
#include <cstdio>
#include <tuple>

#include "engine/core/error.h"
#include "samples/diptych/contact_option.h"
#include "samples/diptych/parse_size.h"
#include "samples/diptych/shading_option.h"
#include "samples/diptych/sweep/sweep.h"

namespace diptych::cli {

namespace {

struct SweepCli {
  SweepOptions options;
  std::string size = "320x240", out = "sweep";
  std::vector<std::string> vary, varyLight, varyView;
};

void printSweepSummary(const nlohmann::json& results) {
  for (const auto& p : results["points"]) {
    std::string params;
    for (const auto& [k, v] : p["params"].items())
      params += k + "=" + (v.is_string() ? v.get<std::string>() : v.dump()) + " ";
    const auto& s = p["signal"];
    if (s.contains("acne_rate"))
      std::printf("%-60s acne %6.2f%%  peter-panning %6.2f%%  leak %6.2f%%  MAE %.4f  %8.2f ms\n",
                  params.c_str(), 100 * s["acne_rate"].get<double>(),
                  100 * s["peter_panning_rate"].get<double>(),
                  100 * s["light_leak_rate"].get<double>(), s["mean_abs_error"].get<double>(),
                  p["producer_ms"].get<double>());
    else
      std::printf("%-60s rel. RMSE %.4g  %8.2f ms\n", params.c_str(), s.value("relative_rmse", 0.0),
                  p["producer_ms"].get<double>());
  }
}

}  // namespace

void addSweepCommand(CLI::App& app, int& exitCode) {
  auto c = std::make_shared<SweepCli>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Cartesian product of a producer's parameters (and the light direction), each point "
      "against the exact producer of the slot: results.json/csv, resumable");
  cmd->add_option("scene", c->options.scene, "Scene (.json, .gltf, .glb)")->required();
  cmd->add_option("--slot", c->options.producer, "SLOT=TYPE[:key=value,...]: the swept producer")
      ->required();
  cmd->add_option("--vary", c->vary, "KEY=V1,V2,... | KEY=START:STOP:STEP | KEY=START:STOP:logN");
  cmd->add_option("--vary-light", c->varyLight,
                  "elevation=... | azimuth=... (degrees; a directional light)");
  cmd->add_option("--vary-view", c->varyView,
                  "size=WxH,... | camera_azimuth=... (degrees) | camera_distance=... (factor)");
  cmd->add_option("--light", c->options.light, "The light classified and moved")
      ->capture_default_str();
  addShadingOption(cmd, c->options.shading);
  cmd->add_option("--receiver", c->options.receiver, "Measure only this object's pixels");
  cmd->add_option("--band", c->options.band, "Boundary band, px")->capture_default_str();
  cmd->add_option("--reach", c->options.reach,
                  "Peter-panning reach from a contact, px (farther: leak)")
      ->capture_default_str();
  addContactOption(cmd, c->options.contact);
  cmd->add_option("--frames", c->options.frames, "Measured frames per point (median)")
      ->capture_default_str();
  cmd->add_option("--warmup", c->options.warmup, "Warm-up frames per point")->capture_default_str();
  cmd->add_option("--size", c->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--out", c->out, "Output folder (resumed when it holds this sweep)")
      ->capture_default_str();
  cmd->callback([c, &exitCode] {
    std::tie(c->options.width, c->options.height) = parseSize(c->size, kMaxSweepSide);
    c->options.out = c->out;
    c->options.axes.clear();
    for (const auto& v : c->vary) c->options.axes.push_back(parseAxis(v, AxisKind::Pass));
    for (const auto& v : c->varyLight) c->options.axes.push_back(parseAxis(v, AxisKind::Light));
    for (const auto& v : c->varyView) c->options.axes.push_back(parseAxis(v, AxisKind::View));
    const nlohmann::json results = runSweep(c->options);
    printSweepSummary(results);
    std::printf("%s\nwrote %s/results.json, %s/results.csv\n",
                results["method"].get<std::string>().c_str(), c->out.c_str(), c->out.c_str());
    exitCode = 0;
  });
}

}  // namespace diptych::cli
