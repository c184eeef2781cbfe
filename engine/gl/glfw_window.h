#pragma once
// The GLFW window behind a GLFW context, for programs that draw into it and read its input
// (the viewer, samples/diptych/view). Other contexts have no window.
struct GLFWwindow;

namespace diptych::gl {

class GlContext;

// nullptr unless `context` was made by createContext(ContextKind::Glfw, ...).
GLFWwindow* glfwWindowOf(GlContext& context);

}  // namespace diptych::gl
