#include "samples/diptych/view/viewer.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include "engine/core/error.h"
#include "engine/core/tonemap.h"
#include "engine/gl/context.h"
#include "engine/gl/glfw_window.h"
#include "engine/metrics/metrics.h"
#include "samples/diptych/view/camera_control.h"

namespace diptych::view {
namespace {

constexpr int kMinSide = 8;             // below this (a minimised window) nothing is rendered
constexpr double kMaxPixels = 1 << 21;  // 2 Mpx: larger windows render smaller, shown scaled
constexpr double kMotionHoldS = 0.3;    // the camera counts as moving this long after a motion
constexpr double kTargetMs = 40.0;      // frame time the reduced resolution aims for

// 8-bit sRGB RGBA of a linear image, as writeImage encodes a PNG (same tone map).
std::vector<std::uint8_t> displayBytes(const Image& image, const ToneMap& tone) {
  std::vector<std::uint8_t> out(std::size_t(image.width) * image.height * 4, 255);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      vec3 c(image.at(x, y, 0));
      if (image.channels >= 3) c = vec3(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
      const vec3 d = toneMapPixel(c, tone);
      for (int k = 0; k < 3; ++k)
        out[(std::size_t(y) * image.width + x) * 4 + k] =
            std::uint8_t(std::lround(linearToSrgb(d[k]) * 255.f));
    }
  return out;
}

}  // namespace

struct Viewer::Textures {
  gl::Texture current, reference, heat;
  void upload(gl::Texture& t, const Image& image, const ToneMap& tone) {
    if (image.empty()) return;
    if (!t || t.width() != image.width || t.height() != image.height) {
      t = gl::Texture::create2D(gl::TextureFormat::RGBA8, image.width, image.height);
      gl::glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      gl::glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    const auto bytes = displayBytes(image, tone);
    gl::glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl::glTextureSubImage2D(t.id(), 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                            bytes.data());
  }
};

Viewer::Viewer(Session& session, gl::GlContext& context, ViewerOptions options, ViewState state)
    : session_(session),
      context_(context),
      window_(gl::glfwWindowOf(context)),
      options_(std::move(options)),
      state_(state),
      textures_(std::make_unique<Textures>()) {
  if (!window_) throw Error("diptych view needs a GLFW window context");
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini left in the working folder
  ImGui::StyleColorsDark();
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 450");
}

Viewer::~Viewer() {
  context_.makeCurrent();
  textures_.reset();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void Viewer::say(const std::string& message) {
  state_.message = message;
  std::printf("view: %s\n", message.c_str());
  std::fflush(stdout);
}

void Viewer::run() {
  while (!quit_ && !glfwWindowShouldClose(window_)) frame();
  if (!quit_) say("window closed");
}

std::pair<int, int> Viewer::renderSize(int w, int h) const {
  const double pixels = double(w) * h;
  if (pixels <= kMaxPixels) return {w, h};
  const double s = std::sqrt(kMaxPixels / pixels);
  return {std::max(kMinSide, int(w * s)), std::max(kMinSide, int(h * s))};
}

void Viewer::frame() {
  glfwPollEvents();
  int fbw = 0, fbh = 0;
  glfwGetFramebufferSize(window_, &fbw, &fbh);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const bool scripted = !options_.script.empty();
  if (scripted) {
    if (waitFrames_ > 0)
      --waitFrames_;
    else if (!runScriptStep() && !options_.scriptPath.empty())
      options_.script.clear();  // done: the window stays open for the user
  } else {
    handleInput();
  }
  const bool moving = scripted ? scriptMotion_ > 0 : glfwGetTime() - lastMotion_ < kMotionHoldS;
  if (scripted && moving) reduction_ = scriptMotion_;
  const bool compare = state_.split || state_.overlay != Overlay::None;
  if (fbw >= kMinSide && fbh >= kMinSide) {
    auto [w, h] = renderSize(fbw, fbh);
    const int r = moving && state_.reduce ? reduction_ : 1;
    const bool changed =
        session_.render(std::max(kMinSide, w / r), std::max(kMinSide, h / r), compare, !moving);
    if (changed && r == 1 &&
        session_.lastFrameWarm())  // full-resolution cost sets the next motion's reduction
      reduction_ = std::clamp(int(std::ceil(std::sqrt(session_.lastFrameMs() / kTargetMs))), 1, 8);
    const auto look = std::make_tuple(state_.overlay, state_.exposure, state_.tone);
    if (changed || look != uploadedLook_) {
      uploadedLook_ = look;
      const ToneMap tone{state_.exposure, state_.tone};
      textures_->upload(textures_->current, session_.current(), tone);
      textures_->upload(textures_->reference, session_.reference(), tone);
      const Image& err = session_.errorMap();
      textures_->heat = gl::Texture();  // none unless this frame has one (never a stale map)
      if (state_.overlay == Overlay::Flip && !err.empty())
        textures_->upload(textures_->heat, heatMap(err, 1.f), {});
      if (state_.overlay == Overlay::Abs && !session_.reference().empty() &&
          session_.reference().width == session_.current().width &&
          session_.reference().height == session_.current().height) {
        Image abs = squaredErrorMap(session_.current(), session_.reference());
        float peak = 0.f;
        for (float& v : abs.pixels) peak = std::max(peak, v = std::sqrt(v));
        textures_->upload(textures_->heat, heatMap(abs, peak > 0.f ? peak : 1.f), {});
      }
    }
    drawImages();
  }
  panels();
  ImGui::Render();
  gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
  gl::glViewport(0, 0, fbw, fbh);
  gl::glClearColor(0.1f, 0.1f, 0.1f, 1.f);
  gl::glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  if (!pendingShot_.empty()) {
    screenshot(pendingShot_);
    pendingShot_.clear();
  }
  context_.swapBuffers();
}

void Viewer::drawImages() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  auto id = [](const gl::Texture& t) { return ImTextureID(std::intptr_t(t.id())); };
  if (!textures_->current) return;
  const bool heat = state_.overlay != Overlay::None && textures_->heat &&
                    textures_->heat.width() == textures_->current.width();
  const gl::Texture& right =
      heat ? textures_->heat : (textures_->reference ? textures_->reference : textures_->current);
  const float split = state_.split ? state_.wipe : (heat ? 0.f : 1.f);
  const float x = split * size.x;
  draw->AddImage(id(textures_->current), ImVec2(0, 0), ImVec2(x, size.y), ImVec2(0, 0),
                 ImVec2(split, 1));
  if (split < 1.f) draw->AddImage(id(right), ImVec2(x, 0), size, ImVec2(split, 0), ImVec2(1, 1));
  if (state_.split) draw->AddLine(ImVec2(x, 0), ImVec2(x, size.y), IM_COL32(255, 255, 255, 200), 2);
}

void Viewer::handleInput() {
  ImGuiIO& io = ImGui::GetIO();
  Camera& cam = session_.camera();
  bool moved = false;
  if (!io.WantCaptureKeyboard) {
    if (ImGui::IsKeyPressed(GLFW_KEY_F)) state_.fly = !state_.fly;
    if (ImGui::IsKeyPressed(GLFW_KEY_HOME) || ImGui::IsKeyPressed(GLFW_KEY_BACKSPACE)) {
      cam = session_.sceneCamera();
      moved = true;
    }
    if (ImGui::IsKeyPressed(GLFW_KEY_TAB)) state_.split = !state_.split;
    if (ImGui::IsKeyPressed(GLFW_KEY_H)) state_.overlay = Overlay((int(state_.overlay) + 1) % 3);
    if (ImGui::IsKeyPressed(GLFW_KEY_P) || ImGui::IsKeyPressed(GLFW_KEY_F12))
      pendingShot_ = "screenshot-" + std::to_string(++screenshots_);
    if (ImGui::IsKeyPressed(GLFW_KEY_R)) writeRecipe("view");
    if (ImGui::IsKeyPressed(GLFW_KEY_C)) saveCamera(options_.outDir / "view.camera.json");
    if (ImGui::IsKeyPressed(GLFW_KEY_L)) loadCamera(options_.outDir / "view.camera.json");
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE)) glfwSetWindowShouldClose(window_, GLFW_TRUE);
    if (state_.fly) {  // distance per frame: 2% of the distance to the target
      const float s = 0.02f;
      const vec3 move((io.KeysDown[GLFW_KEY_D] - io.KeysDown[GLFW_KEY_A]) * s,
                      (io.KeysDown[GLFW_KEY_E] - io.KeysDown[GLFW_KEY_Q]) * s,
                      (io.KeysDown[GLFW_KEY_W] - io.KeysDown[GLFW_KEY_S]) * s);
      if (move != vec3(0.f)) {
        fly(cam, move, 0.f, 0.f);
        moved = true;
      }
    }
  }
  if (!io.WantCaptureMouse) {
    const float wipeX = state_.wipe * io.DisplaySize.x;
    if (ImGui::IsMouseClicked(0) && state_.split && std::abs(io.MousePos.x - wipeX) < 8.f)
      draggingWipe_ = true;
    const ImVec2 d = io.MouseDelta;
    const bool drag = d.x != 0.f || d.y != 0.f;
    if (draggingWipe_ && io.MouseDown[0]) {
      state_.wipe = std::clamp(io.MousePos.x / io.DisplaySize.x, 0.f, 1.f);
    } else if (drag && io.MouseDown[0] && !io.KeyShift) {
      if (state_.fly)
        fly(cam, vec3(0.f), d.x * 0.003f, -d.y * 0.003f);
      else
        orbit(cam, -d.x * 0.005f, d.y * 0.005f);
      moved = true;
    } else if (drag && (io.MouseDown[1] || io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift))) {
      pan(cam, -d.x / io.DisplaySize.y, d.y / io.DisplaySize.y);
      moved = true;
    }
    if (!io.MouseDown[0]) draggingWipe_ = false;
    if (io.MouseWheel != 0.f) {
      dolly(cam, std::pow(0.9f, io.MouseWheel));
      moved = true;
    }
  }
  if (moved) {
    session_.cameraChanged();
    lastMotion_ = glfwGetTime();
  }
}

}  // namespace diptych::view
