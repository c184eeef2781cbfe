#include "samples/diptych/check_command.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "engine/core/error.h"
#include "engine/core/output_file.h"
#include "engine/gl/context.h"
#include "engine/graph/render_world.h"
#include "engine/metrics/metrics.h"
#include "engine/rt/ray_probe.h"
#include "engine/scene/load.h"
#include "passes/registry.h"
#include "samples/diptych/check/cases.h"
#include "samples/diptych/compare/runner.h"
#include "samples/diptych/compare/variants.h"
#include "samples/diptych/parse_size.h"

namespace diptych::cli {
namespace {

struct CheckOptions {
  std::string scene, recipes = "hybrid,whitted,raster", size = "160x120", out = "check";
  std::string scales = "1e-6,1e-4,1e-2,1e2,1e4,1e6", offsets = "1e3,1e4,1e5";
  double failAbove = 0.01;
  bool noRebase = false;
};

std::vector<double> parseList(const std::string& option, const std::string& text, bool positive) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || !std::isfinite(v) || (positive ? !(v > 0) : false) ||
        std::fabs(v) > 1e30)
      throw InputError(option, "",
                       "expected comma-separated finite numbers" +
                           std::string(positive ? " > 0" : "") + ", got '" + item + "'");
    values.push_back(v);
  }
  return values;
}

// "hybrid" (built in), "whitted" (the exact reference), a name in samples/graphs, or a file.
Recipe namedRecipe(const std::string& name) {
  if (name == "hybrid") return defaultHybridRecipe();
  if (name == "whitted") return parseReference("whitted", builtinPasses()).recipe();
  if (name.find('/') == std::string::npos && name.find('.') == std::string::npos)
    return loadRecipe(std::string(DIPTYCH_SAMPLES_DIR) + "/graphs/" + name + ".json");
  return loadRecipe(name);
}

struct NonFinite {
  long nan = 0, inf = 0;
};
NonFinite countNonFinite(const Image& image) {
  NonFinite n;
  for (float v : image.pixels) {
    n.nan += std::isnan(v) ? 1 : 0;
    n.inf += std::isinf(v) ? 1 : 0;
  }
  return n;
}

// FLIP mean on the images with non-finite values replaced by 0 (they are counted separately).
double flipMean(Image test, Image reference) {
  for (Image* im : {&test, &reference})
    for (float& v : im->pixels)
      if (!std::isfinite(v)) v = 0.f;
  MetricOptions options;
  options.metrics = {"flip"};
  return computeMetrics(test, reference, options).at("flip_mean");
}

bool usesShadowMap(const Recipe& r) {
  for (const RecipePass& p : r.passes)
    if (p.type == "shadow_map") return true;
  return false;
}

std::string markdownReport(const nlohmann::json& j, const std::vector<std::string>& recipes) {
  std::string md = fmt::format("# diptych check: {}\n\n{}\n\n| case | rebased |",
                               j["scene"].get<std::string>(), j["method"].get<std::string>());
  for (const auto& r : recipes) md += " FLIP " + r + " |";
  md += " NaN/Inf | self hits / rays | lost / gained shadows | shadow-map warnings | verdict |\n|";
  for (std::size_t i = 0; i < recipes.size() + 7; ++i) md += "---|";
  md += "\n";
  for (const auto& c : j["cases"]) {
    md += fmt::format("| {} | {} |", c["name"].get<std::string>(),
                      c["rebased"].get<bool>() ? "yes" : "no");
    long nonFinite = 0;
    for (const auto& r : recipes) {
      const auto& rr = c["recipes"][r];
      md += fmt::format(" {:.5f} |", rr["flip_mean"].get<double>());
      nonFinite += rr["nan"].get<long>() + rr["inf"].get<long>();
    }
    const auto& p = c["probe"];
    md += fmt::format(" {} | {} / {} | {} / {} | {} | {} |\n", nonFinite,
                      p["self_hits"].get<long>(), p["secondary_rays"].get<long>(),
                      p["lost_shadows"].get<long>(), p["gained_shadows"].get<long>(),
                      c["shadow_map_warnings"].size(), c["pass"].get<bool>() ? "pass" : "FAIL");
  }
  for (const auto& c : j["cases"])
    for (const auto& w : c["shadow_map_warnings"])
      md += fmt::format("\n- {}: {}", c["name"].get<std::string>(), w.get<std::string>());
  return md + "\n";
}

int runCheck(const CheckOptions& o) {
  const auto [width, height] = parseSize(o.size, 4096);
  const std::vector<double> scales = parseList("--scales", o.scales, true);
  const std::vector<double> offsets = parseList("--offsets", o.offsets, false);
  if (!(o.failAbove >= 0.0) || !std::isfinite(o.failAbove))
    throw InputError("--fail-above", "", "expected a finite FLIP bound >= 0");
  std::vector<std::string> recipeNames;
  std::vector<Recipe> recipes;
  {
    std::stringstream in(o.recipes);
    for (std::string name; std::getline(in, name, ',');) {
      recipeNames.push_back(name);
      recipes.push_back(namedRecipe(name));
    }
  }
  if (recipes.empty()) throw InputError("--recipes", "", "no recipe given");
  bool anyShadowMap = false;
  for (const Recipe& r : recipes) anyShadowMap = anyShadowMap || usesShadowMap(r);

  const Scene base = loadScene(o.scene);
  const std::vector<CheckCase> cases = checkCases(scales, offsets);
  std::filesystem::create_directories(o.out);
  std::unique_ptr<gl::GlContext> context =
      gl::createContext(gl::ContextKind::Osmesa, width, height);

  struct Reference {
    std::map<std::string, Image> images;
    RayProbe probe;
  };
  std::map<bool, Reference> references;  // by grazing
  nlohmann::json j;
  j["scene"] = o.scene;
  j["size"] = {width, height};
  j["method"] = fmt::format(
      "Each case renders the scene scaled about the origin (point/spot intensities x s^2), "
      "translated on x, or seen by a grazing camera, at {}x{}, one frame per recipe, and "
      "compares it with the untransformed render of the same camera: FLIP mean (LDR/HDR-FLIP "
      "as engine/metrics picks, 67 ppd, non-finite pixels zeroed and counted separately). "
      "Secondary rays: one pixel-centre primary ray per pixel, its shadow rays and "
      "mirror/refraction rays traced with Embree; a self hit is a secondary ray whose closest "
      "hit is its own triangle; lost/gained shadows are light-pixel pairs shadowed in the "
      "reference but lit in the case, or the converse. Pass: every FLIP mean <= {:g}, no "
      "NaN/Inf, no self hits.",
      width, height, o.failAbove);
  j["cases"] = nlohmann::json::array();
  const int total = int(cases.size() * recipes.size());
  int done = 0;
  bool allPass = true;
  for (const CheckCase& c : cases) {
    glm::dvec3 origin(0.0);
    Scene scene = caseScene(base, c, !o.noRebase, origin);
    const bool rebased = origin != glm::dvec3(0.0);
    RenderWorld world(scene, context.get());
    const FrameSettings frame{.width = width, .height = height, .camera = scene.camera};
    nlohmann::json jc;
    jc["name"] = c.name;
    jc["scale"] = c.scale;
    jc["offset_x"] = c.offset;
    jc["grazing"] = c.grazing;
    jc["rebased"] = rebased;
    const RayProbe probe =
        probeSecondaryRays(scene, world.geometry(), world.rtScene(), scene.camera, width, height);
    Reference& ref = references[c.grazing];
    if (c.reference()) ref.probe = probe;
    const ShadowDifference shadows = compareShadows(probe, ref.probe);
    jc["probe"] = {{"primary_hits", probe.primaryHits}, {"secondary_rays", probe.secondaryRays},
                   {"self_hits", probe.selfHits},       {"lost_shadows", shadows.lost},
                   {"gained_shadows", shadows.gained},  {"compared", shadows.compared}};
    jc["shadow_map_warnings"] =
        anyShadowMap ? shadowMapDepthWarnings(scene, 2048) : std::vector<std::string>{};
    bool pass = probe.selfHits == 0;
    for (std::size_t r = 0; r < recipes.size(); ++r) {
      progress("check", done, total, c.name + " / " + recipeNames[r]);
      const std::string output = recipes[r].outputs.at(0);
      GraphRun run = runGraph(recipes[r], world, frame, {output}, 0, 1);
      Image image = run.outputs.at(output).toImage();
      if (c.reference()) ref.images[recipeNames[r]] = image;
      const NonFinite nf = countNonFinite(image);
      const double flip = flipMean(image, ref.images.at(recipeNames[r]));
      pass = pass && nf.nan == 0 && nf.inf == 0 && flip <= o.failAbove;
      jc["recipes"][recipeNames[r]] = {
          {"flip_mean", flip}, {"nan", nf.nan}, {"inf", nf.inf}, {"cpu_ms", run.totalMs}};
      writeImage(std::filesystem::path(o.out) /
                     fmt::format("case{:02d}-{}.png", j["cases"].size(), recipeNames[r]),
                 image, ToneMap{});
      ++done;
    }
    jc["pass"] = pass;
    allPass = allPass && pass;
    j["cases"].push_back(jc);
  }
  progress("check", total, total, "done");
  j["pass"] = allPass;
  const std::filesystem::path dir(o.out);
  writeTextFile(dir / "check.json", j.dump(2));
  const std::string md = markdownReport(j, recipeNames);
  writeTextFile(dir / "check.md", md);
  std::fputs(md.c_str(), stdout);
  std::printf("wrote %s and %s\n", (dir / "check.json").string().c_str(),
              (dir / "check.md").string().c_str());
  return allPass ? 0 : 3;
}

}  // namespace

void addCheckCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<CheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "check", "Numerics suite: the scene scaled, translated and at grazing view vs as given");
  cmd->add_option("scene", options->scene, "Scene file (.json, .gltf, .glb)")->required();
  cmd->add_option("--recipes", options->recipes,
                  "Comma-separated recipes: hybrid, whitted, a samples/graphs name, or a file")
      ->capture_default_str();
  cmd->add_option("--scales", options->scales, "Uniform scales about the origin")
      ->capture_default_str();
  cmd->add_option("--offsets", options->offsets, "Translations along +x")->capture_default_str();
  cmd->add_option("--size", options->size, "Image size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--out", options->out, "Output folder (check.json, check.md, case images)")
      ->capture_default_str();
  cmd->add_option("--fail-above", options->failAbove,
                  "FLIP mean above which a case fails (exit status 3)")
      ->capture_default_str();
  cmd->add_flag("--no-rebase", options->noRebase,
                "Keep far scenes in absolute float coordinates (to measure what rebasing buys)");
  cmd->callback([options, &exitCode] { exitCode = runCheck(*options); });
}

}  // namespace diptych::cli
