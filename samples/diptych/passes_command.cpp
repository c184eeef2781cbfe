#include "samples/diptych/passes_command.h"

#include <fmt/format.h>

#include <memory>
#include <string>

#include "engine/graph/scene_needs.h"
#include "passes/registry.h"
#include "passes/slots.h"

namespace diptych::cli {
namespace {

std::string layerRule(const TechniqueSlot& s) {
  return s.layerPerLight ? "one layer per scene light" : "one layer";
}

std::string vec4Text(vec4 v) {
  return v.x == v.y && v.y == v.z && v.z == v.w
             ? fmt::format("{}", v.x)
             : fmt::format("({}, {}, {}, {})", v.x, v.y, v.z, v.w);
}

std::string domainOf(const PassTypeInfo& t) {
  return t.create()->domain() == Domain::Gl ? "gl" : "cpu";
}

void printText(const PassRegistry& registry) {
  fmt::print("Technique slots (passes/slots.cpp):\n");
  for (const TechniqueSlot& s : techniqueSlots()) {
    fmt::print("\n  {}: {}\n", s.name, s.meaning);
    fmt::print("    signal '{}' {}, {}, fallback {}; feeds shade's '{}'; culled without {}\n",
               s.signal, formatName(s.format), layerRule(s), vec4Text(s.fallback), s.shadeInput,
               sceneNeedName(s.need));
    fmt::print("    producers: ");
    const char* sep = "";
    for (const PassTypeInfo* t : registry.producersOf(s.name)) {
      fmt::print("{}{}{}", sep, t->name, t->name == s.exact ? " (exact)" : "");
      sep = ", ";
    }
    fmt::print("\n");
  }
  fmt::print("\nPass types (passes/registry.cpp):\n");
  for (const PassTypeInfo& t : registry.all()) {
    fmt::print("\n  {} [{}{}]: {}\n", t.name, domainOf(t), t.slot.empty() ? "" : ", slot " + t.slot,
               t.summary);
    for (const ParamSpec& p : t.params)
      fmt::print("    {:<17} {} ({})\n", p.name, p.doc, p.describe());
  }
}

void printMarkdown(const PassRegistry& registry) {
  fmt::print(
      "| slot | shade input | signal (output name) | format | layers | meaning | fallback "
      "| culled without |\n|---|---|---|---|---|---|---|---|\n");
  for (const TechniqueSlot& s : techniqueSlots())
    fmt::print("| {} | `{}` | `{}` | {} | {} | {} | {} | {} |\n", s.name, s.shadeInput, s.signal,
               formatName(s.format), layerRule(s), s.meaning, vec4Text(s.fallback),
               sceneNeedName(s.need));
  fmt::print("\n| slot | pass type | domain | what | parameters |\n|---|---|---|---|---|\n");
  for (const TechniqueSlot& s : techniqueSlots())
    for (const PassTypeInfo* t : registry.producersOf(s.name)) {
      std::string params;
      for (const ParamSpec& p : t->params)
        params += (params.empty() ? "" : "; ") + fmt::format("`{}`: {}", p.name, p.describe());
      fmt::print("| {} | `{}`{} | {} | {} | {} |\n", s.name, t->name,
                 t->name == s.exact ? " (exact)" : "", domainOf(*t), t->summary,
                 params.empty() ? "-" : params);
    }
}

}  // namespace

void addPassesCommand(CLI::App& app, int& exitCode) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand(
      "passes", "List technique slots, pass types and their parameters (from the registry)");
  cmd->add_flag("--markdown", *markdown, "Print the tables of docs/technique-slots.md");
  cmd->callback([markdown, &exitCode] {
    if (*markdown)
      printMarkdown(builtinPasses());
    else
      printText(builtinPasses());
    exitCode = 0;
  });
}

}  // namespace diptych::cli
