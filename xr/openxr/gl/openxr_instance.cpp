/// @file
/// @brief The OpenXR backend's instance side: instance, system, views, actions and their
/// suggested bindings; the errors a user can fix are OpenXrUnavailable (exit 1).
#include <openxr/openxr_reflection.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <thread>

#include "io/library_logs.h"
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime_impl.h"

namespace vdfx::xr {

const char* xr_result_name(XrResult result) {
  switch (result) {
#define VDFX_XR_RESULT_CASE(name, value) \
  case name: return #name;
    XR_LIST_ENUM_XrResult(VDFX_XR_RESULT_CASE)
#undef VDFX_XR_RESULT_CASE
        default : return "an unknown XrResult";
  }
}

OpenXrCallError::OpenXrCallError(const char* call, XrResult result)
    : std::runtime_error(std::string(call) + " failed: " + xr_result_name(result)),
      result_(result) {}

void xr_check(XrResult result, const char* call) {
  if (result == XR_ERROR_SESSION_LOST)
    throw OpenXrSessionLost(std::string(call) + " answered XR_ERROR_SESSION_LOST");
  if (XR_FAILED(result)) throw OpenXrCallError(call, result);
}

namespace {

constexpr const char* kInstallHint = "install Monado, or set XR_RUNTIME_JSON";

/// The message for a loader that found no usable runtime: the variable's value when set.
std::string no_runtime_message(XrResult result) {
  const char* json = std::getenv("XR_RUNTIME_JSON");
  std::string m = "no OpenXR runtime: ";
  m += kInstallHint;
  m += " (the loader said ";
  m += xr_result_name(result);
  if (json && *json)
    m += std::string("; XR_RUNTIME_JSON=") + json + " names no runtime it can load";
  return m + "; docs/openxr.md lists the runtimes)";
}

bool is_no_runtime(XrResult r) {
  return r == XR_ERROR_RUNTIME_UNAVAILABLE || r == XR_ERROR_RUNTIME_FAILURE ||
         r == XR_ERROR_INSTANCE_LOST || r == XR_ERROR_INITIALIZATION_FAILED ||
         r == XR_ERROR_API_VERSION_UNSUPPORTED;
}

std::string version_text(XrVersion v) {
  return std::to_string(XR_VERSION_MAJOR(v)) + "." + std::to_string(XR_VERSION_MINOR(v)) + "." +
         std::to_string(XR_VERSION_PATCH(v));
}

const char* blend_name(XrEnvironmentBlendMode m) {
  switch (m) {
    case XR_ENVIRONMENT_BLEND_MODE_OPAQUE: return "OPAQUE";
    case XR_ENVIRONMENT_BLEND_MODE_ADDITIVE: return "ADDITIVE";
    case XR_ENVIRONMENT_BLEND_MODE_ALPHA_BLEND: return "ALPHA_BLEND";
    default: return "?";
  }
}

}  // namespace

void OpenXrRuntime::Impl::create_instance() {
  std::uint32_t n = 0;
  XrResult r = xrEnumerateInstanceExtensionProperties(nullptr, 0, &n, nullptr);
  if (XR_FAILED(r)) throw OpenXrUnavailable(no_runtime_message(r));
  std::vector<XrExtensionProperties> ext(
      n, xr_struct<XrExtensionProperties>(XR_TYPE_EXTENSION_PROPERTIES));
  xr_check(xrEnumerateInstanceExtensionProperties(nullptr, n, &n, ext.data()),
           "xrEnumerateInstanceExtensionProperties");
  for (const auto& e : ext) info.extensions.emplace_back(e.extensionName);
  const bool gl = std::count(info.extensions.begin(), info.extensions.end(),
                             XR_KHR_OPENGL_ENABLE_EXTENSION_NAME) > 0;

  auto ci = xr_struct<XrInstanceCreateInfo>(XR_TYPE_INSTANCE_CREATE_INFO);
  std::snprintf(ci.applicationInfo.applicationName, XR_MAX_APPLICATION_NAME_SIZE, "%s",
                options.application_name.c_str());
  ci.applicationInfo.applicationVersion = 1;
  std::snprintf(ci.applicationInfo.engineName, XR_MAX_ENGINE_NAME_SIZE, "vdfx");
  ci.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
  const char* names[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME};
  // Without the extension the instance is made anyway, so the message can name the runtime.
  ci.enabledExtensionCount = gl ? 1 : 0;
  ci.enabledExtensionNames = names;
  r = xrCreateInstance(&ci, &instance);
  if (is_no_runtime(r)) throw OpenXrUnavailable(no_runtime_message(r));
  xr_check(r, "xrCreateInstance");

  auto props = xr_struct<XrInstanceProperties>(XR_TYPE_INSTANCE_PROPERTIES);
  xr_check(xrGetInstanceProperties(instance, &props), "xrGetInstanceProperties");
  info.runtime_name = props.runtimeName;
  info.runtime_version = version_text(props.runtimeVersion);
  if (!gl)
    throw OpenXrUnavailable("the OpenXR runtime '" + info.runtime_name + "' does not offer " +
                            XR_KHR_OPENGL_ENABLE_EXTENSION_NAME +
                            ": vdfx renders with OpenGL; use a runtime with OpenGL support "
                            "(Monado, SteamVR; docs/openxr.md)");
}

void OpenXrRuntime::Impl::get_system() {
  auto gi = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
  gi.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
  const auto deadline = std::chrono::steady_clock::now() + options.headset_wait;
  XrResult r = xrGetSystem(instance, &gi, &system);
  // A headset being switched on, or a streaming client still joining, answers "unavailable" for
  // a moment: wait a little before saying none is there.
  while (r == XR_ERROR_FORM_FACTOR_UNAVAILABLE && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    r = xrGetSystem(instance, &gi, &system);
  }
  if (r == XR_ERROR_FORM_FACTOR_UNAVAILABLE || r == XR_ERROR_FORM_FACTOR_UNSUPPORTED) {
    const double s = std::chrono::duration<double>(options.headset_wait).count();
    throw OpenXrUnavailable(
        "no headset connected: the OpenXR runtime '" + info.runtime_name + "' answers " +
        xr_result_name(r) + " (waited " + std::to_string(s).substr(0, 3) +
        " s); connect and switch on the headset (or start its streaming app), then run again");
  }
  xr_check(r, "xrGetSystem");
  auto sp = xr_struct<XrSystemProperties>(XR_TYPE_SYSTEM_PROPERTIES);
  xr_check(xrGetSystemProperties(instance, system, &sp), "xrGetSystemProperties");
  info.system_name = sp.systemName;
  info.vendor_id = sp.vendorId;
  info.max_layers = sp.graphicsProperties.maxLayerCount;
  info.orientation_tracking = sp.trackingProperties.orientationTracking == XR_TRUE;
  info.position_tracking = sp.trackingProperties.positionTracking == XR_TRUE;
}

void OpenXrRuntime::Impl::read_views() {
  const XrViewConfigurationType stereo = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  std::uint32_t n = 0;
  xr_check(xrEnumerateViewConfigurations(instance, system, 0, &n, nullptr),
           "xrEnumerateViewConfigurations");
  std::vector<XrViewConfigurationType> types(n);
  xr_check(xrEnumerateViewConfigurations(instance, system, n, &n, types.data()),
           "xrEnumerateViewConfigurations");
  if (std::find(types.begin(), types.end(), stereo) == types.end())
    throw OpenXrUnavailable("the headset of the OpenXR runtime '" + info.runtime_name +
                            "' offers no stereo view configuration (PRIMARY_STEREO)");
  xr_check(xrEnumerateViewConfigurationViews(instance, system, stereo, 0, &n, nullptr),
           "xrEnumerateViewConfigurationViews");
  std::vector<XrViewConfigurationView> views(
      n, xr_struct<XrViewConfigurationView>(XR_TYPE_VIEW_CONFIGURATION_VIEW));
  xr_check(xrEnumerateViewConfigurationViews(instance, system, stereo, n, &n, views.data()),
           "xrEnumerateViewConfigurationViews");
  for (const auto& v : views)
    info.views.push_back({static_cast<int>(v.recommendedImageRectWidth),
                          static_cast<int>(v.recommendedImageRectHeight),
                          static_cast<int>(v.maxImageRectWidth),
                          static_cast<int>(v.maxImageRectHeight),
                          static_cast<int>(v.recommendedSwapchainSampleCount),
                          static_cast<int>(v.maxSwapchainSampleCount)});
  if (info.views.size() != 2)
    throw OpenXrUnavailable("the stereo view configuration of '" + info.runtime_name + "' has " +
                            std::to_string(info.views.size()) + " views, not 2");
  xr_check(xrEnumerateEnvironmentBlendModes(instance, system, stereo, 0, &n, nullptr),
           "xrEnumerateEnvironmentBlendModes");
  std::vector<XrEnvironmentBlendMode> modes(n);
  xr_check(xrEnumerateEnvironmentBlendModes(instance, system, stereo, n, &n, modes.data()),
           "xrEnumerateEnvironmentBlendModes");
  for (const auto m : modes) info.blend_modes.emplace_back(blend_name(m));
  // A 360 video fills the view: opaque where offered, else the runtime's first (its preferred).
  if (!modes.empty() &&
      std::find(modes.begin(), modes.end(), XR_ENVIRONMENT_BLEND_MODE_OPAQUE) == modes.end())
    blend = modes.front();
}

void OpenXrRuntime::Impl::create_actions() {
  auto si = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
  std::snprintf(si.actionSetName, sizeof si.actionSetName, "%s", kOpenXrActionSetName.data());
  std::snprintf(si.localizedActionSetName, sizeof si.localizedActionSetName, "%s",
                kOpenXrActionSetLocalizedName.data());
  xr_check(xrCreateActionSet(instance, &si, &action_set), "xrCreateActionSet");
  for (const Hand h : {Hand::Left, Hand::Right})
    xr_check(xrStringToPath(instance, std::string(hand_path(h)).c_str(),
                            &hand_paths[static_cast<int>(h)]),
             "xrStringToPath");
  for (const OpenXrActionSpec& a : openxr_actions()) {
    auto ai = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    std::snprintf(ai.actionName, sizeof ai.actionName, "%s", a.name.data());
    std::snprintf(ai.localizedActionName, sizeof ai.localizedActionName, "%s",
                  a.localized_name.data());
    switch (a.type) {
      case OpenXrActionType::Boolean: ai.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT; break;
      case OpenXrActionType::Float: ai.actionType = XR_ACTION_TYPE_FLOAT_INPUT; break;
      case OpenXrActionType::Vector2: ai.actionType = XR_ACTION_TYPE_VECTOR2F_INPUT; break;
      case OpenXrActionType::Pose: ai.actionType = XR_ACTION_TYPE_POSE_INPUT; break;
      case OpenXrActionType::Vibration: ai.actionType = XR_ACTION_TYPE_VIBRATION_OUTPUT; break;
    }
    ai.countSubactionPaths = 2;
    ai.subactionPaths = hand_paths.data();
    xr_check(xrCreateAction(action_set, &ai, &actions[static_cast<int>(a.action)]),
             "xrCreateAction");
  }
  // Each profile alone: a runtime that does not know one refuses that one only.
  for (const OpenXrProfileBindings& p : openxr_suggested_bindings()) {
    std::vector<XrActionSuggestedBinding> suggested;
    XrPath profile = XR_NULL_PATH;
    xr_check(xrStringToPath(instance, p.profile.c_str(), &profile), "xrStringToPath");
    for (const OpenXrBinding& b : p.bindings) {
      XrPath path = XR_NULL_PATH;
      xr_check(xrStringToPath(instance, b.path.c_str(), &path), "xrStringToPath");
      suggested.push_back({actions[static_cast<int>(b.action)], path});
    }
    auto sb = xr_struct<XrInteractionProfileSuggestedBinding>(
        XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    sb.interactionProfile = profile;
    sb.countSuggestedBindings = static_cast<std::uint32_t>(suggested.size());
    sb.suggestedBindings = suggested.data();
    const XrResult r = xrSuggestInteractionProfileBindings(instance, &sb);
    if (XR_SUCCEEDED(r))
      info.profiles_accepted.push_back(p.profile);
    else
      info.profiles_refused.push_back(p.profile + ": " + xr_result_name(r));
  }
}

OpenXrRuntime::Impl::~Impl() {
  destroy_session();
  if (action_set) xrDestroyActionSet(action_set);
  if (instance) xrDestroyInstance(instance);
}

OpenXrRuntime::OpenXrRuntime(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
OpenXrRuntime::~OpenXrRuntime() = default;

std::unique_ptr<OpenXrRuntime> OpenXrRuntime::create(const OpenXrOptions& options) {
  // vdfx says what failed itself (no runtime: which variable, what to install); the loader's own
  // lines on stderr only bury that, unless --verbose or the user's XR_LOADER_DEBUG asks for them.
  if (io::library_logs_quiet()) setenv("XR_LOADER_DEBUG", "none", 0);
  auto impl = std::make_unique<Impl>();
  impl->options = options;
  impl->create_instance();
  impl->get_system();
  impl->read_views();
  impl->create_actions();
  return std::unique_ptr<OpenXrRuntime>(new OpenXrRuntime(std::move(impl)));
}

const OpenXrSystemInfo& OpenXrRuntime::info() const {
  return impl_->info;
}

std::unique_ptr<InputBackend> OpenXrRuntime::create_input_backend() {
  return create_openxr_input_backend(*this);
}

}  // namespace vdfx::xr
