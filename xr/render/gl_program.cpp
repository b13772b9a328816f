/// @file
/// @brief GlProgram: compile, link, and readable error messages.
#include "xr/render/gl_program.h"

#include <epoxy/gl.h>

#include <regex>
#include <sstream>
#include <vector>

#include "effects/glsl_common.h"
#include "xr/render/gl_context.h"

namespace vdfx::xr {
namespace {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::string cur;
  for (char c : text) {
    if (c == '\n') {
      lines.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

unsigned compile(GLenum stage, const std::string& label, std::string_view source) {
  const std::string full =
      std::string(effects::glsl::kDesktopPrelude) + "#line 1\n" + std::string(source);
  const GLuint s = glCreateShader(stage);
  const char* ptr = full.c_str();
  glShaderSource(s, 1, &ptr, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(s, len, nullptr, log.data());
    glDeleteShader(s);
    throw GlError("shader " + label + " does not compile:\n" +
                  annotate_shader_log(label, source, log));
  }
  return s;
}

}  // namespace

std::string annotate_shader_log(std::string_view shader_name, std::string_view source,
                                std::string_view log) {
  static const std::regex mesa(R"(^\s*\d+:(\d+)\(\d+\):\s*(.*)$)");
  static const std::regex nvidia(R"(^\s*\d+\((\d+)\)\s*:\s*(.*)$)");
  static const std::regex khronos(R"(^\s*(?:ERROR|WARNING):\s*\d+:(\d+):\s*(.*)$)");
  const std::vector<std::string> src = split_lines(source);
  std::ostringstream out;
  for (const std::string& line : split_lines(log)) {
    if (line.find_first_not_of(" \t\r\0") == std::string::npos) continue;
    std::smatch m;
    if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia) ||
        std::regex_match(line, m, khronos)) {
      const int n = std::stoi(m[1].str());
      out << shader_name << " line " << n << ": " << m[2].str() << "\n";
      if (n >= 1 && n <= static_cast<int>(src.size()))
        out << "  > " << src[static_cast<size_t>(n - 1)] << "\n";
    } else {
      out << shader_name << ": " << line << "\n";
    }
  }
  return out.str();
}

GlProgram GlProgram::build(std::string_view name, std::string_view vs, std::string_view fs) {
  const std::string n(name);
  const GLuint v = compile(GL_VERTEX_SHADER, n + ".vert", vs);
  GLuint f = 0;
  try {
    f = compile(GL_FRAGMENT_SHADER, n + ".frag", fs);
  } catch (...) {
    glDeleteShader(v);
    throw;
  }
  GlProgram p;
  p.name_ = n;
  p.id_ = glCreateProgram();
  glAttachShader(p.id_, v);
  glAttachShader(p.id_, f);
  glLinkProgram(p.id_);
  glDeleteShader(v);
  glDeleteShader(f);
  GLint ok = GL_FALSE;
  glGetProgramiv(p.id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetProgramiv(p.id_, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(p.id_, len, nullptr, log.data());
    throw GlError("program " + n + " does not link: " + log);
  }
  return p;
}

GlProgram::~GlProgram() {
  if (id_) glDeleteProgram(id_);
}
GlProgram::GlProgram(GlProgram&& o) noexcept : id_(o.id_), name_(std::move(o.name_)) {
  o.id_ = 0;
}
GlProgram& GlProgram::operator=(GlProgram&& o) noexcept {
  if (this != &o) {
    if (id_) glDeleteProgram(id_);
    id_ = o.id_;
    name_ = std::move(o.name_);
    o.id_ = 0;
  }
  return *this;
}
void GlProgram::use() const {
  glUseProgram(id_);
}
int GlProgram::uniform(const char* uname) const {
  return glGetUniformLocation(id_, uname);
}

std::string_view fullscreen_vertex_source() {
  return effects::glsl::kFullscreenVertex;
}
}  // namespace vdfx::xr
