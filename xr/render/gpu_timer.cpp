/// @file
/// @brief GpuTimer with GL_TIMESTAMP queries.
#include "xr/render/gpu_timer.h"

#include <epoxy/gl.h>

#include <chrono>

#include "xr/render/gl_context.h"

namespace vdfx::xr {

GpuTimer::~GpuTimer() {
  for (const Pending& p : pending_) {
    glDeleteQueries(1, &p.begin);
    glDeleteQueries(1, &p.end);
  }
}

void GpuTimer::start(const std::string& stage) {
  Pending p;
  p.stage = stage;
  glGenQueries(1, &p.begin);
  glGenQueries(1, &p.end);
  glQueryCounter(p.begin, GL_TIMESTAMP);
  open_.push_back(pending_.size());
  pending_.push_back(std::move(p));
}

void GpuTimer::stop() {
  if (open_.empty()) throw GlError("GpuTimer::stop without a started stage");
  glQueryCounter(pending_[open_.back()].end, GL_TIMESTAMP);
  open_.pop_back();
}

std::vector<StageTime> GpuTimer::collect() {
  if (!open_.empty())
    throw GlError("GpuTimer::collect: stage '" + pending_[open_.back()].stage + "' is still open");
  std::vector<StageTime> out;
  for (const Pending& p : pending_) {
    GLuint64 a = 0, b = 0;
    glGetQueryObjectui64v(p.begin, GL_QUERY_RESULT, &a);  // waits for the GPU
    glGetQueryObjectui64v(p.end, GL_QUERY_RESULT, &b);
    out.push_back({p.stage, static_cast<double>(b - a) * 1e-6});
    glDeleteQueries(1, &p.begin);
    glDeleteQueries(1, &p.end);
  }
  pending_.clear();
  return out;
}

double finished_wall_ms(const std::function<void()>& work) {
  glFinish();
  const auto t0 = std::chrono::steady_clock::now();
  work();
  glFinish();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace vdfx::xr
