#include "samples/diptych/bias/study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "engine/core/error.h"
#include "engine/scene/load.h"
#include "engine/scene/world_geometry.h"
#include "passes/raster/shadow_map_frusta.h"
#include "samples/diptych/sweep/geometry.h"
#include "samples/diptych/sweep/sweep.h"

namespace diptych::cli {
namespace {

std::string join(const auto& values) {
  std::string out;
  for (const auto& v : values) out += (out.empty() ? "" : ",") + fmt::format("{}", v);
  return out;
}

// The amount range of a mode: from clear acne to clear peter-panning on the study's scenes.
// Constant bias is placed around its predicted threshold for a horizontal receiver under a
// directional light (theta = 90 - elevation), so every curve crosses inside the range.
std::pair<double, double> amountRange(const std::string& mode, const BiasStudyOptions& o,
                                      const Scene& scene) {
  if (mode == "slope") return {0.05, 20};
  if (mode == "normal_offset") return {0.02, 20};
  if (mode == "receiver_plane" || mode == "adaptive") return {1e-8, 1e-1};
  const WorldGeometry world = flattenScene(scene);
  const Light& light = scene.lights.at(std::size_t(o.light));
  if (light.type != LightType::Directional) {
    // Perspective and cube maps: the texel at the scene's centre (texelScale per unit of axis
    // depth, times the distance), at a 60 degree incidence; the rendered receivers refine it.
    double lo = 1e30, hi = 0;
    const double distance =
        glm::length(0.5f * (world.bounds.lo + world.bounds.hi) - light.position);
    for (int res : o.resolutions) {
      shadowmap::FrustumOptions fo;
      fo.resolution = res;
      const double w =
          shadowmap::fitLightFrusta(scene.lights, world.bounds, fo)[o.light].texelScale * distance;
      lo = std::min(lo, predictedThreshold("constant", w, 60.0));
      hi = std::max(hi, predictedThreshold("constant", w, 60.0));
    }
    return {lo / 10, hi * 20};
  }
  double lo = 1e30, hi = 0;
  for (int res : o.resolutions)
    for (double e : o.elevations) {
      const Scene s = sceneAt(scene, {{"elevation", e}}, o.light);
      shadowmap::FrustumOptions fo;
      fo.resolution = res;
      const double w = shadowmap::fitLightFrusta(s.lights, world.bounds, fo)[o.light].texelScale;
      const double b = predictedThreshold("constant", w, 90.0 - e);
      lo = std::min(lo, b);
      hi = std::max(hi, b);
    }
  return {lo / 10, hi * 20};
}

nlohmann::json curveSummary(const std::string& mode, const std::string& key,
                            const std::vector<nlohmann::json>& points) {
  std::vector<double> amounts, acne, predictedAcne;
  const nlohmann::json* best = nullptr;
  for (const auto& p : points) {
    amounts.push_back(key.empty() ? 0.0 : p["params"][key].get<double>());
    acne.push_back(p["signal"]["acne_rate"].get<double>());
    if (p["geometry"].contains("predicted_acne_rate"))
      predictedAcne.push_back(p["geometry"]["predicted_acne_rate"].get<double>());
    if (!best || p["signal"]["misclassified"].get<double>() <
                     (*best)["signal"]["misclassified"].get<double>())
      best = &p;
  }
  const auto& first = points.front();
  const double predicted = predictedThreshold(mode, first["geometry"]["texel_world"].get<double>(),
                                              first["geometry"]["incidence_deg"].get<double>());
  const double cross = key.empty() ? 0.0 : crossing(amounts, acne, 0.01);
  // Where the per-pixel texel model's acne rate drops below 1% (constant bias): the prediction
  // for receivers whose texel and incidence vary (point and spot lights, curved receivers).
  const double predictedCross = !key.empty() && predictedAcne.size() == points.size()
                                    ? crossing(amounts, predictedAcne, 0.01)
                                    : 0.0;
  nlohmann::json c = {
      {"resolution", first["params"].value("resolution", 2048)},
      {"elevation", first["params"].value("elevation", nlohmann::json())},
      {"filter", first["params"].value("filter", std::string("none"))},
      {"texel_world", first["geometry"]["texel_world"]},
      {"incidence_deg", first["geometry"]["incidence_deg"]},
      {"pixel_world", first["geometry"]["pixel_world"]},
      {"predicted_threshold", predicted > 0 ? nlohmann::json(predicted) : nlohmann::json()},
      {"acne_crossing_1pct", cross},
      {"crossing_over_predicted",
       predicted > 0 && cross > 0 ? nlohmann::json(cross / predicted) : nlohmann::json()},
      {"predicted_crossing_1pct",
       predictedCross > 0 ? nlohmann::json(predictedCross) : nlohmann::json()},
      {"crossing_over_predicted_crossing",
       predictedCross > 0 && cross > 0 ? nlohmann::json(cross / predictedCross) : nlohmann::json()},
      {"max_acne_rate", *std::max_element(acne.begin(), acne.end())},
      {"best",
       {{"amount", key.empty() ? nlohmann::json() : (*best)["params"][key]},
        {"index", (*best)["index"]},
        {"misclassified", (*best)["signal"]["misclassified"]},
        {"acne_rate", (*best)["signal"]["acne_rate"]},
        {"peter_panning_rate", (*best)["signal"]["peter_panning_rate"]},
        {"light_leak_rate", (*best)["signal"]["light_leak_rate"]},
        {"mean_abs_error", (*best)["signal"]["mean_abs_error"]},
        {"producer_ms", (*best)["producer_ms"]}}},
      {"indices", nlohmann::json::array()}};
  for (const auto& p : points) c["indices"].push_back(p["index"]);
  return c;
}

// A renderer ships one setting: the amount whose mean misclassification over every curve of the
// mode (resolutions, elevations, filters) is least, with its mean and its worst curve.
nlohmann::json oneAmountForAll(const std::string& key,
                               const std::map<std::string, std::vector<nlohmann::json>>& curves,
                               const std::vector<std::string>& order) {
  nlohmann::json best;
  const std::size_t amounts = curves.at(order.front()).size();
  for (std::size_t i = 0; i < amounts; ++i) {
    double sum = 0, worst = -1;
    std::string worstCurve;
    for (const auto& id : order) {
      const auto& points = curves.at(id);
      if (i >= points.size()) return nlohmann::json();
      const double e = points[i]["signal"]["misclassified"].get<double>();
      sum += e;
      if (e > worst) {
        worst = e;
        nlohmann::json params = points[i]["params"];
        if (!key.empty()) params.erase(key);
        worstCurve = params.dump();
      }
    }
    const double mean = sum / double(order.size());
    if (best.is_null() || mean < best["mean_misclassified"].get<double>())
      best = {
          {"amount", key.empty() ? nlohmann::json() : curves.at(order.front())[i]["params"][key]},
          {"mean_misclassified", mean},
          {"worst_misclassified", worst},
          {"worst_curve", worstCurve}};
  }
  return best;
}

}  // namespace

std::string biasAmountKey(const std::string& mode) {
  static const std::map<std::string, std::string> keys = {{"none", ""},
                                                          {"constant", "constant_bias"},
                                                          {"slope", "factor"},
                                                          {"normal_offset", "normal_scale"},
                                                          {"receiver_plane", "plane_epsilon"},
                                                          {"adaptive", "adaptive_epsilon"}};
  const auto it = keys.find(mode);
  if (it == keys.end())
    throw InputError("--modes", mode,
                     "unknown bias mode (known: none, constant, slope, normal_offset, "
                     "receiver_plane, adaptive)");
  return it->second;
}

double predictedThreshold(const std::string& mode, double texelWorld, double incidenceDeg) {
  // Constant bias along the light ray: a receiver tilted by theta changes its light depth by
  // w tan(theta) across one texel, and the map holds the depth at the texel centre, so the
  // receiver's own depth misses the stored one by up to (w/2) tan(theta) (Woo 1992 names the
  // self-shadowing; Isidoro 2006 and Dou et al. 2014 give this bound).
  if (mode == "constant") return 0.5 * texelWorld * std::tan(incidenceDeg * kRadiansPerDegree);
  // Normal offset delta = k w sin(theta) along n puts the point delta / cos(theta) above the
  // receiver along the light; clearing (w/2) tan(theta) needs k >= 1/2 whatever theta
  // (Holbert 2011 scales the offset by the texel and sin(theta) for exactly this reason).
  if (mode == "normal_offset") return 0.5;
  // Slope-scaled: the depth error is dz/du du + dz/dv dv with |du|, |dv| <= 1/2 texel, so a factor
  // of 1/2 of max(|dz/du|, |dz/dv|) suffices when the slope is along a map axis (1 diagonally).
  if (mode == "slope") return 0.5;
  return 0;  // none, receiver_plane, adaptive: no quantization term (float rounding only)
}

double crossing(const std::vector<double>& amounts, const std::vector<double>& rates,
                double level) {
  int above = -1;
  for (std::size_t i = 0; i < rates.size(); ++i) {
    if (rates[i] >= level) above = int(i);
    if (rates[i] < level && above >= 0 && above + 1 == int(i)) {
      const double a0 = amounts[above], a1 = amounts[i], r0 = rates[above], r1 = rates[i];
      const double t = (r0 - level) / (r0 - r1);
      return a0 > 0 && a1 > 0 ? std::exp(std::log(a0) + t * (std::log(a1) - std::log(a0)))
                              : a0 + t * (a1 - a0);
    }
  }
  return above < 0 ? 0.0 : -1.0;
}

nlohmann::json runBiasStudy(const BiasStudyOptions& o) {
  if (o.points < 2 || o.points > 200)
    throw InputError("--points", "", "need 2..200 amounts per mode");
  if (o.resolutions.empty()) throw InputError("--resolutions", "", "empty list");
  const Scene scene = loadScene(o.scene);
  if (o.light < 0 || o.light >= int(scene.lights.size()))
    throw InputError(o.scene, "lights", "the scene has no light " + std::to_string(o.light));
  const bool directional = scene.lights[o.light].type == LightType::Directional;
  // The thresholds scale with tan(90 - elevation): 0 at 90 and unbounded at 0, so both ends are
  // outside what a sweep of amounts can span.
  if (directional && o.elevations.empty())
    throw InputError("--elevations", "", "empty list (a directional light needs elevations)");
  for (double e : o.elevations)
    if (!(e > 0.0 && e < 90.0))
      throw InputError("--elevations", fmt::format("{}", e), "each must be in (0, 90) degrees");
  // Every mode's sweep, built (and so validated) before the first is rendered.
  std::vector<std::pair<std::string, SweepOptions>> sweeps;
  for (const std::string& mode : o.modes) {
    const std::string key = biasAmountKey(mode);
    SweepOptions s;
    s.scene = o.scene;
    s.producer = "visibility=shadow_map:bias=" + mode + (mode == "slope" ? ",units=0" : "");
    s.width = o.width;
    s.height = o.height;
    s.frames = o.frames;
    s.warmup = o.warmup;
    s.light = o.light;
    s.receiver = o.receiver;
    s.contact = o.contact;
    s.out = o.out / mode;
    s.label = "shadow-bias";
    if (directional && !o.elevations.empty())
      s.axes.push_back(parseAxis("elevation=" + join(o.elevations), AxisKind::Light));
    s.axes.push_back(parseAxis("resolution=" + join(o.resolutions), AxisKind::Pass));
    s.axes.push_back(parseAxis("filter=" + join(o.filters), AxisKind::Pass));
    if (!key.empty()) {
      const auto [lo, hi] = amountRange(mode, o, scene);
      s.axes.push_back(
          parseAxis(fmt::format("{}={:.6g}:{:.6g}:log{}", key, lo, hi, o.points), AxisKind::Pass));
    }
    sweeps.emplace_back(mode, std::move(s));
  }
  nlohmann::json summary = {{"scene", o.scene},
                            {"size", {o.width, o.height}},
                            {"directional", directional},
                            {"receiver", o.receiver},
                            {"modes", nlohmann::json::array()}};
  for (auto& [mode, s] : sweeps) {
    std::fprintf(stderr, "shadow-bias: mode %s -> %s\n", mode.c_str(), s.out.string().c_str());
    const nlohmann::json results = runSweep(s);
    const std::string key = biasAmountKey(mode);
    // One curve per (elevation, resolution, filter): points are in axis order, amount innermost.
    std::map<std::string, std::vector<nlohmann::json>> curves;
    std::vector<std::string> order;
    for (const auto& p : results["points"]) {
      nlohmann::json id = p["params"];
      if (!key.empty()) id.erase(key);
      if (!curves.count(id.dump())) order.push_back(id.dump());
      curves[id.dump()].push_back(p);
    }
    nlohmann::json m = {
        {"mode", mode}, {"key", key}, {"folder", mode}, {"curves", nlohmann::json::array()}};
    for (const auto& id : order) m["curves"].push_back(curveSummary(mode, key, curves[id]));
    m["points"] = results["points"];
    m["one_amount"] = oneAmountForAll(key, curves, order);
    summary["modes"].push_back(m);
  }
  return summary;
}

}  // namespace diptych::cli
