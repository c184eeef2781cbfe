// The viewer's ImGui panels: view and camera, technique slots (from the pass registry's
// parameter schemas), comparison figures, and per-pass timings with culled passes.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "engine/core/timing.h"
#include "engine/gl/context.h"
#include "passes/registry.h"
#include "samples/diptych/view/viewer.h"

namespace diptych::view {
namespace {

// One parameter's widget from its schema entry; returns the new value when the user changed it.
std::optional<nlohmann::json> paramWidget(const ParamSpec& spec, const nlohmann::json& current) {
  const nlohmann::json value = current.is_null() ? spec.fallback : current;
  const char* label = spec.name.c_str();
  // A slider for a range one can drag across; a typed field for ranges like [0, 1e30].
  const bool log = spec.lo > 0 && spec.hi / spec.lo > 100;
  switch (spec.type) {
    case ParamSpec::Type::Boolean: {
      bool v = value.get<bool>();
      if (ImGui::Checkbox(label, &v)) return v;
      break;
    }
    case ParamSpec::Type::Choice: {
      const std::string v = value.get<std::string>();
      if (ImGui::BeginCombo(label, v.c_str())) {
        std::optional<nlohmann::json> picked;
        for (const std::string& c : spec.choices)
          if (ImGui::Selectable(c.c_str(), c == v) && c != v) picked = c;
        ImGui::EndCombo();
        return picked;
      }
      break;
    }
    case ParamSpec::Type::Integer: {
      int v = value.get<int>();
      const bool slider = spec.hi - spec.lo <= 1e5;
      const bool changed = slider ? ImGui::SliderInt(label, &v, int(spec.lo), int(spec.hi), "%d",
                                                     log ? ImGuiSliderFlags_Logarithmic : 0)
                                  : ImGui::InputInt(label, &v);
      if (changed) return int(std::clamp(double(v), spec.lo, spec.hi));
      break;
    }
    case ParamSpec::Type::Number: {
      double v = value.get<double>();
      bool changed = false;
      if (spec.hi - spec.lo <= 1e4) {
        float f = float(v);
        changed = ImGui::SliderFloat(label, &f, float(spec.lo), float(spec.hi), "%.5g",
                                     log ? ImGuiSliderFlags_Logarithmic : 0);
        v = f;
      } else {
        changed = ImGui::InputDouble(label, &v, 0, 0, "%.6g", ImGuiInputTextFlags_EnterReturnsTrue);
      }
      if (changed) return std::clamp(v, spec.lo, spec.hi);
      break;
    }
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%s (%s)", spec.doc.c_str(), spec.describe().c_str());
  return std::nullopt;
}

}  // namespace

void Viewer::panels() {
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(420, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("Diptych view");
  ImGui::PushItemWidth(230);
  ImGui::TextWrapped("%s", session_.scenePath().c_str());
  ImGui::TextDisabled("%s", context_.info().renderer.c_str());
  if (const LiveGraph* live = session_.live())
    ImGui::Text("frame %dx%d: %.1f ms%s", live->graph.frame.width, live->graph.frame.height,
                session_.lastFrameMs(), reduction_ > 1 ? " (moves at reduced size)" : "");
  if (ImGui::CollapsingHeader("Camera", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::Checkbox("fly (F)", &state_.fly);
    ImGui::SameLine();
    ImGui::Checkbox("reduce while moving", &state_.reduce);
    if (ImGui::Button("reset (Home)")) {
      session_.camera() = session_.sceneCamera();
      session_.cameraChanged();
    }
    ImGui::SameLine();
    if (ImGui::Button("save (C)")) saveCamera(options_.outDir / "view.camera.json");
    ImGui::SameLine();
    if (ImGui::Button("load (L)")) loadCamera(options_.outDir / "view.camera.json");
    if (ImGui::Button("screenshot (P)"))
      pendingShot_ = "screenshot-" + std::to_string(++screenshots_);
    ImGui::SameLine();
    if (ImGui::Button("write recipe (R)")) writeRecipe("view");
    ImGui::SliderFloat("exposure", &state_.exposure, -8.f, 8.f, "%+.1f EV");
  }
  if (ImGui::CollapsingHeader("Technique slots", ImGuiTreeNodeFlags_DefaultOpen)) slotPanel();
  if (!state_.message.empty()) ImGui::TextWrapped("%s", state_.message.c_str());
  ImGui::PopItemWidth();
  ImGui::End();
  // Comparison and timings on the right, so that the left keeps the slots.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x - 8, 8), ImGuiCond_FirstUseEver, ImVec2(1, 0));
  ImGui::SetNextWindowSize(ImVec2(400, 0), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.85f);
  ImGui::Begin("Compare");
  ImGui::PushItemWidth(200);
  comparePanel();
  ImGui::PopItemWidth();
  if (ImGui::CollapsingHeader("Timings", ImGuiTreeNodeFlags_DefaultOpen)) timingPanel();
  ImGui::End();
}

void Viewer::slotPanel() {
  const PassRegistry& registry = builtinPasses();
  const LiveGraph* live = session_.live();
  for (const TechniqueSlot& slot : techniqueSlots()) {
    const auto state = session_.slotState(slot.name);
    if (!state) continue;
    ImGui::PushID(slot.name.c_str());
    std::optional<SlotOverride> change;
    if (ImGui::BeginCombo(slot.name.c_str(), state->type.c_str())) {
      for (const PassTypeInfo* p : registry.producersOf(slot.name))
        if (ImGui::Selectable(p->name.c_str(), p->name == state->type) && p->name != state->type)
          change =
              SlotOverride{.slot = slot.name, .type = p->name, .text = slot.name + "=" + p->name};
      ImGui::EndCombo();
    }
    if (const PassTypeInfo* info = registry.find(state->type)) {
      ImGui::Indent();
      for (const ParamSpec& spec : info->params)
        if (auto v = paramWidget(spec, state->params.value(spec.name, nlohmann::json()))) {
          if (auto error = session_.setParam(slot.name, spec.name, *v)) say(*error);
        }
      ImGui::Unindent();
    }
    // Why the producer does not run, when it does not (the compiler's cull reason).
    if (live)
      for (const GraphPass& p : live->graph.passes)
        if (p.culled && p.type == state->type)
          ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "culled: %s", p.cullReason.c_str());
    if (change) {
      if (auto error = session_.setSlot(*change))
        say(*error);
      else
        say("slot " + change->text);
    }
    ImGui::PopID();
  }
}

void Viewer::comparePanel() {
  ImGui::Text("reference: %s", session_.referenceText().c_str());
  if (session_.referenceSamples() > 0)
    ImGui::Text("accumulated %d samples per pixel", session_.referenceSamples());
  ImGui::Checkbox("split (Tab)", &state_.split);
  ImGui::SameLine();
  ImGui::SliderFloat("wipe", &state_.wipe, 0.f, 1.f, "%.2f");
  int overlay = int(state_.overlay);
  ImGui::Text("heat map (H):");
  ImGui::SameLine();
  ImGui::RadioButton("none", &overlay, 0);
  ImGui::SameLine();
  ImGui::RadioButton("FLIP", &overlay, 1);
  ImGui::SameLine();
  ImGui::RadioButton("abs", &overlay, 2);
  state_.overlay = Overlay(overlay);
  const Figures& f = session_.figures();
  if (!f.valid) {
    ImGui::TextDisabled("figures: when the camera stops");
    return;
  }
  ImGui::Text("RMSE %.5g   FLIP mean %.4f", f.rmse, f.flipMean);
  if (f.referenceSamples > 0) ImGui::TextDisabled("(against %d samples)", f.referenceSamples);
  if (f.visibility)
    ImGui::Text("visibility (light 0): acne %.2f%%  peter-panning %.2f%%  leak %.2f%%",
                100 * f.acneRate, 100 * f.peterPanningRate, 100 * f.lightLeakRate);
}

void Viewer::timingPanel() {
  const LiveGraph* live = session_.live();
  if (!live) return;
  const CompiledGraph& g = live->graph;
  if (ImGui::Button("time 10 frames")) session_.timeFrames(10);
  ImGui::TextDisabled("median of the last <= 32 frames after the first;");
  ImGui::TextDisabled(
      "CPU steady_clock, GPU GL_TIME_ELAPSED, GL wait: for earlier nodes' GL work (render "
      "--timings)");
  if (ImGui::BeginTable("timings", 5, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit)) {
    ImGui::TableSetupColumn("node");
    ImGui::TableSetupColumn("dom");
    ImGui::TableSetupColumn("cpu ms");
    ImGui::TableSetupColumn("gpu ms");
    ImGui::TableSetupColumn("gl wait ms");
    ImGui::TableHeadersRow();
    double total = 0;
    for (std::size_t n = 0; n < g.nodes.size(); ++n) {
      const NodeTiming& t = live->executor->timings()[n];
      const double cpu = t.cpuMs.empty() ? 0 : summarize(t.cpuMs).median;
      const double wait = t.glWaitMs.empty() ? 0 : summarize(t.glWaitMs).median;
      total += cpu + wait;  // the waits are frame time too, kept out of the nodes' cpu ms
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(g.nodes[n].name.c_str());  // readback:/upload: are the transfers
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(domainName(g.nodes[n].domain));
      ImGui::TableNextColumn();
      if (t.cpuMs.empty())
        ImGui::TextUnformatted("-");  // only the first frame ran: one-time work, not shown
      else
        ImGui::Text("%.2f", cpu);
      ImGui::TableNextColumn();
      if (t.gpuMs.empty())
        ImGui::TextUnformatted("-");
      else
        ImGui::Text("%.2f", summarize(t.gpuMs).median);
      ImGui::TableNextColumn();
      if (t.glWaitMs.empty())
        ImGui::TextUnformatted("-");
      else
        ImGui::Text("%.2f", wait);
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("total");
    ImGui::TableNextColumn();
    ImGui::TableNextColumn();
    ImGui::Text("%.2f", total);  // cpu ms plus GL waits
    ImGui::EndTable();
  }
  for (const GraphPass& p : g.passes)
    if (p.culled)
      ImGui::TextWrapped("culled: %s (%s): %s", p.name.c_str(), p.type.c_str(),
                         p.cullReason.c_str());
}

}  // namespace diptych::view
