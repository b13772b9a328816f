/// @file
/// @brief Shader compile/link with messages that name the shader and quote the failing line.
#pragma once

#include <string>
#include <string_view>

namespace vdfx::xr {

/// A linked GL program (move-only). Sources are given without a #version line: the builder
/// prepends the desktop prelude (effects/glsl_common.h) and a #line directive so the driver's line
/// numbers are the source's own.
class GlProgram {
 public:
  GlProgram() = default;
  /// Compiles and links; throws GlError "<name>.vert line 12: <driver message>\n  > <source line>"
  /// for each problem the driver reports.
  static GlProgram build(std::string_view name, std::string_view vertex_source,
                         std::string_view fragment_source);
  ~GlProgram();
  GlProgram(GlProgram&& o) noexcept;
  GlProgram& operator=(GlProgram&& o) noexcept;
  GlProgram(const GlProgram&) = delete;
  GlProgram& operator=(const GlProgram&) = delete;

  unsigned id() const { return id_; }
  void use() const;
  /// Uniform location, -1 when the uniform is absent (or optimised out).
  int uniform(const char* name) const;
  const std::string& name() const { return name_; }

 private:
  unsigned id_ = 0;
  std::string name_;
};

/// The vertex shader every full-screen pass shares (effects/glsl_common.h's kFullscreenVertex).
std::string_view fullscreen_vertex_source();

/// Turns a driver info log into lines "<shader> line N: message\n  > source line" (Mesa
/// "0:12(5): error: ...", NVIDIA "0(12) : error ...", AMD/Intel "ERROR: 0:12: ..."). Exposed for
/// its unit test.
std::string annotate_shader_log(std::string_view shader_name, std::string_view source,
                                std::string_view log);

}  // namespace vdfx::xr
