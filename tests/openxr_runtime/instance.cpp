/// @file
/// @brief Instance, system and view configuration entry points, paths, strings and the event
/// queue (xrPollEvent).
#include <cmath>
#include <cstdio>
#include <cstring>

#include "tests/openxr_runtime/capture.h"
#include "tests/openxr_runtime/entry_points.h"
#include "tests/openxr_runtime/session_state.h"

namespace vdfx::test_runtime::api {
namespace {

constexpr const char* kRuntimeName = "vdfx test runtime";
constexpr XrVersion kRuntimeVersion = XR_MAKE_VERSION(0, 1, 0);
constexpr XrVersion kMinGlVersion = XR_MAKE_VERSION(3, 3, 0);
constexpr XrVersion kMaxGlVersion = XR_MAKE_VERSION(4, 6, 0);

/// The extensions offered: OpenGL unless VDFX_TEST_RUNTIME_NO_OPENGL=1 (a runtime without it),
/// XR_FB_display_refresh_rate when VDFX_TEST_RUNTIME_REFRESH_RATES lists rates.
std::vector<XrExtensionProperties> offered_extensions(bool opengl, bool refresh_rate) {
  std::vector<XrExtensionProperties> out;
  const auto offer = [&](const char* name, std::uint32_t version) {
    XrExtensionProperties p{};
    p.type = XR_TYPE_EXTENSION_PROPERTIES;
    std::snprintf(p.extensionName, sizeof p.extensionName, "%s", name);
    p.extensionVersion = version;
    out.push_back(p);
  };
  if (opengl) offer(XR_KHR_OPENGL_ENABLE_EXTENSION_NAME, XR_KHR_opengl_enable_SPEC_VERSION);
  if (refresh_rate)
    offer(XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME, XR_FB_display_refresh_rate_SPEC_VERSION);
  return out;
}

XrResult check_system(const char* fn, const Instance& inst, XrSystemId id) {
  if (id != kSystemId || !inst.system_found) {
    return fail(fn, XR_ERROR_SYSTEM_INVALID,
                "systemId " + std::to_string(id) + " was not returned by xrGetSystem");
  }
  return XR_SUCCESS;
}

XrResult check_view_config(const char* fn, XrViewConfigurationType type) {
  if (type == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) return XR_SUCCESS;
  if (type == XR_VIEW_CONFIGURATION_TYPE_PRIMARY_MONO) {
    return fail(fn, XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED,
                "the simulated headset has the stereo view configuration only");
  }
  return fail(fn, XR_ERROR_VALIDATION_FAILURE,
              "not a view configuration type: " + std::to_string(type));
}

/// The headset, script and knobs of a new instance; throws with a message naming the file.
std::unique_ptr<Instance> make_instance() {
  auto inst = std::make_unique<Instance>();
  inst->config = read_config_from_environment();
  if (!inst->config.script_path.empty()) {
    inst->script = read_script(inst->config.script_path);
    for (const auto& w : inst->script->warnings)
      std::fprintf(stderr, "vdfx-test-runtime: %s\n", w.c_str());
  }
  std::string hmd = inst->config.hmd;
  if (hmd.empty() && inst->script && !inst->script->hmd.empty() && inst->script->hmd != "sim") {
    hmd = inst->script->hmd;
  }
  inst->hmd = load_hmd(hmd.empty() ? "generic90" : hmd);
  // With XR_FB_display_refresh_rate the display runs at the headset's own rate when it is one of
  // those offered, else at the first one offered.
  const std::vector<float>& rates = inst->config.refresh_rates;
  if (!rates.empty()) {
    inst->refresh_hz = rates.front();
    for (const float hz : rates)
      if (std::abs(hz - inst->hmd.refresh_hz) < 0.01) inst->refresh_hz = hz;
  }
  return inst;
}

}  // namespace

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateApiLayerProperties(uint32_t capacity, uint32_t* count,
                                                             XrApiLayerProperties* properties) {
  // The loader answers this itself; a runtime has no layers.
  return guarded("xrEnumerateApiLayerProperties", [&] {
    return two_call("xrEnumerateApiLayerProperties", capacity, count, properties, 0,
                    [](XrApiLayerProperties&, std::size_t) { return XR_SUCCESS; });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateInstanceExtensionProperties(
    const char* layerName, uint32_t capacity, uint32_t* count, XrExtensionProperties* properties) {
  constexpr const char* fn = "xrEnumerateInstanceExtensionProperties";
  return guarded(fn, [&] {
    if (layerName) return fail(fn, XR_ERROR_API_LAYER_NOT_PRESENT, "the runtime has no layers");
    const auto offered = offered_extensions(opengl_offered_from_environment(),
                                            refresh_rate_offered_from_environment());
    return two_call(
        fn, capacity, count, properties, offered.size(),
        [&](XrExtensionProperties& p, std::size_t i) {
          const XrResult r = check_struct(fn, "properties[i]", &p, XR_TYPE_EXTENSION_PROPERTIES);
          if (XR_FAILED(r)) return r;
          std::memcpy(p.extensionName, offered[i].extensionName, sizeof p.extensionName);
          p.extensionVersion = offered[i].extensionVersion;
          return XR_SUCCESS;
        });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrCreateInstance(const XrInstanceCreateInfo* info,
                                                XrInstance* instance) {
  constexpr const char* fn = "xrCreateInstance";
  return guarded(fn, [&] {
    XrResult r = check_struct(fn, "createInfo", info, XR_TYPE_INSTANCE_CREATE_INFO,
                              {XR_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT});
    if (XR_FAILED(r)) return r;
    if (!instance) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "instance is null");
    if (live_instance()) {
      return fail(fn, XR_ERROR_LIMIT_REACHED, "one instance at a time: destroy the other first");
    }
    if (XR_VERSION_MAJOR(info->applicationInfo.apiVersion) != 1) {
      return fail(fn, XR_ERROR_API_VERSION_UNSUPPORTED, "the runtime implements OpenXR 1.0");
    }
    if (info->applicationInfo.applicationName[0] == '\0') {
      return fail(fn, XR_ERROR_NAME_INVALID, "applicationInfo.applicationName is empty");
    }
    auto inst = make_instance();
    const auto offered =
        offered_extensions(!inst->config.no_opengl, !inst->config.refresh_rates.empty());
    for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
      const std::string name = info->enabledExtensionNames[i];
      bool found = false;
      for (const auto& p : offered) found = found || name == p.extensionName;
      if (!found) {
        return fail(fn, XR_ERROR_EXTENSION_NOT_PRESENT, "the runtime does not offer " + name);
      }
      inst->gl_enabled = inst->gl_enabled || name == XR_KHR_OPENGL_ENABLE_EXTENSION_NAME;
      inst->refresh_rate_enabled =
          inst->refresh_rate_enabled || name == XR_FB_DISPLAY_REFRESH_RATE_EXTENSION_NAME;
    }
    inst->app_name = info->applicationInfo.applicationName;
    live_instance() = std::move(inst);
    *instance = to_handle<XrInstance>(live_instance().get());
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrDestroyInstance(XrInstance instance) {
  constexpr const char* fn = "xrDestroyInstance";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    if (inst->session) {
      if (inst->session->recorder) inst->session->recorder->call(fn, inst->session->waits);
      destroy_session(*inst);
    }
    live_instance().reset();
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetInstanceProperties(XrInstance instance,
                                                       XrInstanceProperties* properties) {
  constexpr const char* fn = "xrGetInstanceProperties";
  return guarded(fn, [&] {
    if (!find_instance(instance)) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r =
        check_struct(fn, "instanceProperties", properties, XR_TYPE_INSTANCE_PROPERTIES);
    if (XR_FAILED(r)) return r;
    properties->runtimeVersion = kRuntimeVersion;
    std::strncpy(properties->runtimeName, kRuntimeName, XR_MAX_RUNTIME_NAME_SIZE);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrPollEvent(XrInstance instance, XrEventDataBuffer* eventData) {
  constexpr const char* fn = "xrPollEvent";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r = check_struct(fn, "eventData", eventData, XR_TYPE_EVENT_DATA_BUFFER);
    if (XR_FAILED(r)) return r;
    return pop_event(*inst, *eventData);
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrResultToString(XrInstance instance, XrResult value,
                                                char buffer[XR_MAX_RESULT_STRING_SIZE]) {
  return guarded("xrResultToString", [&] {
    if (!find_instance(instance)) {
      return fail("xrResultToString", XR_ERROR_HANDLE_INVALID, "unknown instance");
    }
    const std::string name = result_name(value);
    std::strncpy(buffer, name.c_str(), XR_MAX_RESULT_STRING_SIZE - 1);
    buffer[XR_MAX_RESULT_STRING_SIZE - 1] = '\0';
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrStructureTypeToString(XrInstance instance, XrStructureType value,
                                                       char buffer[XR_MAX_STRUCTURE_NAME_SIZE]) {
  return guarded("xrStructureTypeToString", [&] {
    if (!find_instance(instance)) {
      return fail("xrStructureTypeToString", XR_ERROR_HANDLE_INVALID, "unknown instance");
    }
    const std::string name = structure_type_name(value);
    std::strncpy(buffer, name.c_str(), XR_MAX_STRUCTURE_NAME_SIZE - 1);
    buffer[XR_MAX_STRUCTURE_NAME_SIZE - 1] = '\0';
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetSystem(XrInstance instance, const XrSystemGetInfo* getInfo,
                                           XrSystemId* systemId) {
  constexpr const char* fn = "xrGetSystem";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r = check_struct(fn, "getInfo", getInfo, XR_TYPE_SYSTEM_GET_INFO);
    if (XR_FAILED(r)) return r;
    if (!systemId) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "systemId is null");
    if (getInfo->formFactor == XR_FORM_FACTOR_HANDHELD_DISPLAY) {
      return fail(fn, XR_ERROR_FORM_FACTOR_UNSUPPORTED, "the runtime simulates a headset only");
    }
    if (getInfo->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) {
      return fail(fn, XR_ERROR_VALIDATION_FAILURE, "not a form factor");
    }
    const int call = inst->get_system_calls++;
    if (inst->config.hmd_always_absent || call < inst->config.hmd_absent_calls) {
      // Not reported on stderr: an app asking again until the headset is on is normal.
      return XR_ERROR_FORM_FACTOR_UNAVAILABLE;
    }
    inst->system_found = true;
    *systemId = kSystemId;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetSystemProperties(XrInstance instance, XrSystemId systemId,
                                                     XrSystemProperties* properties) {
  constexpr const char* fn = "xrGetSystemProperties";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_system(fn, *inst, systemId);
    if (XR_FAILED(r)) return r;
    r = check_struct(fn, "properties", properties, XR_TYPE_SYSTEM_PROPERTIES);
    if (XR_FAILED(r)) return r;
    properties->systemId = kSystemId;
    properties->vendorId = 0;
    const std::string name = std::string(kRuntimeName) + ": " + inst->hmd.name;
    std::strncpy(properties->systemName, name.c_str(), XR_MAX_SYSTEM_NAME_SIZE - 1);
    properties->systemName[XR_MAX_SYSTEM_NAME_SIZE - 1] = '\0';
    properties->graphicsProperties = {kMaxSwapchainSize, kMaxSwapchainSize, kMaxLayerCount};
    properties->trackingProperties = {XR_TRUE, XR_TRUE};
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateEnvironmentBlendModes(XrInstance instance,
                                                                XrSystemId systemId,
                                                                XrViewConfigurationType type,
                                                                uint32_t capacity, uint32_t* count,
                                                                XrEnvironmentBlendMode* modes) {
  constexpr const char* fn = "xrEnumerateEnvironmentBlendModes";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_system(fn, *inst, systemId);
    if (XR_SUCCEEDED(r)) r = check_view_config(fn, type);
    if (XR_FAILED(r)) return r;
    return two_call(fn, capacity, count, modes, 1, [](XrEnvironmentBlendMode& m, std::size_t) {
      m = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateViewConfigurations(XrInstance instance,
                                                             XrSystemId systemId, uint32_t capacity,
                                                             uint32_t* count,
                                                             XrViewConfigurationType* types) {
  constexpr const char* fn = "xrEnumerateViewConfigurations";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const XrResult r = check_system(fn, *inst, systemId);
    if (XR_FAILED(r)) return r;
    return two_call(fn, capacity, count, types, 1, [](XrViewConfigurationType& t, std::size_t) {
      t = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetViewConfigurationProperties(
    XrInstance instance, XrSystemId systemId, XrViewConfigurationType type,
    XrViewConfigurationProperties* properties) {
  constexpr const char* fn = "xrGetViewConfigurationProperties";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_system(fn, *inst, systemId);
    if (XR_SUCCEEDED(r)) r = check_view_config(fn, type);
    if (XR_SUCCEEDED(r)) {
      r = check_struct(fn, "configurationProperties", properties,
                       XR_TYPE_VIEW_CONFIGURATION_PROPERTIES);
    }
    if (XR_FAILED(r)) return r;
    properties->viewConfigurationType = type;
    properties->fovMutable = XR_TRUE;
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrEnumerateViewConfigurationViews(XrInstance instance,
                                                                 XrSystemId systemId,
                                                                 XrViewConfigurationType type,
                                                                 uint32_t capacity, uint32_t* count,
                                                                 XrViewConfigurationView* views) {
  constexpr const char* fn = "xrEnumerateViewConfigurationViews";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_system(fn, *inst, systemId);
    if (XR_SUCCEEDED(r)) r = check_view_config(fn, type);
    if (XR_FAILED(r)) return r;
    return two_call(fn, capacity, count, views, 2, [&](XrViewConfigurationView& v, std::size_t i) {
      const XrResult c = check_struct(fn, "views[i]", &v, XR_TYPE_VIEW_CONFIGURATION_VIEW);
      if (XR_FAILED(c)) return c;
      v.recommendedImageRectWidth = static_cast<uint32_t>(inst->hmd.eyes[i].width);
      v.recommendedImageRectHeight = static_cast<uint32_t>(inst->hmd.eyes[i].height);
      v.maxImageRectWidth = kMaxSwapchainSize;
      v.maxImageRectHeight = kMaxSwapchainSize;
      v.recommendedSwapchainSampleCount = 1;
      v.maxSwapchainSampleCount = 1;
      return XR_SUCCESS;
    });
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrStringToPath(XrInstance instance, const char* pathString,
                                              XrPath* path) {
  constexpr const char* fn = "xrStringToPath";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    if (!pathString || !path) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "null argument");
    if (!is_well_formed_path(pathString)) {
      return fail(fn, XR_ERROR_PATH_FORMAT_INVALID,
                  std::string("'") + pathString + "' is not a well-formed path");
    }
    *path = inst->paths.get(pathString);
    return XR_SUCCESS;
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrPathToString(XrInstance instance, XrPath path, uint32_t capacity,
                                              uint32_t* count, char* buffer) {
  constexpr const char* fn = "xrPathToString";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    const std::string* s = inst->paths.str(path);
    if (!s) return fail(fn, XR_ERROR_PATH_INVALID, "unknown path " + std::to_string(path));
    return two_call_string(fn, capacity, count, buffer, *s);
  });
}

XRAPI_ATTR XrResult XRAPI_CALL xrGetOpenGLGraphicsRequirementsKHR(
    XrInstance instance, XrSystemId systemId, XrGraphicsRequirementsOpenGLKHR* requirements) {
  constexpr const char* fn = "xrGetOpenGLGraphicsRequirementsKHR";
  return guarded(fn, [&] {
    Instance* inst = find_instance(instance);
    if (!inst) return fail(fn, XR_ERROR_HANDLE_INVALID, "unknown instance");
    XrResult r = check_system(fn, *inst, systemId);
    if (XR_SUCCEEDED(r)) {
      r = check_struct(fn, "graphicsRequirements", requirements,
                       XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR);
    }
    if (XR_FAILED(r)) return r;
    requirements->minApiVersionSupported = kMinGlVersion;
    requirements->maxApiVersionSupported = kMaxGlVersion;
    inst->gl_requirements_queried = true;
    return XR_SUCCESS;
  });
}

}  // namespace vdfx::test_runtime::api
