#include "samples/diptych/compare/report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/log.h"
#include "engine/core/output_file.h"
#include "engine/graph/device_info.h"
#include "samples/diptych/compare/sdf_steps_report.h"

namespace diptych::cli {
namespace {

// The sRGB display version of a linear image, as the PNG writer would encode it (for panels).
Image display(const Image& linear) {
  Image out(linear.width, linear.height, 3);
  for (int y = 0; y < linear.height; ++y)
    for (int x = 0; x < linear.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const float v = linear.channels > c ? linear.at(x, y, c) : linear.at(x, y, 0);
        out.at(x, y, c) = std::isfinite(v) ? std::clamp(v, 0.f, 1.f) : 0.f;
      }
  return out;
}

// variant | reference | heat map, side by side (linear values; the PNG writer encodes sRGB).
Image panel(const Image& variant, const Image& reference, const Image& heatmap) {
  const Image parts[3] = {display(variant), display(reference), heatmap};
  const int gap = 4;
  Image out(3 * variant.width + 2 * gap, variant.height, 3, 1.f);
  for (int p = 0; p < 3; ++p)
    for (int y = 0; y < variant.height; ++y)
      for (int x = 0; x < variant.width; ++x)
        for (int c = 0; c < 3; ++c)
          out.at(p * (variant.width + gap) + x, y, c) =
              parts[p].at(x, y, std::min(c, parts[p].channels - 1));
  return out;
}

std::string number(const nlohmann::json& v) {
  return v.is_number() ? fmt::format("{:.4g}", v.get<double>()) : "-";
}

const char* kStyle =
    R"(body{font-family:system-ui,sans-serif;margin:24px;color:#222;max-width:1400px}
table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ccc;padding:3px 7px;text-align:right}
th{background:#f3f3f3}td:first-child{text-align:left}tr.pareto td:first-child{font-weight:bold;color:#b00}
.variant{display:flex;gap:16px;align-items:flex-start;margin:18px 0}.split{position:relative;display:inline-block}
.split img{display:block}.split img.top{position:absolute;top:0;left:0;clip-path:inset(0 calc(100% - var(--pos)) 0 0)}
.split input{width:100%}td.same-frame{text-align:left;color:#555}.caption{font-size:12px;color:#555}img.plot{max-width:100%})";

// One-time costs (results.json "one_time_ms", what -> ms, of the run or of a variant): their
// sum, and the list "what ms, ..." the report shows.
struct OneTimeCosts {
  double totalMs = 0;
  std::string parts;
};
OneTimeCosts oneTimeCosts(const nlohmann::json& costs) {
  OneTimeCosts c;
  for (const auto& [what, ms] : costs.items()) {
    c.totalMs += ms.get<double>();
    c.parts += fmt::format("{}{} {:.1f} ms", c.parts.empty() ? "" : ", ", what, ms.get<double>());
  }
  return c;
}

// "1.04x", and with timing rounds the range of the per-round paired ratios: "1.04x (0.94-1.19)".
std::string speedupText(const nlohmann::json& v) {
  std::string text = fmt::format("{:.2f}x", v["speedup_vs_reference"].get<double>());
  if (const auto r = v.value("speedup_rounds", nlohmann::json::array()); r.size() > 1) {
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    text += fmt::format(" ({:.2f}-{:.2f})", lo->get<double>(), hi->get<double>());
  }
  return text;
}

// Against the all-exact frame of the same run (exact / variant, paired per round): "1.15x" with
// the rounds' range as speedupText; "-" for that frame itself or a run without it.
std::string exactSpeedupText(const nlohmann::json& v) {
  if (!v.contains("speedup_vs_exact")) return "-";
  std::string text = fmt::format("{:.2f}x", v["speedup_vs_exact"].get<double>());
  if (const auto r = v.value("speedup_vs_exact_rounds", nlohmann::json::array()); r.size() > 1) {
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    text += fmt::format(" ({:.2f}-{:.2f})", lo->get<double>(), hi->get<double>());
  }
  return text;
}

// A variant compiled to an earlier one's frame (same_frame.h): "same frame as NAME (reason)".
std::string sameFrameText(const nlohmann::json& v) {
  return fmt::format("same frame as {} ({})", v["same_frame_as"].get<std::string>(),
                     v["same_frame_reason"].get<std::string>());
}

// A variant timed on its own whose pixels are an earlier one's (same_image.h): "same image as
// NAME (largest difference D): reason".
std::string sameImageText(const nlohmann::json& v) {
  return fmt::format(
      "same image as {} (largest difference {:.1e}): {}", v["same_image_as"].get<std::string>(),
      v["same_image_difference"].get<double>(), v["same_image_reason"].get<std::string>());
}

// Printed (and shown in the report) when the speed-ups come from one round. Identical frames
// measured 0.77-0.88x in one round on the loaded 2-core VM (docs/compare.md, "Timing rounds").
const char* kOneRoundNote =
    "Speed-ups from one timing round: a change of load between variants moves them, and on a "
    "shared machine differences within about +-20% are not distinguishable from that noise "
    "(docs/compare.md, \"Timing rounds\"); --rounds 3 times every variant in turn, pairs it "
    "with the reference of its round and shows the range beside each speed-up.";

}  // namespace

void printSummaryTable(const std::vector<ReportVariant>& variants, const std::string& metric,
                       int rounds) {
  const int width = rounds > 1 ? 20 : 9;  // "1.04x (0.94-1.19)"
  std::printf("%-36s %10s %*s %*s %10s %10s %8s %s\n", "variant", "total ms", width, "speedup",
              width, "vs exact", "rmse", metric.c_str(), "ssim", "pareto");
  for (const ReportVariant& r : variants) {
    const nlohmann::json& v = r.result;
    if (v.contains("same_frame_as")) {
      std::printf("%-36s %s\n", r.name.c_str(), sameFrameText(v).c_str());
      continue;
    }
    const auto& m = v["metrics"];
    std::printf(
        "%-36s %10.2f %*s %*s %10.4g %10.4g %8.4f %-6s%s\n", r.name.c_str(),
        v["total_ms"].get<double>(), width, speedupText(v).c_str(), width,
        exactSpeedupText(v).c_str(), m.value("rmse", 0.0), m.value(metric, 0.0),
        m.value("ssim", 0.0), v["pareto"].get<bool>() ? "*" : "",
        v.contains("same_image_as") ? (" = " + v["same_image_as"].get<std::string>()).c_str() : "");
  }
  // Below the table, why the rows marked "= NAME" show NAME's error: their pixels are its.
  for (const ReportVariant& r : variants)
    if (r.result.contains("same_image_as"))
      std::printf("%s: %s\n", r.name.c_str(), sameImageText(r.result).c_str());
  if (rounds == 1) std::printf("%s\n", kOneRoundNote);
}

std::string htmlEscape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

const char* reportStyle() {
  return kStyle;
}

std::vector<std::string> writeReport(const std::filesystem::path& dir, const nlohmann::json& header,
                                     const Image& reference, std::vector<ReportVariant>& variants,
                                     const std::string& plotMetric) {
  std::vector<std::string> written;
  auto image = [&](const std::string& rel, const Image& img) {
    writeImage(dir / rel, img);
    written.push_back(rel);
  };
  image("images/reference.exr", reference);
  image("images/reference.png", reference);
  nlohmann::json results = header;
  results["variants"] = nlohmann::json::array();
  for (ReportVariant& v : variants) {
    image("images/" + v.name + ".exr", v.image);
    image("images/" + v.name + ".png", v.image);
    image("heatmaps/" + v.name + ".png", v.heatmap);
    image("panels/" + v.name + ".png", panel(v.image, reference, v.heatmap));
    const std::string graphFile = "graphs/" + v.name + ".json";
    std::filesystem::create_directories(dir / "graphs");
    writeTextFile(dir / graphFile, v.result["graph"].dump(2));
    const std::string dotFile = "graphs/" + v.name + ".dot";
    writeTextFile(dir / dotFile, v.dot);
    written.push_back(graphFile);
    written.push_back(dotFile);
    v.result["files"] = {{"exr", "images/" + v.name + ".exr"},
                         {"png", "images/" + v.name + ".png"},
                         {"heatmap", "heatmaps/" + v.name + ".png"},
                         {"panel", "panels/" + v.name + ".png"},
                         {"graph", graphFile},
                         {"graph_dot", dotFile}};
    nlohmann::json entry = v.result;
    entry.erase("graph");  // kept in its own file
    results["variants"].push_back(entry);
  }
  writeTextFile(dir / "results.json", results.dump(2));
  written.push_back("results.json");

  // CSV: one row per variant; per-pass columns are the union over variants.
  std::vector<std::string> metricNames, passNames;
  for (const auto& v : results["variants"]) {
    for (const auto& [k, _] : v["metrics"].items())
      if (std::find(metricNames.begin(), metricNames.end(), k) == metricNames.end())
        metricNames.push_back(k);
    for (const auto& [k, _] : v["pass_ms"].items())
      if (std::find(passNames.begin(), passNames.end(), k) == passNames.end())
        passNames.push_back(k);
  }
  std::ostringstream csv;
  csv << "variant,same_frame_as,same_image_as,total_ms,speedup_vs_reference,speedup_vs_exact,"
         "saved_ms_vs_exact,rays,pareto,one_time_ms";
  for (const auto& m : metricNames) csv << "," << m;
  for (const auto& p : passNames) csv << ",ms:" << p;
  csv << "\n";
  for (const auto& v : results["variants"]) {
    csv << v["name"].get<std::string>() << "," << v.value("same_frame_as", "") << ","
        << v.value("same_image_as", "") << "," << v["total_ms"].get<double>() << ","
        << v["speedup_vs_reference"].get<double>() << ","
        << (v.contains("speedup_vs_exact") ? v["speedup_vs_exact"].dump() : "") << ","
        << (v.contains("saved_ms_vs_exact") ? v["saved_ms_vs_exact"].dump() : "") << ","
        << v["rays"].get<double>() << "," << (v["pareto"].get<bool>() ? 1 : 0) << ",";
    csv << oneTimeCosts(v.value("one_time_ms", nlohmann::json::object()))
               .totalMs;  // the sum (results.json lists them)
    for (const auto& m : metricNames)
      csv << "," << (v["metrics"].contains(m) ? v["metrics"][m].dump() : "");
    for (const auto& p : passNames)
      csv << "," << (v["pass_ms"].contains(p) ? v["pass_ms"][p].dump() : "");
    csv << "\n";
  }
  writeTextFile(dir / "results.csv", csv.str());
  written.push_back("results.csv");

  const std::string script = std::string(DIPTYCH_TOOLS_DIR) + "/plot_error_vs_time.py";
  const std::string command =
      fmt::format("/usr/bin/python3 '{}' '{}' '{}' '{}'", script, (dir / "results.json").string(),
                  plotMetric, (dir / "plot").string());
  if (std::system(command.c_str()) != 0)
    throw Error(
        "the error-vs-time plot failed (needs /usr/bin/python3 with matplotlib: Debian "
        "python3-matplotlib): " +
        command);
  written.push_back("plot.svg");
  written.push_back("plot.png");

  std::string page =
      "<!doctype html><html><head><meta charset=\"utf-8\"><title>Diptych "
      "comparison</title><style>" +
      std::string(kStyle) + "</style></head><body>\n";
  page += fmt::format(
      "<h1>Diptych comparison: {}</h1>\n<p>Reference: <b>{}</b> ({:.1f} ms{}). {}x{}. {}</p>\n",
      htmlEscape(header["scene"].get<std::string>()),
      htmlEscape(header["reference"]["spec"].get<std::string>()),
      header["reference"]["ms"].get<double>(),
      header["reference"].value("ms_cached", false) ? ", time from the cached run"
      : header["reference"]["cached"].get<bool>()   ? ", image cached"
                                                    : "",
      header["size"]["width"].get<int>(), header["size"]["height"].get<int>(),
      htmlEscape(header["method"].get<std::string>()));
  page +=
      fmt::format("<p id=\"devices\">Measured on {}. One-time costs, not in any frame: {}.</p>\n",
                  htmlEscape(deviceSummary(header["devices"])),
                  htmlEscape(oneTimeCosts(header["one_time_ms"]).parts));
  page +=
      "<h2>Error against time</h2>\n<img class=\"plot\" src=\"plot.svg\" alt=\"error versus time "
      "plot\">\n";
  page +=
      "<h2>Results</h2>\n<table id=\"results\"><tr><th>variant</th><th>total "
      "ms</th><th title=\"reference / variant\">speed-up</th><th title=\"the all-exact frame of "
      "this run / variant: what the technique saves against the exact producer it "
      "replaces\">vs exact</th><th>one-time ms</th><th>rays</th>";
  const std::vector<std::string> shown = {"rmse", "relmse",    "psnr",
                                          "ssim", "flip_mean", "flip_p95"};
  for (const auto& m : shown) page += "<th>" + m + "</th>";
  page += "<th>signal error</th></tr>\n";
  for (const auto& v : results["variants"]) {
    std::string signal;
    if (v["signals"].contains("visibility"))
      for (const auto& l : v["signals"]["visibility"])
        signal +=
            fmt::format("light {}: false shadow {:.2f}%, false lit {:.2f}%, boundary {:+.2f} px; ",
                        l["light"].get<int>(), 100 * l["false_shadow_rate"].get<double>(),
                        100 * l["false_lit_rate"].get<double>(),
                        l["mean_boundary_displacement_px"].get<double>());
    // Its pixels are an earlier variant's: said before the signal errors that show it.
    if (v.contains("same_image_as")) signal += sameImageText(v) + "; ";
    for (const char* slot : {"reflection", "transmission"})
      if (v["signals"].contains(slot))
        signal += fmt::format("{} rel. RMSE {:.3g}; ", slot,
                              v["signals"][slot]["relative_rmse"].get<double>());
    // Work the variant did once for the world (static shadow maps, prefiltered environments):
    // outside its frame time, listed in the cell's tooltip.
    const OneTimeCosts oneTime = oneTimeCosts(v.value("one_time_ms", nlohmann::json::object()));
    // With timing rounds, the range of the round totals beside their median.
    std::string spread;
    if (const auto r = v.value("total_ms_rounds", nlohmann::json::array()); r.size() > 1) {
      const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
      spread = fmt::format(" <span class=\"caption\">({:.1f}&ndash;{:.1f})</span>",
                           lo->get<double>(), hi->get<double>());
    }
    // A same-frame variant has no time of its own: the row says whose frame it is instead.
    const std::string timing =
        v.contains("same_frame_as")
            ? fmt::format("<td colspan=\"3\" class=\"same-frame\">{}</td>",
                          htmlEscape(sameFrameText(v)))
            : fmt::format("<td>{:.2f}{}</td><td>{}</td><td>{}</td>", v["total_ms"].get<double>(),
                          spread, htmlEscape(speedupText(v)), htmlEscape(exactSpeedupText(v)));
    page += fmt::format("<tr class=\"{}\"><td>{}</td>{}<td title=\"{}\">{:.1f}</td><td>{:.0f}</td>",
                        v["pareto"].get<bool>() ? "pareto" : "",
                        htmlEscape(v["name"].get<std::string>()), timing, htmlEscape(oneTime.parts),
                        oneTime.totalMs, v["rays"].get<double>());
    for (const auto& m : shown)
      page += "<td>" + number(v["metrics"].value(m, nlohmann::json())) + "</td>";
    page += "<td style=\"text-align:left\">" + htmlEscape(signal) + "</td></tr>\n";
  }
  page += "</table>\n<p class=\"caption\">Bold red: on the Pareto front of time and " +
          htmlEscape(plotMetric) +
          ". Files: <a href=\"results.json\">results.json</a>, <a "
          "href=\"results.csv\">results.csv</a>.</p>\n";
  if (header.value("rounds", 1) == 1)
    page += "<p class=\"caption\" id=\"one-round\">" + htmlEscape(kOneRoundNote) + "</p>\n";
  page += sdfStepSection(header.value("sdf_steps", nlohmann::json()));
  page +=
      "<h2>Images</h2>\n<p class=\"caption\">Drag a slider: left of it the variant, right of it "
      "the reference. "
      "Beside it, the FLIP error heat map.</p>\n";
  for (const auto& v : results["variants"]) {
    const std::string name = htmlEscape(v["name"].get<std::string>());
    const std::string caption =
        v.contains("same_frame_as")   ? name + ": " + htmlEscape(sameFrameText(v))
        : v.contains("same_image_as") ? name + ": " + htmlEscape(sameImageText(v))
                                      : name;
    page += fmt::format(
        "<div class=\"variant\"><div><div class=\"caption\">{1}</div><div class=\"split\" "
        "style=\"--pos:50%\">"
        "<img src=\"images/reference.png\" alt=\"reference\"><img class=\"top\" "
        "src=\"images/{0}.png\" alt=\"{0}\">"
        "<input type=\"range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"split position\" "
        "oninput=\"this.parentElement.style.setProperty('--pos', this.value + '%')\"></div></div>"
        "<div><div class=\"caption\">FLIP error</div><img src=\"heatmaps/{0}.png\" alt=\"{0} heat "
        "map\"></div></div>\n",
        name, caption);
  }
  // For readers and for the headless-browser test: mark the page once the plot has loaded.
  page +=
      "<script>window.addEventListener('load', function () {\n"
      "  var plot = document.querySelector('img.plot');\n"
      "  document.body.setAttribute('data-plot-loaded', String(!!plot && plot.naturalWidth > 0));\n"
      "  document.body.setAttribute('data-rows', String(document.querySelectorAll('#results "
      "tr').length - 1));\n"
      "});</script>\n";
  page += "</body></html>\n";
  writeTextFile(dir / "report.html", page);
  written.push_back("report.html");
  return written;
}

}  // namespace diptych::cli
