#pragma once
// The window of `diptych view`: a GLFW window (OpenGL 4.5 core) with Dear ImGui over the frame
// the Session renders. Input, display (wipe, heat map), panels and the script all act on the
// Session; nothing here renders a scene by itself.
#include <filesystem>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "engine/core/image.h"
#include "engine/gl/objects.h"
#include "samples/diptych/view/script.h"
#include "samples/diptych/view/session.h"

struct GLFWwindow;

namespace diptych::view {

enum class Overlay { None, Flip, Abs };

// What the panels and keys change besides the Session.
struct ViewState {
  bool split = true;  // wipe between the current recipe (left) and the reference (right)
  float wipe = 0.5f;  // wipe position, fraction of the width
  Overlay overlay = Overlay::None;
  bool fly = false;    // fly mode: WASD/QE move, drag turns the view
  bool reduce = true;  // reduced resolution while the camera moves (docs/viewer.md)
  float exposure = 0.f;
  ToneOperator tone = ToneOperator::Clamp;
  std::string message;  // last action, shown in the panel and printed
};

struct ViewerOptions {
  std::filesystem::path outDir = ".";  // screenshots, recipes, cameras
  std::string scriptPath;              // empty: interactive
  std::vector<ScriptCommand> script;
};

class Viewer {
 public:
  Viewer(Session& session, gl::GlContext& context, ViewerOptions options, ViewState state);
  ~Viewer();
  // Runs until the window closes or the script quits. Throws InputError for a failing script
  // command (naming its line).
  void run();

 private:
  struct Textures;
  void frame();
  void handleInput();
  bool runScriptStep();  // false when the script is done
  void execute(const ScriptCommand& c);
  void drawImages();  // the frame, the wipe and the heat map, behind the panels
  void panels();
  void slotPanel();
  void comparePanel();
  void timingPanel();
  void screenshot(const std::string& name);
  void writeRecipe(const std::string& name);
  void saveCamera(const std::filesystem::path& file);
  void loadCamera(const std::filesystem::path& file);
  void say(const std::string& message);
  std::pair<int, int> renderSize(int fbWidth, int fbHeight) const;
  Image windowPixels() const;

  Session& session_;
  gl::GlContext& context_;
  GLFWwindow* window_;
  ViewerOptions options_;
  ViewState state_;
  std::unique_ptr<Textures> textures_;
  std::size_t scriptNext_ = 0;
  int waitFrames_ = 0;
  bool quit_ = false;
  bool draggingWipe_ = false;
  double lastMotion_ = -1e9;  // glfwGetTime() of the last camera motion
  int reduction_ = 1;         // render at 1/reduction_ of the window while moving
  int scriptMotion_ = 0;      // script "motion on FACTOR": > 0 acts as moving at that factor
  std::string pendingShot_;   // screenshot name to write after this frame is drawn
  int screenshots_ = 0;
  std::tuple<Overlay, float, ToneOperator> uploadedLook_{};  // what the textures show
};

}  // namespace diptych::view
