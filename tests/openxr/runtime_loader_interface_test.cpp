/// @file
/// @brief The runtime library as the loader sees it (the OpenXR loader documentation, "Runtime
/// Interface Negotiation"): one exported symbol, the negotiation, and xrGetInstanceProcAddr
/// answering every OpenXR 1.0 function and refusing the rest.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cstring>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/support/test_paths.h"

namespace vdfx::test_runtime {
namespace {

// The loader's negotiation structs (the documentation's layout; not in OpenXR 1.0.20's headers).
struct LoaderInfo {
  int structType;  // XR_LOADER_INTERFACE_STRUCT_LOADER_INFO = 1
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t minInterfaceVersion, maxInterfaceVersion;
  XrVersion minApiVersion, maxApiVersion;
};
struct RuntimeRequest {
  int structType;  // XR_LOADER_INTERFACE_STRUCT_RUNTIME_REQUEST = 3
  std::uint32_t structVersion;
  std::size_t structSize;
  std::uint32_t runtimeInterfaceVersion;
  XrVersion runtimeApiVersion;
  PFN_xrGetInstanceProcAddr getInstanceProcAddr;
};
using Negotiate = XrResult (*)(const LoaderInfo*, RuntimeRequest*);

class LoaderInterface : public RuntimeTest {
 protected:
  void SetUp() override {
    RuntimeTest::SetUp();
    library_ = dlopen(VDFX_TEST_RUNTIME_LIBRARY, RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(library_, nullptr) << dlerror();
    negotiate_ = reinterpret_cast<Negotiate>(dlsym(library_, "xrNegotiateLoaderRuntimeInterface"));
    ASSERT_NE(negotiate_, nullptr);
  }
  void TearDown() override {
    if (library_) dlclose(library_);
    RuntimeTest::TearDown();
  }
  static LoaderInfo loader_info() {
    return {1, 1, sizeof(LoaderInfo), 1, 1, XR_MAKE_VERSION(1, 0, 0), XR_MAKE_VERSION(1, 0, 1023)};
  }
  static RuntimeRequest request() { return {3, 1, sizeof(RuntimeRequest), 0, 0, nullptr}; }
  /// The runtime's xrGetInstanceProcAddr, from a negotiation that must succeed.
  PFN_xrGetInstanceProcAddr negotiated() {
    const LoaderInfo info = loader_info();
    RuntimeRequest r = request();
    EXPECT_EQ(negotiate_(&info, &r), XR_SUCCESS);
    EXPECT_NE(r.getInstanceProcAddr, nullptr);
    return r.getInstanceProcAddr;
  }
  /// An instance without OpenGL, through the runtime's own xrCreateInstance.
  static XrInstance create_instance(PFN_xrGetInstanceProcAddr gipa) {
    PFN_xrVoidFunction f = nullptr;
    EXPECT_EQ(gipa(XR_NULL_HANDLE, "xrCreateInstance", &f), XR_SUCCESS);
    XrInstanceCreateInfo create{};
    create.type = XR_TYPE_INSTANCE_CREATE_INFO;
    std::strcpy(create.applicationInfo.applicationName, "loader interface test");
    create.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    XrInstance instance = XR_NULL_HANDLE;
    EXPECT_EQ(reinterpret_cast<PFN_xrCreateInstance>(f)(&create, &instance), XR_SUCCESS);
    EXPECT_NE(instance, XR_NULL_HANDLE);
    return instance;
  }
  static void destroy_instance(PFN_xrGetInstanceProcAddr gipa, XrInstance instance) {
    PFN_xrVoidFunction f = nullptr;
    ASSERT_EQ(gipa(instance, "xrDestroyInstance", &f), XR_SUCCESS);
    EXPECT_EQ(reinterpret_cast<PFN_xrDestroyInstance>(f)(instance), XR_SUCCESS);
  }

  void* library_ = nullptr;
  Negotiate negotiate_ = nullptr;
};

TEST_F(LoaderInterface, ExportsTheNegotiationOnly) {
  for (const char* name : {"xrGetInstanceProcAddr", "xrCreateInstance", "xrEndFrame"}) {
    EXPECT_EQ(dlsym(library_, name), nullptr) << name;
  }
}

TEST_F(LoaderInterface, NegotiatesVersionOneAndRefusesOtherStructs) {
  const LoaderInfo info = loader_info();
  RuntimeRequest r = request();
  ASSERT_EQ(negotiate_(&info, &r), XR_SUCCESS);
  EXPECT_EQ(r.runtimeInterfaceVersion, 1u);
  EXPECT_EQ(XR_VERSION_MAJOR(r.runtimeApiVersion), 1u);
  EXPECT_NE(r.getInstanceProcAddr, nullptr);
  LoaderInfo newer = loader_info();
  newer.minInterfaceVersion = newer.maxInterfaceVersion = 2;
  ::testing::internal::CaptureStderr();  // the runtime says why
  EXPECT_EQ(negotiate_(&newer, &r), XR_ERROR_INITIALIZATION_FAILED);
  RuntimeRequest wrong = request();
  wrong.structVersion = 2;
  EXPECT_EQ(negotiate_(&info, &wrong), XR_ERROR_INITIALIZATION_FAILED);
  EXPECT_NE(::testing::internal::GetCapturedStderr().find("xrNegotiateLoaderRuntimeInterface"),
            std::string::npos);
}

// Every function of OpenXR 1.0 core the runtime serves for an instance.
constexpr const char* kCoreFunctions[] = {
    "xrGetInstanceProcAddr",
    "xrEnumerateApiLayerProperties",
    "xrEnumerateInstanceExtensionProperties",
    "xrCreateInstance",
    "xrDestroyInstance",
    "xrGetInstanceProperties",
    "xrPollEvent",
    "xrResultToString",
    "xrStructureTypeToString",
    "xrGetSystem",
    "xrGetSystemProperties",
    "xrEnumerateEnvironmentBlendModes",
    "xrCreateSession",
    "xrDestroySession",
    "xrEnumerateReferenceSpaces",
    "xrCreateReferenceSpace",
    "xrGetReferenceSpaceBoundsRect",
    "xrCreateActionSpace",
    "xrLocateSpace",
    "xrDestroySpace",
    "xrEnumerateViewConfigurations",
    "xrGetViewConfigurationProperties",
    "xrEnumerateViewConfigurationViews",
    "xrEnumerateSwapchainFormats",
    "xrCreateSwapchain",
    "xrDestroySwapchain",
    "xrEnumerateSwapchainImages",
    "xrAcquireSwapchainImage",
    "xrWaitSwapchainImage",
    "xrReleaseSwapchainImage",
    "xrBeginSession",
    "xrEndSession",
    "xrRequestExitSession",
    "xrWaitFrame",
    "xrBeginFrame",
    "xrEndFrame",
    "xrLocateViews",
    "xrStringToPath",
    "xrPathToString",
    "xrCreateActionSet",
    "xrDestroyActionSet",
    "xrCreateAction",
    "xrDestroyAction",
    "xrSuggestInteractionProfileBindings",
    "xrAttachSessionActionSets",
    "xrGetCurrentInteractionProfile",
    "xrGetActionStateBoolean",
    "xrGetActionStateFloat",
    "xrGetActionStateVector2f",
    "xrGetActionStatePose",
    "xrSyncActions",
    "xrEnumerateBoundSourcesForAction",
    "xrGetInputSourceLocalizedName",
    "xrApplyHapticFeedback",
    "xrStopHapticFeedback",
};

TEST_F(LoaderInterface, WithoutAnInstanceServesWhatTheLoaderNeedsFirstOnly) {
  const PFN_xrGetInstanceProcAddr gipa = negotiated();
  PFN_xrVoidFunction f = nullptr;
  for (const char* name : {"xrCreateInstance", "xrEnumerateInstanceExtensionProperties",
                           "xrEnumerateApiLayerProperties"}) {
    EXPECT_EQ(gipa(XR_NULL_HANDLE, name, &f), XR_SUCCESS) << name;
    EXPECT_NE(f, nullptr);
  }
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(gipa(XR_NULL_HANDLE, "xrDestroyInstance", &f), XR_ERROR_HANDLE_INVALID);
  ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(gipa(XR_NULL_HANDLE, "xrFrobnicateVDFX", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(f, nullptr);
}

TEST_F(LoaderInterface, ServesEveryCoreFunctionAndNothingElse) {
  const PFN_xrGetInstanceProcAddr gipa = negotiated();
  const XrInstance instance = create_instance(gipa);
  PFN_xrVoidFunction f = nullptr;
  for (const char* name : kCoreFunctions) {
    f = nullptr;
    EXPECT_EQ(gipa(instance, name, &f), XR_SUCCESS) << name;
    EXPECT_NE(f, nullptr) << name;
  }
  // An extension's function only when the instance enabled it.
  EXPECT_EQ(gipa(instance, "xrGetOpenGLGraphicsRequirementsKHR", &f),
            XR_ERROR_FUNCTION_UNSUPPORTED);
  EXPECT_EQ(gipa(instance, "xrGetVisibilityMaskKHR", &f), XR_ERROR_FUNCTION_UNSUPPORTED);
  destroy_instance(gipa, instance);
}

TEST_F(LoaderInterface, ResultToStringNamesResultsAsTheHeadersDo) {
  const PFN_xrGetInstanceProcAddr gipa = negotiated();
  const XrInstance instance = create_instance(gipa);
  PFN_xrVoidFunction f = nullptr;
  // As the headers name them, and unknown ones by number.
  ASSERT_EQ(gipa(instance, "xrResultToString", &f), XR_SUCCESS);
  char text[XR_MAX_RESULT_STRING_SIZE];
  reinterpret_cast<PFN_xrResultToString>(f)(instance, XR_ERROR_SESSION_LOST, text);
  EXPECT_STREQ(text, "XR_ERROR_SESSION_LOST");
  reinterpret_cast<PFN_xrResultToString>(f)(instance, XrResult(-999), text);
  EXPECT_STREQ(text, "XR_UNKNOWN_FAILURE_-999");
  destroy_instance(gipa, instance);
}

}  // namespace
}  // namespace vdfx::test_runtime
