/// @file
/// @brief An OpenGL 4.3+ core context: a GLFW window, visible (mirror) or hidden (offscreen).
///
/// Only built with VDFX_WITH_GL. Functions are loaded through libepoxy, so any file that issues
/// GL calls includes <epoxy/gl.h>; this header does not, so it can be included anywhere.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

struct GLFWwindow;

namespace vdfx::xr {

/// A GL problem the program cannot recover from (no display, no 4.3 context, a shader that does
/// not compile, an incomplete framebuffer). The message says what and where.
class GlError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// No OpenGL 4.3 context can be had here at all (no display, no X server, an older driver):
/// the environment, not a bug, so the command line reports it as a usage error (exit 2).
class GlUnavailableError : public GlError {
 public:
  using GlError::GlError;
};

struct GlContextOptions {
  int width = 1280;  //!< window size (the hidden window of an offscreen context is tiny)
  int height = 720;
  bool visible = false;   //!< false: hidden window, render to textures only
  bool vsync = true;      //!< swap interval 1 for a visible window
  bool resizable = true;  //!< the user may resize a visible window
  std::string title = "vdfx";
  bool debug_output = false;  //!< GL_KHR_debug messages to stderr
};

class GlContext {
 public:
  /// Opens the window and makes its context current. Throws GlError with a clear message when no
  /// display can be opened (DISPLAY unset: "run under xvfb-run -a") or the driver lacks GL 4.3.
  static std::unique_ptr<GlContext> create(const GlContextOptions& options = {});
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  void make_current();
  void swap_buffers();
  void poll_events();
  bool should_close() const;
  GLFWwindow* window() const { return window_; }
  /// Drawable size of the default framebuffer in pixels.
  void framebuffer_size(int* width, int* height) const;
  /// GL_RENDERER and GL_VERSION strings, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
  std::string renderer() const;
  std::string version() const;
  /// The largest width or height of an image this implementation renders and samples: the
  /// smallest of GL_MAX_TEXTURE_SIZE, GL_MAX_RENDERBUFFER_SIZE and GL_MAX_VIEWPORT_DIMS. Sizes
  /// are checked against it before any texture is allocated (a larger one is a GL error).
  int max_image_side() const;

 private:
  explicit GlContext(GLFWwindow* w) : window_(w) {}
  GLFWwindow* window_ = nullptr;
};

/// Throws GlError naming `where` when glGetError reports an error (cheap; used after setup steps).
void check_gl(const char* where);

}  // namespace vdfx::xr
