/// @file
/// @brief GLFW + libepoxy implementation of GlContext.
#include <epoxy/gl.h>
// epoxy must come first: GLFW then includes no GL header of its own.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <sstream>

#include "xr/render/gl_context.h"

namespace vdfx::xr {
namespace {

std::string& last_glfw_error() {
  static std::string message;
  return message;
}

void on_glfw_error(int code, const char* description) {
  std::ostringstream s;
  s << "GLFW error " << code << ": " << (description ? description : "(none)");
  last_glfw_error() = s.str();
}

int& live_contexts() {
  static int count = 0;
  return count;
}

void GLAPIENTRY on_gl_debug(GLenum, GLenum type, GLuint, GLenum severity, GLsizei,
                            const GLchar* message, const void*) {
  if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
  std::cerr << "GL debug (" << (type == GL_DEBUG_TYPE_ERROR ? "error" : "message")
            << "): " << message << "\n";
}

}  // namespace

std::unique_ptr<GlContext> GlContext::create(const GlContextOptions& o) {
  glfwSetErrorCallback(on_glfw_error);
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland))
    throw GlUnavailableError(
        "cannot create an OpenGL context: no display (DISPLAY is not set). "
        "Run under a desktop session or a virtual one: `xvfb-run -a <command>`.");
  if (live_contexts() == 0 && glfwInit() != GLFW_TRUE)
    throw GlUnavailableError("cannot create an OpenGL context: glfwInit failed on DISPLAY='" +
                             std::string(display ? display : "") + "' (" + last_glfw_error() +
                             "). Is the X server running? Try `xvfb-run -a <command>`.");
  glfwDefaultWindowHints();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_RESIZABLE, o.resizable ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, o.debug_output ? GLFW_TRUE : GLFW_FALSE);
  const int w = o.visible ? o.width : 16, h = o.visible ? o.height : 16;
  GLFWwindow* window = glfwCreateWindow(w, h, o.title.c_str(), nullptr, nullptr);
  if (!window) {
    if (live_contexts() == 0) glfwTerminate();
    throw GlUnavailableError("cannot create an OpenGL 4.3 core context (" + last_glfw_error() +
                             "). The driver must offer OpenGL 4.3 core; Mesa llvmpipe offers 4.5.");
  }
  ++live_contexts();
  std::unique_ptr<GlContext> ctx(new GlContext(window));
  ctx->make_current();
  glfwSwapInterval(o.visible && o.vsync ? 1 : 0);
  if (epoxy_gl_version() < 43)
    throw GlUnavailableError("OpenGL " + ctx->version() +
                             " is older than the 4.3 core the compositor needs");
  if (o.debug_output) {
    glEnable(GL_DEBUG_OUTPUT);
    glDebugMessageCallback(on_gl_debug, nullptr);
  }
  return ctx;
}

GlContext::~GlContext() {
  glfwDestroyWindow(window_);
  if (--live_contexts() == 0) glfwTerminate();
}

void GlContext::make_current() {
  glfwMakeContextCurrent(window_);
}
void GlContext::swap_buffers() {
  glfwSwapBuffers(window_);
}
void GlContext::poll_events() {
  glfwPollEvents();
}
bool GlContext::should_close() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}
void GlContext::framebuffer_size(int* width, int* height) const {
  glfwGetFramebufferSize(window_, width, height);
}

std::string GlContext::renderer() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return s ? s : "";
}
std::string GlContext::version() const {
  const auto* s = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return s ? s : "";
}

int GlContext::max_image_side() const {
  GLint tex = 0, rb = 0;
  GLint viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &tex);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &rb);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({tex, rb, viewport[0], viewport[1]});
}

void check_gl(const char* where) {
  const GLenum e = glGetError();
  if (e == GL_NO_ERROR) return;
  std::ostringstream s;
  s << "OpenGL error 0x" << std::hex << e << " after " << where;
  // The one error a user can meet with valid options (a machine with less memory than the sizes
  // need): say so in words.
  if (e == GL_OUT_OF_MEMORY) s << " (GL_OUT_OF_MEMORY: the GL implementation ran out of memory)";
  throw GlError(s.str());
}

}  // namespace vdfx::xr
