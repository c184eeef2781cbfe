#include "samples/diptych/bias/report.h"

#include <fmt/format.h>

#include <cstdlib>

#include "engine/core/error.h"
#include "engine/core/output_file.h"
#include "samples/diptych/compare/report.h"

namespace diptych::cli {
namespace {

std::string num(const nlohmann::json& v, const char* format = "{:.3g}") {
  return v.is_number() ? fmt::format(fmt::runtime(format), v.get<double>()) : "-";
}
std::string pct(const nlohmann::json& v) {
  return v.is_number() ? fmt::format("{:.2f}%", 100 * v.get<double>()) : "-";
}
std::string curveName(const nlohmann::json& c) {
  std::string s = fmt::format("{} map", c["resolution"].get<int>());
  if (c["elevation"].is_number()) s += fmt::format(", {:g}° sun", c["elevation"].get<double>());
  if (c["filter"] != "none") s += ", " + c["filter"].get<std::string>();
  return s;
}

std::string biasCsv(const nlohmann::json& summary) {
  std::string csv =
      "mode,key,resolution,elevation,filter,texel_world,incidence_deg,predicted_threshold,"
      "acne_crossing_1pct,crossing_over_predicted,predicted_crossing_1pct,max_acne_rate,best_"
      "amount,best_misclassified,"
      "best_acne_rate,best_peter_panning_rate,best_light_leak_rate,best_mean_abs_error,"
      "best_producer_ms\n";
  for (const auto& m : summary["modes"])
    for (const auto& c : m["curves"]) {
      const auto& b = c["best"];
      csv += fmt::format(
          "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
          m["mode"].get<std::string>(), m["key"].get<std::string>(), c["resolution"].dump(),
          c["elevation"].dump(), c["filter"].get<std::string>(), c["texel_world"].dump(),
          c["incidence_deg"].dump(), c["predicted_threshold"].dump(),
          c["acne_crossing_1pct"].dump(), c["crossing_over_predicted"].dump(),
          c.value("predicted_crossing_1pct", nlohmann::json()).dump(), c["max_acne_rate"].dump(),
          b["amount"].dump(), b["misclassified"].dump(), b["acne_rate"].dump(),
          b["peter_panning_rate"].dump(), b["light_leak_rate"].dump(), b["mean_abs_error"].dump(),
          b["producer_ms"].dump());
    }
  return csv;
}

const char* kLegend =
    "<p class=\"caption\">Class maps: <span style=\"background:#ccc\">&nbsp;lit&nbsp;</span> "
    "<span style=\"background:#4e4e4e;color:#fff\">&nbsp;shadow&nbsp;</span> "
    "<span style=\"background:#f41a1a;color:#fff\">&nbsp;acne&nbsp;</span> "
    "<span style=\"background:#1a7cff;color:#fff\">&nbsp;peter-panning&nbsp;</span> "
    "<span style=\"background:#ffee00\">&nbsp;light leak&nbsp;</span> "
    "<span style=\"background:#e700e7;color:#fff\">&nbsp;wrong inside the boundary "
    "band&nbsp;</span>, black: background or another object.</p>\n";

}  // namespace

std::vector<std::string> writeBiasReport(const std::filesystem::path& dir,
                                         const nlohmann::json& summary) {
  writeTextFile(dir / "summary.json", summary.dump(1));
  writeTextFile(dir / "summary.csv", biasCsv(summary));
  const std::string script = std::string(DIPTYCH_BIAS_TOOLS_DIR) + "/plot_shadow_bias.py";
  const std::string command =
      fmt::format("/usr/bin/python3 '{}' '{}' '{}'", script, (dir / "summary.json").string(),
                  (dir / "plots").string());
  if (std::system(command.c_str()) != 0)
    throw Error(
        "the shadow-bias plots failed (needs /usr/bin/python3 with matplotlib: Debian "
        "python3-matplotlib): " +
        command);

  std::string page =
      "<!doctype html><html><head><meta charset=\"utf-8\"><title>Diptych shadow "
      "bias</title><style>" +
      std::string(reportStyle()) +
      "\nimg.cls{width:240px;image-rendering:pixelated}</style></head><body>\n";
  page += fmt::format(
      "<h1>Shadow-map bias: {}</h1>\n<p>{}x{} pixels. Every point: the <code>shadow_map</code> "
      "visibility beside the exact <code>rt_shadows</code> visibility on the same G-buffer{}. "
      "Acne = false shadow outside the 2-pixel boundary band, as a share of exactly lit pixels; "
      "peter-panning = false light outside the band within 16 px of a contact (an exactly "
      "shadowed pixel whose exact shadow ray meets its occluder within the contact distance) on "
      "the same object, leak = other false light, both as shares of exactly shadowed pixels "
      "(docs/shadow-bias.md). Best = least "
      "misclassified (acne + peter-panning + leak over all pixels outside the band). Files: <a "
      "href=\"summary.json\">summary.json</a>, <a href=\"summary.csv\">summary.csv</a>, each "
      "mode's MODE/results.json and results.csv.</p>\n",
      htmlEscape(summary["scene"].get<std::string>()), summary["size"][0].get<int>(),
      summary["size"][1].get<int>(),
      summary["receiver"].get<std::string>().empty()
          ? ""
          : ", measured on '" + htmlEscape(summary["receiver"].get<std::string>()) + "' only");

  // The best of every mode per configuration: the table the docs quote.
  page +=
      "<h2>Best amount per mode</h2>\n<table id=\"best\"><tr><th>mode</th><th>curve</th>"
      "<th>texel (world)</th><th>incidence</th><th>predicted threshold</th><th>texel model: acne "
      "&lt; 1% from</th><th>measured acne &lt; 1% from</th><th>ratio</th><th>best "
      "amount</th><th>misclassified</th><th>acne</th>"
      "<th>peter-panning</th><th>leak</th><th>MAE</th><th>ms</th></tr>\n";
  for (const auto& m : summary["modes"])
    for (const auto& c : m["curves"]) {
      const auto& b = c["best"];
      const double cross = c["acne_crossing_1pct"].get<double>();
      page += fmt::format(
          "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}°</td><td>{}</td><td>{}</td><td>{}</td>"
          "<td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
          "</tr>\n",
          htmlEscape(m["mode"].get<std::string>()), htmlEscape(curveName(c)), num(c["texel_world"]),
          num(c["incidence_deg"], "{:.1f}"), num(c["predicted_threshold"]),
          num(c.value("predicted_crossing_1pct", nlohmann::json())),
          cross > 0 ? num(cross) : (cross == 0 ? "never acne" : "never below"),
          num(c["crossing_over_predicted"], "{:.2f}"), num(b["amount"]), pct(b["misclassified"]),
          pct(b["acne_rate"]), pct(b["peter_panning_rate"]), pct(b["light_leak_rate"]),
          num(b["mean_abs_error"]), num(b["producer_ms"], "{:.1f}"));
    }
  page += "</table>\n";
  page +=
      "<h2>Error against time</h2>\n<img class=\"plot\" src=\"plots/time.svg\" alt=\"error "
      "against time\">\n";
  for (const auto& m : summary["modes"]) {
    const std::string mode = m["mode"].get<std::string>();
    page += "<h2>" + htmlEscape(mode) + "</h2>\n";
    if (!m["key"].get<std::string>().empty())
      page += "<img class=\"plot\" src=\"plots/" + mode + ".svg\" alt=\"" + mode + " curves\">\n";
    // Heat maps of the classes: smallest amount, best, largest, of the first curve.
    const auto& c = m["curves"][0];
    const auto& idx = c["indices"];
    page += "<div class=\"variant\">";
    std::vector<std::pair<std::string, int>> shown = {{"smallest amount", idx.front().get<int>()}};
    if (idx.size() > 1) {
      shown.push_back({"best", c["best"]["index"].get<int>()});
      shown.push_back({"largest amount", idx.back().get<int>()});
    }
    for (const auto& [what, i] : shown) {
      const auto& p = m["points"][std::size_t(i)];
      const std::string amount = m["key"].get<std::string>().empty()
                                     ? ""
                                     : " = " + num(p["params"][m["key"].get<std::string>()]);
      page += fmt::format(
          "<div><div class=\"caption\">{}, {}{}: acne {}, peter-panning {}, leak {}</div><img "
          "class=\"cls\" src=\"{}/{}\" alt=\"classes\"></div>",
          htmlEscape(curveName(c)), what, htmlEscape(m["key"].get<std::string>() + amount),
          pct(p["signal"]["acne_rate"]), pct(p["signal"]["peter_panning_rate"]),
          pct(p["signal"]["light_leak_rate"]), mode, p["files"]["classes"].get<std::string>());
    }
    // The contacts that tell peter-panning from leak (the same for every amount of the curve).
    const auto& first = m["points"][std::size_t(idx.front().get<int>())];
    if (first["files"].contains("contacts"))
      page += fmt::format(
          "<div><div class=\"caption\">{}: contacts (red), {} px of them</div>"
          "<img class=\"cls\" "
          "src=\"{}/{}\" alt=\"contacts\"></div>",
          htmlEscape(curveName(c)), first["signal"].value("contact_pixels", 0LL), mode,
          first["files"]["contacts"].get<std::string>());
    page += "</div>\n" + std::string(kLegend);
  }
  page +=
      "<script>window.addEventListener('load', function () {\n"
      "  var plots = document.querySelectorAll('img.plot, img.cls'), ok = plots.length > 0;\n"
      "  plots.forEach(function (p) { ok = ok && p.naturalWidth > 0; });\n"
      "  document.body.setAttribute('data-plots-loaded', String(ok));\n"
      "  document.body.setAttribute('data-rows', String(document.querySelectorAll('#best "
      "tr').length - 1));\n"
      "});</script>\n</body></html>\n";
  writeTextFile(dir / "report.html", page);
  return {"summary.json", "summary.csv", "plots", "report.html"};
}

}  // namespace diptych::cli
