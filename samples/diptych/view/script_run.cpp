// The viewer's script commands (script.h), each acting like the key or panel control it names.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>

#include "engine/core/error.h"
#include "samples/diptych/view/camera_control.h"
#include "samples/diptych/view/viewer.h"

namespace diptych::view {
namespace {

// "KEY=VALUE" -> the JSON value --slot would give it (number, true/false, else a string).
std::pair<std::string, nlohmann::json> keyValue(const std::string& text) {
  const SlotOverride o = parseSlotOverride("visibility=x:" + text);
  auto it = o.params.begin();
  return {it.key(), it.value()};
}

}  // namespace

bool Viewer::runScriptStep() {
  if (scriptNext_ >= options_.script.size()) return false;
  execute(options_.script[scriptNext_++]);
  return true;
}

void Viewer::execute(const ScriptCommand& c) {
  const std::string place = "line " + std::to_string(c.line);
  auto fail = [&](const std::string& message) {
    throw InputError(options_.scriptPath, place, message);
  };
  const auto& a = c.args;
  const auto& n = c.numbers;
  if (c.verb == "slot") {
    if (auto error = session_.setSlot(parseSlotOverride(a[0]))) fail(*error);
    say("slot " + a[0]);
  } else if (c.verb == "param") {
    const auto [key, value] = keyValue(a[1]);
    if (auto error = session_.setParam(a[0], key, value)) fail(*error);
    say("param " + a[0] + " " + a[1]);
  } else if (c.verb == "camera") {
    Camera& cam = session_.camera();
    if (a[0] == "orbit") orbit(cam, glm::radians(float(n[0])), glm::radians(float(n[1])));
    if (a[0] == "pan") pan(cam, float(n[0]), float(n[1]));
    if (a[0] == "dolly") {
      if (!(n[0] > 0)) fail("dolly FACTOR must be positive");
      dolly(cam, float(n[0]));
    }
    if (a[0] == "fly") fly(cam, vec3(n[0], n[1], n[2]), 0.f, 0.f);
    if (a[0] == "reset") cam = session_.sceneCamera();
    if (a[0] == "save") saveCamera(options_.outDir / a[1]);
    if (a[0] == "load") loadCamera(options_.outDir / a[1]);
    if (a[0] != "save") session_.cameraChanged();
  } else if (c.verb == "split") {
    state_.split = a[0] == "on";
    if (!n.empty()) {
      if (!(n[0] >= 0 && n[0] <= 1)) fail("the wipe position is a fraction in [0, 1]");
      state_.wipe = float(n[0]);
    }
  } else if (c.verb == "overlay") {
    state_.overlay = a[0] == "flip" ? Overlay::Flip : a[0] == "abs" ? Overlay::Abs : Overlay::None;
  } else if (c.verb == "exposure") {
    if (std::abs(n[0]) > 64) fail("exposure is in [-64, 64] stops");
    state_.exposure = float(n[0]);
  } else if (c.verb == "resize") {
    if (n[0] < 1 || n[1] < 1 || n[0] > 16384 || n[1] > 16384)
      fail("resize takes a width and height in 1..16384");
    glfwSetWindowSize(window_, int(n[0]), int(n[1]));
    waitFrames_ = 2;  // the X server applies the size on a later event
  } else if (c.verb == "frames") {
    if (n[0] < 0 || n[0] > 100000) fail("frames takes a count in 0..100000");
    waitFrames_ = int(n[0]);
  } else if (c.verb == "screenshot") {
    pendingShot_ = a[0];
  } else if (c.verb == "write-recipe") {
    writeRecipe(a[0]);
  } else if (c.verb == "motion") {  // frames as while the camera moves, at 1/FACTOR size
    if (!n.empty() && (n[0] < 1 || n[0] > 8)) fail("motion FACTOR is in 1..8");
    scriptMotion_ = n.empty() ? 0 : int(n[0]);
  } else if (c.verb == "time") {
    if (n[0] < 1 || n[0] > 1000) fail("time takes a frame count in 1..1000");
    session_.timeFrames(int(n[0]));
  } else if (c.verb == "quit") {
    say("quit (script " + place + ")");
    quit_ = true;
    glfwSetWindowShouldClose(window_, GLFW_TRUE);  // as the window's close button does
  }
}

}  // namespace diptych::view
