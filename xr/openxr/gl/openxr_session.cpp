/// @file
/// @brief The OpenXR backend's session: the GL binding, spaces, lifecycle and the frame.
#include <glm/gtc/quaternion.hpp>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

#include "effects/coords.h"
#include "xr/openxr/gl/openxr_runtime_impl.h"
#include "xr/render/gl_texture.h"

namespace vdfx::xr {
namespace {

Pose to_pose(const XrPosef& p) {
  Pose out;
  out.position = {p.position.x, p.position.y, p.position.z};
  out.orientation = glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
  return out;
}

FovDeg to_fov(const XrFovf& f) {
  const double d = effects::kRadToDeg;
  FovDeg out;
  out.angle_left = f.angleLeft * d;
  out.angle_right = f.angleRight * d;
  out.angle_up = f.angleUp * d;
  out.angle_down = f.angleDown * d;
  return out;
}

XrPosef identity_pose() {
  XrPosef p{};
  p.orientation.w = 1.0f;
  return p;
}

}  // namespace

void OpenXrRuntime::Impl::restore_context() {
  if (current_glx_context() != glx_context) {
    ++context_restores;
    glfwMakeContextCurrent(window);
  }
  // SteamVR 2.12 leaves a GL error set after xrEndFrame (SteamVR-for-Linux issue 799): it is the
  // runtime's, and vdfx's next check_gl would blame its own step for it.
  while (glGetError() != GL_NO_ERROR) {
  }
}

void OpenXrRuntime::Impl::check_gl_requirements() {
  PFN_xrGetOpenGLGraphicsRequirementsKHR get = nullptr;
  xr_check(xrGetInstanceProcAddr(instance, "xrGetOpenGLGraphicsRequirementsKHR",
                                 reinterpret_cast<PFN_xrVoidFunction*>(&get)),
           "xrGetInstanceProcAddr(xrGetOpenGLGraphicsRequirementsKHR)");
  auto req = xr_struct<XrGraphicsRequirementsOpenGLKHR>(XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR);
  xr_check(get(instance, system, &req), "xrGetOpenGLGraphicsRequirementsKHR");
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  const XrVersion have = XR_MAKE_VERSION(major, minor, 0);
  if (have < req.minApiVersionSupported)
    throw OpenXrUnavailable("the OpenXR runtime '" + info.runtime_name + "' needs OpenGL " +
                            std::to_string(XR_VERSION_MAJOR(req.minApiVersionSupported)) + "." +
                            std::to_string(XR_VERSION_MINOR(req.minApiVersionSupported)) +
                            "; this context is " + std::to_string(major) + "." +
                            std::to_string(minor) + " (update the GPU driver)");
}

void OpenXrRuntime::Impl::create_session(GLFWwindow* w) {
  window = w;
  glfwMakeContextCurrent(w);
  glx_context = current_glx_context();
  const std::shared_ptr<const void> binding = current_glx_binding();
  if (!binding)
    throw OpenXrUnavailable(
        "the window's OpenGL context is not a GLX one (XR_KHR_opengl_enable's Xlib binding needs "
        "it): run under X11 or XWayland");
  check_gl_requirements();
  auto ci = xr_struct<XrSessionCreateInfo>(XR_TYPE_SESSION_CREATE_INFO);
  ci.next = binding.get();
  ci.systemId = system;
  const XrResult r = xrCreateSession(instance, &ci, &session);
  restore_context();
  xr_check(r, "xrCreateSession");
  create_spaces();
  auto ai = xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
  ai.countActionSets = 1;
  ai.actionSets = &action_set;
  xr_check(xrAttachSessionActionSets(session, &ai), "xrAttachSessionActionSets");
}

void OpenXrRuntime::Impl::create_spaces() {
  std::uint32_t n = 0;
  xr_check(xrEnumerateReferenceSpaces(session, 0, &n, nullptr), "xrEnumerateReferenceSpaces");
  std::vector<XrReferenceSpaceType> types(n);
  xr_check(xrEnumerateReferenceSpaces(session, n, &n, types.data()), "xrEnumerateReferenceSpaces");
  const bool stage =
      std::find(types.begin(), types.end(), XR_REFERENCE_SPACE_TYPE_STAGE) != types.end();
  // vdfx's LOCAL has its origin on the floor, the head about kDefaultEyeHeight above it
  // (docs/input.md): OpenXR's STAGE where the runtime has one (its origin is on the floor), else
  // OpenXR's LOCAL (origin at the head) moved down by the standing eye height.
  auto ri = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
  ri.poseInReferenceSpace = identity_pose();
  ri.referenceSpaceType = stage ? XR_REFERENCE_SPACE_TYPE_STAGE : XR_REFERENCE_SPACE_TYPE_LOCAL;
  if (!stage) ri.poseInReferenceSpace.position.y = static_cast<float>(-kDefaultEyeHeight);
  xr_check(xrCreateReferenceSpace(session, &ri, &local), "xrCreateReferenceSpace(world)");
  world_space_name = stage ? "STAGE" : "LOCAL, 1.6 m down";
  ri.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
  ri.poseInReferenceSpace = identity_pose();
  xr_check(xrCreateReferenceSpace(session, &ri, &view), "xrCreateReferenceSpace(VIEW)");
  for (int h = 0; h < 2; ++h) {
    auto si = xr_struct<XrActionSpaceCreateInfo>(XR_TYPE_ACTION_SPACE_CREATE_INFO);
    si.action = actions[static_cast<int>(OpenXrAction::Aim)];
    si.subactionPath = hand_paths[h];
    si.poseInActionSpace = identity_pose();
    xr_check(xrCreateActionSpace(session, &si, &aim[h]), "xrCreateActionSpace(aim)");
  }
}

std::vector<std::int64_t> OpenXrRuntime::Impl::enumerate_formats() {
  std::uint32_t n = 0;
  xr_check(xrEnumerateSwapchainFormats(session, 0, &n, nullptr), "xrEnumerateSwapchainFormats");
  std::vector<std::int64_t> formats(n);
  xr_check(xrEnumerateSwapchainFormats(session, n, &n, formats.data()),
           "xrEnumerateSwapchainFormats");
  formats.resize(n);
  return formats;
}

void OpenXrRuntime::Impl::destroy_session() {
  if (!session) return;
  for (OpenXrSwapchain& c : eyes) destroy_swapchain(c);
  for (auto& [texture, c] : quad_chains) destroy_swapchain(c);
  quad_chains.clear();
  if (copy_vao && window) {
    glfwMakeContextCurrent(window);
    glDeleteVertexArrays(1, &copy_vao);
    copy_vao = 0;
  }
  copy_program = GlProgram();
  for (XrSpace& s : aim)
    if (s) xrDestroySpace(s), s = XR_NULL_HANDLE;
  if (view) xrDestroySpace(view), view = XR_NULL_HANDLE;
  if (local) xrDestroySpace(local), local = XR_NULL_HANDLE;
  xrDestroySession(session);
  session = XR_NULL_HANDLE;
  if (window) restore_context();
  window = nullptr;  // the session was bound to it; nothing is drawn for OpenXR after this
  glx_context = nullptr;
}

void OpenXrRuntime::Impl::handle_event(const XrEventDataBuffer& event) {
  LifecycleStep step = LifecycleStep::Nothing;
  if (event.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
    const auto& e = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
    step = lifecycle.on_state(e.state);
  } else if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
    step = lifecycle.on_instance_loss();
  }
  if (step == LifecycleStep::BeginSession) {
    auto bi = xr_struct<XrSessionBeginInfo>(XR_TYPE_SESSION_BEGIN_INFO);
    bi.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    const XrResult r = xrBeginSession(session, &bi);
    restore_context();
    xr_check(r, "xrBeginSession");
  } else if (step == LifecycleStep::EndSession) {
    const XrResult r = xrEndSession(session);
    restore_context();
    xr_check(r, "xrEndSession");
  }
}

void OpenXrRuntime::start_session(GLFWwindow* window, int eye_width, int eye_height) {
  Impl& m = *impl_;
  m.create_session(window);
  OpenXrSwapchainInfo& s = m.swapchain_info;
  s.offered = m.enumerate_formats();
  const auto chosen = choose_swapchain_format(s.offered);
  if (!chosen) {
    std::string listed;
    for (const std::int64_t f : s.offered)
      listed += (listed.empty() ? "" : ", ") + gl_format_name(f);
    throw OpenXrUnavailable("the OpenXR runtime '" + m.info.runtime_name +
                            "' offers no swapchain format vdfx can render to (it offers: " +
                            (listed.empty() ? "none" : listed) +
                            "; vdfx takes GL_SRGB8_ALPHA8, GL_RGBA16F, GL_RGB10_A2 or GL_RGBA8)");
  }
  s.format = *chosen;
  const OpenXrViewInfo& v = m.info.views[0];
  s.eye_width = std::clamp(eye_width, 1, std::max(1, v.max_width));
  s.eye_height = std::clamp(eye_height, 1, std::max(1, v.max_height));
  for (OpenXrSwapchain& c : m.eyes)
    c = m.create_swapchain(s.format.format, s.eye_width, s.eye_height);
}

const OpenXrSwapchainInfo& OpenXrRuntime::swapchains() const {
  return impl_->swapchain_info;
}

void OpenXrRuntime::poll_events() {
  Impl& m = *impl_;
  for (;;) {
    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    const XrResult r = xrPollEvent(m.instance, &event);
    if (r == XR_EVENT_UNAVAILABLE) break;
    xr_check(r, "xrPollEvent");
    m.handle_event(event);
    if (m.lifecycle.leaving()) break;
  }
}

const OpenXrLifecycle& OpenXrRuntime::lifecycle() const {
  return impl_->lifecycle;
}

void OpenXrRuntime::request_exit() {
  Impl& m = *impl_;
  if (m.lifecycle.request_exit()) xr_check(xrRequestExitSession(m.session), "xrRequestExitSession");
}

void OpenXrRuntime::end_session() {
  impl_->destroy_session();
}

void OpenXrRuntime::session_lost() {
  Impl& m = *impl_;
  m.frame_begun = false;
  m.lifecycle.on_session_lost();
}

OpenXrFrame OpenXrRuntime::begin_frame() {
  Impl& m = *impl_;
  auto fs = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
  auto wi = xr_struct<XrFrameWaitInfo>(XR_TYPE_FRAME_WAIT_INFO);
  XrResult r = xrWaitFrame(m.session, &wi, &fs);
  m.restore_context();
  xr_check(r, "xrWaitFrame");
  auto bi = xr_struct<XrFrameBeginInfo>(XR_TYPE_FRAME_BEGIN_INFO);
  r = xrBeginFrame(m.session, &bi);
  m.restore_context();
  xr_check(r, "xrBeginFrame");
  m.frame_begun = true;
  m.xr_time = fs.predictedDisplayTime;
  if (!m.epoch) m.epoch = fs.predictedDisplayTime - fs.predictedDisplayPeriod;
  m.eye_submitted = {false, false};
  m.quad_layers.clear();
  OpenXrFrame f;
  f.xr_time = fs.predictedDisplayTime;
  f.time_ns = fs.predictedDisplayTime - *m.epoch;
  f.period_ns = fs.predictedDisplayPeriod;
  f.should_render = fs.shouldRender == XR_TRUE;
  return f;
}

std::array<EyeView, 2> OpenXrRuntime::locate_views() {
  Impl& m = *impl_;
  auto li = xr_struct<XrViewLocateInfo>(XR_TYPE_VIEW_LOCATE_INFO);
  li.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  li.displayTime = m.xr_time;
  li.space = m.local;
  auto vs = xr_struct<XrViewState>(XR_TYPE_VIEW_STATE);
  std::uint32_t n = 0;
  m.views = {xr_struct<XrView>(XR_TYPE_VIEW), xr_struct<XrView>(XR_TYPE_VIEW)};
  xr_check(xrLocateViews(m.session, &li, &vs, 2, &n, m.views.data()), "xrLocateViews");
  std::array<EyeView, 2> out;
  for (int e = 0; e < 2; ++e) {
    out[e].eye = e == 0 ? Eye::Left : Eye::Right;
    // An untracked orientation keeps the runtime's last pose (the spec says it may be stale).
    out[e].pose = to_pose(m.views[e].pose);
    out[e].pose.orientation = glm::normalize(out[e].pose.orientation);
    out[e].fov = to_fov(m.views[e].fov);
    out[e].view = view_from_pose(out[e].pose);
    out[e].projection = projection_from_fov(out[e].fov, 0.05, 100.0);
    out[e].width = m.swapchain_info.eye_width;
    out[e].height = m.swapchain_info.eye_height;
  }
  return out;
}

void OpenXrRuntime::submit_eye(int eye, const GlTexture& image) {
  Impl& m = *impl_;
  m.copy_into(m.eyes.at(eye), image.id(), false, false);
  m.eye_submitted[eye] = true;
}

void OpenXrRuntime::end_frame() {
  Impl& m = *impl_;
  std::array<XrCompositionLayerProjectionView, 2> pv{};
  auto projection = xr_struct<XrCompositionLayerProjection>(XR_TYPE_COMPOSITION_LAYER_PROJECTION);
  std::vector<const XrCompositionLayerBaseHeader*> layers;
  if (m.eye_submitted[0] && m.eye_submitted[1]) {
    for (int e = 0; e < 2; ++e) {
      pv[e] =
          xr_struct<XrCompositionLayerProjectionView>(XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
      pv[e].pose = m.views[e].pose;
      pv[e].fov = m.views[e].fov;
      pv[e].subImage.swapchain = m.eyes[e].handle;
      pv[e].subImage.imageRect = {{0, 0}, {m.eyes[e].width, m.eyes[e].height}};
    }
    projection.space = m.local;
    projection.viewCount = 2;
    projection.views = pv.data();
    layers.push_back(reinterpret_cast<const XrCompositionLayerBaseHeader*>(&projection));
    for (const XrCompositionLayerQuad& q : m.quad_layers)
      layers.push_back(reinterpret_cast<const XrCompositionLayerBaseHeader*>(&q));
  }
  auto ei = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
  ei.displayTime = m.xr_time;
  ei.environmentBlendMode = m.blend;
  ei.layerCount = static_cast<std::uint32_t>(layers.size());
  ei.layers = layers.data();
  const XrResult r = xrEndFrame(m.session, &ei);
  m.restore_context();
  m.frame_begun = false;
  xr_check(r, "xrEndFrame");
}

void OpenXrRuntime::haptic_pulse(Hand hand) {
  Impl& m = *impl_;
  if (!m.lifecycle.running()) return;
  auto hi = xr_struct<XrHapticActionInfo>(XR_TYPE_HAPTIC_ACTION_INFO);
  hi.action = m.actions[static_cast<int>(OpenXrAction::Haptic)];
  hi.subactionPath = m.hand_paths[static_cast<int>(hand)];
  auto v = xr_struct<XrHapticVibration>(XR_TYPE_HAPTIC_VIBRATION);
  v.duration = 30'000'000;  // 30 ms: felt, not distracting
  v.frequency = XR_FREQUENCY_UNSPECIFIED;
  v.amplitude = 0.6f;
  xr_check(xrApplyHapticFeedback(m.session, &hi, reinterpret_cast<XrHapticBaseHeader*>(&v)),
           "xrApplyHapticFeedback");
}

int OpenXrRuntime::context_restores() const {
  return impl_->context_restores;
}

bool OpenXrRuntime::has_epoch() const {
  return impl_->epoch.has_value();
}

std::int64_t OpenXrRuntime::to_xr_time(std::int64_t loop_ns) const {
  return loop_ns + impl_->epoch.value_or(0);
}

}  // namespace vdfx::xr
