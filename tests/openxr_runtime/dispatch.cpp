/// @file
/// @brief The loader's way in: xrNegotiateLoaderRuntimeInterface (the library's one exported
/// symbol) and xrGetInstanceProcAddr over every entry point; anything else is
/// XR_ERROR_FUNCTION_UNSUPPORTED.
///
/// The negotiation structs are those of the OpenXR loader's runtime interface (the loader
/// documentation, "Runtime Interface Negotiation"); OpenXR 1.0.20's installed headers do not
/// declare them (openxr_loader_negotiation.h came with 1.0.29), so they are declared here with
/// the layout the loader passes.
#include <cstring>
#include <map>
#include <string>

#include "tests/openxr_runtime/entry_points.h"

namespace vdfx::test_runtime {

enum XrLoaderInterfaceStructs {
  XR_LOADER_INTERFACE_STRUCT_UNINTIALIZED = 0,
  XR_LOADER_INTERFACE_STRUCT_LOADER_INFO,
  XR_LOADER_INTERFACE_STRUCT_API_LAYER_REQUEST,
  XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST,
};
constexpr std::uint32_t kLoaderInfoStructVersion = 1;
constexpr std::uint32_t kRuntimeInfoStructVersion = 1;
constexpr std::uint32_t kRuntimeInterfaceVersion = 1;

struct XrNegotiateLoaderInfo {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion;
  std::uint32_t maxInterfaceVersion;
  XrVersion minApiVersion;
  XrVersion maxApiVersion;
};

struct XrNegotiateRuntimeRequest {
  XrLoaderInterfaceStructs structType;
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
};

namespace {

/// The extension an entry point belongs to: given only to an instance that enabled it.
enum class Extension { kNone, kOpenGl, kRefreshRate };

struct Entry {
  PFN_xrVoidFunction function;
  bool needs_instance;  //!< false for the three a null instance may ask for
  Extension extension;
};

template <class F>
PFN_xrVoidFunction as_void(F* f) {
  return reinterpret_cast<PFN_xrVoidFunction>(f);
}

const std::map<std::string, Entry>& entries() {
#define VDFX_ENTRY(name)                          \
  {                                               \
#name, {                                      \
      as_void(&api::name), true, Extension::kNone \
    }                                             \
  }
  static const std::map<std::string, Entry> table{
      {"xrGetInstanceProcAddr", {as_void(&api::xrGetInstanceProcAddr), false, Extension::kNone}},
      {"xrEnumerateApiLayerProperties",
       {as_void(&api::xrEnumerateApiLayerProperties), false, Extension::kNone}},
      {"xrEnumerateInstanceExtensionProperties",
       {as_void(&api::xrEnumerateInstanceExtensionProperties), false, Extension::kNone}},
      {"xrCreateInstance", {as_void(&api::xrCreateInstance), false, Extension::kNone}},
      {"xrGetOpenGLGraphicsRequirementsKHR",
       {as_void(&api::xrGetOpenGLGraphicsRequirementsKHR), true, Extension::kOpenGl}},
      {"xrEnumerateDisplayRefreshRatesFB",
       {as_void(&api::xrEnumerateDisplayRefreshRatesFB), true, Extension::kRefreshRate}},
      {"xrGetDisplayRefreshRateFB",
       {as_void(&api::xrGetDisplayRefreshRateFB), true, Extension::kRefreshRate}},
      {"xrRequestDisplayRefreshRateFB",
       {as_void(&api::xrRequestDisplayRefreshRateFB), true, Extension::kRefreshRate}},
      VDFX_ENTRY(xrDestroyInstance),
      VDFX_ENTRY(xrGetInstanceProperties),
      VDFX_ENTRY(xrPollEvent),
      VDFX_ENTRY(xrResultToString),
      VDFX_ENTRY(xrStructureTypeToString),
      VDFX_ENTRY(xrGetSystem),
      VDFX_ENTRY(xrGetSystemProperties),
      VDFX_ENTRY(xrEnumerateEnvironmentBlendModes),
      VDFX_ENTRY(xrCreateSession),
      VDFX_ENTRY(xrDestroySession),
      VDFX_ENTRY(xrEnumerateReferenceSpaces),
      VDFX_ENTRY(xrCreateReferenceSpace),
      VDFX_ENTRY(xrGetReferenceSpaceBoundsRect),
      VDFX_ENTRY(xrCreateActionSpace),
      VDFX_ENTRY(xrLocateSpace),
      VDFX_ENTRY(xrDestroySpace),
      VDFX_ENTRY(xrEnumerateViewConfigurations),
      VDFX_ENTRY(xrGetViewConfigurationProperties),
      VDFX_ENTRY(xrEnumerateViewConfigurationViews),
      VDFX_ENTRY(xrEnumerateSwapchainFormats),
      VDFX_ENTRY(xrCreateSwapchain),
      VDFX_ENTRY(xrDestroySwapchain),
      VDFX_ENTRY(xrEnumerateSwapchainImages),
      VDFX_ENTRY(xrAcquireSwapchainImage),
      VDFX_ENTRY(xrWaitSwapchainImage),
      VDFX_ENTRY(xrReleaseSwapchainImage),
      VDFX_ENTRY(xrBeginSession),
      VDFX_ENTRY(xrEndSession),
      VDFX_ENTRY(xrRequestExitSession),
      VDFX_ENTRY(xrWaitFrame),
      VDFX_ENTRY(xrBeginFrame),
      VDFX_ENTRY(xrEndFrame),
      VDFX_ENTRY(xrLocateViews),
      VDFX_ENTRY(xrStringToPath),
      VDFX_ENTRY(xrPathToString),
      VDFX_ENTRY(xrCreateActionSet),
      VDFX_ENTRY(xrDestroyActionSet),
      VDFX_ENTRY(xrCreateAction),
      VDFX_ENTRY(xrDestroyAction),
      VDFX_ENTRY(xrSuggestInteractionProfileBindings),
      VDFX_ENTRY(xrAttachSessionActionSets),
      VDFX_ENTRY(xrGetCurrentInteractionProfile),
      VDFX_ENTRY(xrGetActionStateBoolean),
      VDFX_ENTRY(xrGetActionStateFloat),
      VDFX_ENTRY(xrGetActionStateVector2f),
      VDFX_ENTRY(xrGetActionStatePose),
      VDFX_ENTRY(xrSyncActions),
      VDFX_ENTRY(xrEnumerateBoundSourcesForAction),
      VDFX_ENTRY(xrGetInputSourceLocalizedName),
      VDFX_ENTRY(xrApplyHapticFeedback),
      VDFX_ENTRY(xrStopHapticFeedback),
  };
#undef VDFX_ENTRY
  return table;
}

}  // namespace

namespace api {

XRAPI_ATTR XrResult XRAPI_CALL xrGetInstanceProcAddr(XrInstance instance, const char* name,
                                                     PFN_xrVoidFunction* function) {
  constexpr const char* fn = "xrGetInstanceProcAddr";
  if (!name || !function) return fail(fn, XR_ERROR_VALIDATION_FAILURE, "null argument");
  *function = nullptr;
  const auto it = entries().find(name);
  std::lock_guard<std::mutex> lock(runtime_mutex());
  const Instance* inst = instance == XR_NULL_HANDLE ? nullptr : find_instance(instance);
  if (instance != XR_NULL_HANDLE && !inst) {
    return fail(fn, XR_ERROR_HANDLE_INVALID, std::string("unknown instance asking for ") + name);
  }
  if (it == entries().end()) return XR_ERROR_FUNCTION_UNSUPPORTED;  // not reported: normal
  if (!inst && it->second.needs_instance) {
    return fail(fn, XR_ERROR_HANDLE_INVALID, std::string(name) + " needs an instance");
  }
  const Extension ext = it->second.extension;
  if ((ext == Extension::kOpenGl && !inst->gl_enabled) ||
      (ext == Extension::kRefreshRate && !inst->refresh_rate_enabled))
    return XR_ERROR_FUNCTION_UNSUPPORTED;
  *function = it->second.function;
  return XR_SUCCESS;
}

}  // namespace api
}  // namespace vdfx::test_runtime

extern "C" __attribute__((visibility("default"))) XrResult XRAPI_CALL
xrNegotiateLoaderRuntimeInterface(const vdfx::test_runtime::XrNegotiateLoaderInfo* loaderInfo,
                                  vdfx::test_runtime::XrNegotiateRuntimeRequest* runtimeRequest) {
  using namespace vdfx::test_runtime;
  constexpr const char* fn = "xrNegotiateLoaderRuntimeInterface";
  if (!loaderInfo || !runtimeRequest ||
      loaderInfo->structType != XR_LOADER_INTERFACE_STRUCT_LOADER_INFO ||
      loaderInfo->structVersion != kLoaderInfoStructVersion ||
      loaderInfo->structSize != sizeof(XrNegotiateLoaderInfo) ||
      runtimeRequest->structType != XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST ||
      runtimeRequest->structVersion != kRuntimeInfoStructVersion ||
      runtimeRequest->structSize != sizeof(XrNegotiateRuntimeRequest)) {
    return fail(fn, XR_ERROR_INITIALIZATION_FAILED, "the loader's structs are not version 1");
  }
  if (loaderInfo->minInterfaceVersion > kRuntimeInterfaceVersion ||
      loaderInfo->maxInterfaceVersion < kRuntimeInterfaceVersion ||
      XR_VERSION_MAJOR(loaderInfo->maxApiVersion) < 1 ||
      XR_VERSION_MAJOR(loaderInfo->minApiVersion) > 1) {
    return fail(fn, XR_ERROR_INITIALIZATION_FAILED,
                "the loader wants an interface or API version the runtime does not have");
  }
  runtimeRequest->runtimeInterfaceVersion = kRuntimeInterfaceVersion;
  runtimeRequest->runtimeApiVersion = XR_CURRENT_API_VERSION;
  runtimeRequest->getInstanceProcAddr = &api::xrGetInstanceProcAddr;
  return XR_SUCCESS;
}
