/// @file
/// @brief The tests' "no validation error" means something: with the core validation layer on,
/// an app's mistake is written to the layer's report, the call fails before the runtime sees it,
/// and OpenXrTestEnvironment::validation_errors() returns it.
#include <gtest/gtest.h>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

class ValidationLayer : public RuntimeTest {};

TEST_F(ValidationLayer, AnAppsMistakeReachesTheReport) {
  expect_validation_errors();
  XrTestApp app;
  ASSERT_TRUE(app.start());
  EXPECT_EQ(env().validation_errors(), "");
  XrReferenceSpaceCreateInfo info{};
  info.type = XR_TYPE_SESSION_CREATE_INFO;  // the wrong type
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  info.poseInReferenceSpace = XrTestApp::identity();
  XrSpace space = XR_NULL_HANDLE;
  ::testing::internal::CaptureStderr();
  EXPECT_EQ(xrCreateReferenceSpace(app.session, &info, &space), XR_ERROR_VALIDATION_FAILURE);
  // The layer stopped it: the runtime, which reports its own refusals, never saw the call.
  EXPECT_EQ(::testing::internal::GetCapturedStderr().find("vdfx-test-runtime"), std::string::npos);
  const std::string errors = env().validation_errors();
  EXPECT_NE(errors.find("[VALID_ERROR | VUID-XrReferenceSpaceCreateInfo-type-type | "
                        "xrCreateReferenceSpace]"),
            std::string::npos)
      << errors;
}

}  // namespace
}  // namespace vdfx::test_runtime
