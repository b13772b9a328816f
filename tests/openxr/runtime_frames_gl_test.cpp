/// @file
/// @brief What an app submits comes back: projection and quad layers read back from the
/// runtime's folder (pixels, poses, FOVs, sizes, flags) for each colour format, the frames
/// chosen, the views following the script, and the checks the runtime makes of layers, structs
/// and swapchain image order.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/imgcodecs.hpp>

#include "tests/openxr/runtime_test_fixture.h"
#include "tests/openxr/xr_test_app.h"

namespace vdfx::test_runtime {
namespace {

using nlohmann::json;

/// The sRGB encoding of a linear value, to 8 bits (what the read-back shows of a linear format).
int encoded(double linear) {
  const double e = linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
  return static_cast<int>(std::lround(e * 255.0));
}

std::filesystem::path frame_dir(const OpenXrTestEnvironment& env, int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%06d", frame);
  return env.output_dir() / name;
}

/// A session past its first frame: FOCUSED, frames shown.
void run_to_focused(XrTestApp& app) {
  ASSERT_TRUE(app.start());
  app.poll_states();
  XR_EXPECT_OK(app.begin_session());
  app.empty_frame();
  ASSERT_EQ(app.poll_states().back(), XR_SESSION_STATE_FOCUSED);
}

struct Projection {
  XrCompositionLayerProjection layer{};
  std::array<XrCompositionLayerProjectionView, 2> views{};
};

/// Both eyes' views located in `space` at `time`, each showing `rect` of its swapchain.
Projection projection(XrTestApp& app, XrSpace space, XrTime time,
                      std::array<XrSwapchain, 2> swapchains, XrRect2Di rect,
                      std::array<std::uint32_t, 2> array_index = {0, 0}) {
  XrViewLocateInfo info{};
  info.type = XR_TYPE_VIEW_LOCATE_INFO;
  info.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
  info.displayTime = time;
  info.space = space;
  XrViewState state{};
  state.type = XR_TYPE_VIEW_STATE;
  std::array<XrView, 2> views{};
  for (auto& v : views) v.type = XR_TYPE_VIEW;
  uint32_t count = 0;
  XR_EXPECT_OK(xrLocateViews(app.session, &info, &state, 2, &count, views.data()));
  Projection p;
  for (int i = 0; i < 2; ++i) {
    p.views[i].type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
    p.views[i].pose = views[i].pose;
    p.views[i].fov = views[i].fov;
    p.views[i].subImage = {swapchains[i], rect, array_index[i]};
  }
  p.layer.type = XR_TYPE_COMPOSITION_LAYER_PROJECTION;
  p.layer.space = space;
  p.layer.viewCount = 2;
  p.layer.views = p.views.data();
  return p;
}

const XrCompositionLayerBaseHeader* base(const void* layer) {
  return static_cast<const XrCompositionLayerBaseHeader*>(layer);
}

struct FormatCase {
  const char* name;
  std::int64_t format;
  /// What the PNG shows of a channel cleared to `v` (the format's storage, then the display).
  int (*shown)(double v);
  const char* encoding;
};

const FormatCase kFormats[] = {
    {"SRGB8_ALPHA8", GL_SRGB8_ALPHA8, [](double v) { return int(std::lround(v * 255)); }, "stored"},
    {"RGBA8", GL_RGBA8, [](double v) { return encoded(std::round(v * 255) / 255); },
     "linear-to-srgb"},
    {"RGBA16F", GL_RGBA16F, [](double v) { return encoded(v); }, "linear-to-srgb"},
    {"RGB10_A2", GL_RGB10_A2, [](double v) { return encoded(std::round(v * 1023) / 1023); },
     "linear-to-srgb"},
};

class FramesReadBack : public RuntimeTest, public ::testing::WithParamInterface<FormatCase> {};

TEST_P(FramesReadBack, AProjectionLayerComesBackAsTheHeadsetWouldShowIt) {
  const FormatCase& c = GetParam();
  XrTestApp app;
  run_to_focused(app);
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSwapchain left = app.swapchain(c.format, 32, 16);
  const XrSwapchain right = app.swapchain(c.format, 32, 16);
  const float left_colour[4] = {0.25f, 0.5f, 0.75f, 1.0f};
  const float right_colour[4] = {0.75f, 0.125f, 0.0f, 1.0f};
  app.render_clear(left, left_colour);
  app.render_clear(right, right_colour);
  const XrFrameState s = app.wait_frame();
  XR_EXPECT_OK(app.begin_frame());
  const Projection p =
      projection(app, local, s.predictedDisplayTime, {left, right}, {{0, 0}, {32, 16}});
  XR_EXPECT_OK(app.end_frame({base(&p.layer)}, s.predictedDisplayTime));
  XR_EXPECT_OK(xrDestroySession(app.session));  // writes the last frame and session.json
  app.session = XR_NULL_HANDLE;

  const json f = read_json(frame_dir(env(), 1) / "frame.json");
  EXPECT_EQ(f.at("display_time_ns"), frame_time(1));
  const json& views = f.at("layers").at(0).at("views");
  for (int eye = 0; eye < 2; ++eye) {
    const float* colour = eye == 0 ? left_colour : right_colour;
    const json& v = views.at(eye);
    EXPECT_EQ(v.at("swapchain").at("format"), std::string("GL_") + c.name);
    EXPECT_EQ(v.at("encoding"), c.encoding);
    const cv::Mat png =
        cv::imread((frame_dir(env(), 1) / v.at("image")).string(), cv::IMREAD_UNCHANGED);
    ASSERT_EQ(png.cols, 32);
    ASSERT_EQ(png.rows, 16);
    for (const cv::Point at : {cv::Point(0, 0), cv::Point(31, 15), cv::Point(17, 9)}) {
      const cv::Vec4b px = png.at<cv::Vec4b>(at);  // B, G, R, A
      EXPECT_NEAR(px[2], c.shown(colour[0]), 1) << c.name;
      EXPECT_NEAR(px[1], c.shown(colour[1]), 1) << c.name;
      EXPECT_NEAR(px[0], c.shown(colour[2]), 1) << c.name;
      EXPECT_EQ(px[3], 255);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, FramesReadBack, ::testing::ValuesIn(kFormats),
                         [](const auto& info) { return std::string(info.param.name); });

class Frames : public RuntimeTest {};

TEST_F(Frames, ImageRowsGoDownFromTheTopAndOnlyTheRectangleComesBack) {
  XrTestApp app;
  run_to_focused(app);
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSwapchain sc = app.swapchain(GL_SRGB8_ALPHA8, 32, 16);
  // GL's rows count up from the bottom: the lower half (rows 0-7) red, the upper half green,
  // and the rectangle (4, 2) + 8 x 10 reads 6 rows of the lower half and 4 of the upper.
  app.render(sc, [] {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 32, 8);
    glClearColor(1, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glScissor(0, 8, 32, 8);
    glClearColor(0, 1, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  });
  const XrFrameState s = app.wait_frame();
  XR_EXPECT_OK(app.begin_frame());
  const Projection p = projection(app, local, s.predictedDisplayTime, {sc, sc}, {{4, 2}, {8, 10}});
  XR_EXPECT_OK(app.end_frame({base(&p.layer)}, s.predictedDisplayTime));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const json v = read_json(frame_dir(env(), 1) / "frame.json").at("layers").at(0).at("views").at(0);
  EXPECT_EQ(v.at("image_rect"), (json{{"x", 4}, {"y", 2}, {"width", 8}, {"height", 10}}));
  const cv::Mat png =
      cv::imread((frame_dir(env(), 1) / "layer0-view0.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(png.cols, 8);
  ASSERT_EQ(png.rows, 10);
  for (int y = 0; y < 10; ++y) {
    const cv::Vec4b px = png.at<cv::Vec4b>(y, 3);
    EXPECT_EQ(px[1], y < 4 ? 255 : 0) << "row " << y;  // green on top
    EXPECT_EQ(px[2], y < 4 ? 0 : 255) << "row " << y;
  }
}

TEST_F(Frames, AQuadLayerComesBackWithItsPoseSizeAndFlags) {
  XrTestApp app;
  run_to_focused(app);
  const XrSpace view = app.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  const XrSwapchain sc = app.swapchain(GL_SRGB8_ALPHA8, 20, 10);
  const float premultiplied[4] = {0.5f, 0.25f, 0.0f, 0.5f};
  app.render_clear(sc, premultiplied);
  const XrFrameState s = app.wait_frame();
  XR_EXPECT_OK(app.begin_frame());
  XrCompositionLayerQuad quad{};
  quad.type = XR_TYPE_COMPOSITION_LAYER_QUAD;
  quad.layerFlags = XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT;
  quad.space = view;
  quad.eyeVisibility = XR_EYE_VISIBILITY_LEFT;
  quad.subImage = {sc, {{0, 0}, {20, 10}}, 0};
  quad.pose = XrTestApp::identity();
  quad.pose.position = {0.1f, 0.0f, -1.0f};
  quad.size = {0.5f, 0.25f};
  XR_EXPECT_OK(app.end_frame({base(&quad)}, s.predictedDisplayTime));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const json layer = read_json(frame_dir(env(), 1) / "frame.json").at("layers").at(0);
  EXPECT_EQ(layer.at("type"), "quad");
  EXPECT_EQ(layer.at("space"), "VIEW");
  EXPECT_EQ(layer.at("eye_visibility"), "left");
  EXPECT_EQ(layer.at("flags"), json::array({"blend_texture_source_alpha"}));
  EXPECT_EQ(layer.at("size_m"), json::array({0.5, 0.25}));
  // No script: the head stands at (0, 1.6, 0) looking along -z, so VIEW (0.1, 0, -1) is LOCAL
  // (0.1, 1.6, -1).
  const json& p = layer.at("pose_in_local").at("p");
  EXPECT_NEAR(p.at(0), 0.1, 1e-6);
  EXPECT_NEAR(p.at(1), 1.6, 1e-6);
  EXPECT_NEAR(p.at(2), -1.0, 1e-6);
  const cv::Mat png =
      cv::imread((frame_dir(env(), 1) / layer.at("image")).string(), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(png.size(), cv::Size(20, 10));
  EXPECT_EQ(png.at<cv::Vec4b>(5, 10), cv::Vec4b(0, 64, 128, 128));  // B, G, R, A as stored
}

TEST_F(Frames, EachViewOfAnArraySwapchainComesFromItsOwnLayer) {
  XrTestApp app;
  run_to_focused(app);
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSwapchain sc = app.swapchain(GL_SRGB8_ALPHA8, 16, 8, 2);
  const float red[4] = {1, 0, 0, 1}, blue[4] = {0, 0, 1, 1};
  // One acquire for both layers of the image, as an app rendering both eyes does.
  app.render(
      sc,
      [&] {
        for (int layer = 0; layer < 2; ++layer) {
          GLint texture = 0;
          glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                                GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &texture);
          glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GLuint(texture), 0,
                                    layer);
          const float* c = layer == 0 ? red : blue;
          glClearColor(c[0], c[1], c[2], c[3]);
          glClear(GL_COLOR_BUFFER_BIT);
        }
      },
      0);
  const XrFrameState s = app.wait_frame();
  XR_EXPECT_OK(app.begin_frame());
  const Projection p =
      projection(app, local, s.predictedDisplayTime, {sc, sc}, {{0, 0}, {16, 8}}, {0, 1});
  XR_EXPECT_OK(app.end_frame({base(&p.layer)}, s.predictedDisplayTime));
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  const cv::Mat l =
      cv::imread((frame_dir(env(), 1) / "layer0-view0.png").string(), cv::IMREAD_UNCHANGED);
  const cv::Mat r =
      cv::imread((frame_dir(env(), 1) / "layer0-view1.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(l.at<cv::Vec4b>(4, 8), cv::Vec4b(0, 0, 255, 255));
  EXPECT_EQ(r.at<cv::Vec4b>(4, 8), cv::Vec4b(255, 0, 0, 255));
}

TEST_F(Frames, OnlyTheChosenFramesAreReadBack) {
  set("VDFX_TEST_RUNTIME_CAPTURE", "1,3-4");
  XrTestApp app;
  run_to_focused(app);  // frame 0
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSwapchain sc = app.swapchain(GL_SRGB8_ALPHA8, 8, 8);
  for (int k = 1; k <= 5; ++k) {
    const float grey[4] = {0.1f * float(k), 0.1f * float(k), 0.1f * float(k), 1.0f};
    app.render_clear(sc, grey);
    const XrFrameState s = app.wait_frame();
    XR_EXPECT_OK(app.begin_frame());
    const Projection p = projection(app, local, s.predictedDisplayTime, {sc, sc}, {{0, 0}, {8, 8}});
    XR_EXPECT_OK(app.end_frame({base(&p.layer)}, s.predictedDisplayTime));
  }
  XR_EXPECT_OK(xrDestroySession(app.session));
  app.session = XR_NULL_HANDLE;
  EXPECT_EQ(session_json().at("frames_captured"), json::array({1, 3, 4}));
  for (int k = 0; k <= 5; ++k) {
    EXPECT_EQ(std::filesystem::exists(frame_dir(env(), k)), k == 1 || k == 3 || k == 4) << k;
  }
  // Frame 4 shows what was rendered for it.
  const cv::Mat png =
      cv::imread((frame_dir(env(), 4) / "layer0-view1.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_NEAR(png.at<cv::Vec4b>(0, 0)[0], 102, 1);  // 0.4 stored as it is (sRGB format)
}

TEST_F(Frames, ViewsFollowTheScriptedHead) {
  script({{20'000'000, 0.0}, {50'000'000, 30.0, {0.1, 1.7, 0.2}}});
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSpace view = app.reference_space(XR_REFERENCE_SPACE_TYPE_VIEW);
  const auto locate_views = [&](XrSpace space, XrTime t, std::array<XrView, 2>& views) {
    XrViewLocateInfo info{XR_TYPE_VIEW_LOCATE_INFO, nullptr,
                          XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, t, space};
    XrViewState state{XR_TYPE_VIEW_STATE, nullptr, 0};
    for (auto& v : views) v = {XR_TYPE_VIEW, nullptr, {}, {}};
    uint32_t n = 0;
    XR_EXPECT_OK(xrLocateViews(app.session, &info, &state, 2, &n, views.data()));
    EXPECT_EQ(n, 2u);
    return state.viewStateFlags;
  };
  std::array<XrView, 2> views{};
  // Before the script's first sample nothing is tracked.
  EXPECT_EQ(locate_views(local, frame_time(1), views), 0u);
  // From 50 ms: head at (0.1, 1.7, 0.2) turned 30 degrees left; each eye IPD/2 beside it.
  const XrViewStateFlags all =
      XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
      XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT;
  EXPECT_EQ(locate_views(local, frame_time(5), views), all);
  const glm::dquat head = glm::angleAxis(glm::radians(30.0), glm::dvec3(0, 1, 0));
  for (int eye = 0; eye < 2; ++eye) {
    const glm::dvec3 want =
        glm::dvec3(0.1, 1.7, 0.2) + head * glm::dvec3(eye == 0 ? -0.0315 : 0.0315, 0, 0);
    EXPECT_NEAR(views[eye].pose.position.x, want.x, 1e-6);
    EXPECT_NEAR(views[eye].pose.position.y, want.y, 1e-6);
    EXPECT_NEAR(views[eye].pose.position.z, want.z, 1e-6);
    EXPECT_NEAR(views[eye].pose.orientation.y, head.y, 1e-6);
    EXPECT_NEAR(views[eye].pose.orientation.w, head.w, 1e-6);
  }
  // generic90's left eye: angleLeft -52, angleRight 47 degrees.
  EXPECT_NEAR(views[0].fov.angleLeft, glm::radians(-52.0), 1e-6);
  EXPECT_NEAR(views[0].fov.angleRight, glm::radians(47.0), 1e-6);
  EXPECT_NEAR(views[1].fov.angleLeft, glm::radians(-47.0), 1e-6);
  // In VIEW space the eyes sit on its x axis, unturned.
  locate_views(view, frame_time(5), views);
  EXPECT_NEAR(views[1].pose.position.x, 0.0315, 1e-6);
  EXPECT_NEAR(views[1].pose.position.z, 0.0, 1e-6);
  EXPECT_NEAR(views[1].pose.orientation.w, 1.0, 1e-6);
  // And VIEW located in LOCAL is the head.
  XrSpaceLocation where{XR_TYPE_SPACE_LOCATION, nullptr, 0, {}};
  XR_EXPECT_OK(xrLocateSpace(view, local, frame_time(5), &where));
  EXPECT_NEAR(where.pose.position.x, 0.1, 1e-6);
  EXPECT_NEAR(where.pose.position.z, 0.2, 1e-6);
}

class FramesWithoutLayer : public RuntimeTest {};

TEST_F(FramesWithoutLayer, BadLayersAreRefusedWithTheSpecsResults) {
  without_layer();  // these are the runtime's own checks
  XrTestApp app;
  run_to_focused(app);
  const XrSpace local = app.reference_space(XR_REFERENCE_SPACE_TYPE_LOCAL);
  const XrSwapchain sc = app.swapchain(GL_SRGB8_ALPHA8, 16, 16);
  const XrSwapchain never_released = app.swapchain(GL_SRGB8_ALPHA8, 16, 16);
  const XrSwapchain depth = app.swapchain(GL_DEPTH_COMPONENT24, 16, 16);
  const float grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
  app.render_clear(sc, grey);
  const XrFrameState s = app.wait_frame();
  XR_EXPECT_OK(app.begin_frame());
  const XrTime t = s.predictedDisplayTime;
  Projection p = projection(app, local, t, {sc, sc}, {{0, 0}, {16, 16}});
  const auto end_with = [&](const void* layer) { return app.end_frame({base(layer)}, t); };
  p.views[1].subImage.imageRect = {{8, 8}, {16, 16}};  // reaches past the image
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_SWAPCHAIN_RECT_INVALID);
  p.views[1].subImage.imageRect = {{0, 0}, {16, 16}};
  p.views[1].subImage.swapchain = never_released;
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_LAYER_INVALID);
  p.views[1].subImage.swapchain = depth;
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_LAYER_INVALID);
  p.views[1].subImage.swapchain = sc;
  p.views[1].pose.orientation = {0.0f, 0.0f, 0.0f, 0.5f};  // not a unit quaternion
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_POSE_INVALID);
  p.views[1].pose.orientation = {0.0f, 0.0f, 0.0f, 1.0f};
  p.layer.viewCount = 1;
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_VALIDATION_FAILURE);
  p.layer.viewCount = 2;
  p.views[0].type = XR_TYPE_VIEW;  // a wrong struct where a projection view belongs
  EXPECT_EQ(end_with(&p.layer), XR_ERROR_VALIDATION_FAILURE);
  p.views[0].type = XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW;
  XrCompositionLayerCubeKHR cube{};
  cube.type = XR_TYPE_COMPOSITION_LAYER_CUBE_KHR;  // an extension the runtime does not have
  cube.space = local;
  EXPECT_EQ(end_with(&cube), XR_ERROR_LAYER_INVALID);
  // The frame is still open: a good layer ends it.
  EXPECT_EQ(end_with(&p.layer), XR_SUCCESS);
}

TEST_F(FramesWithoutLayer, StructTypesAndNextChainsAreChecked) {
  without_layer();  // the layer would refuse these before the runtime sees them
  XrTestApp app;
  run_to_focused(app);
  XrFrameState wrong{};
  wrong.type = XR_TYPE_FRAME_WAIT_INFO;
  EXPECT_EQ(xrWaitFrame(app.session, nullptr, &wrong), XR_ERROR_VALIDATION_FAILURE);
  // A struct that extends nothing here, chained where it does not belong.
  XrFrameWaitInfo stray{};
  stray.type = XR_TYPE_FRAME_WAIT_INFO;
  XrReferenceSpaceCreateInfo info{};
  info.type = XR_TYPE_REFERENCE_SPACE_CREATE_INFO;
  info.next = &stray;
  info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
  info.poseInReferenceSpace = XrTestApp::identity();
  XrSpace space = XR_NULL_HANDLE;
  EXPECT_EQ(xrCreateReferenceSpace(app.session, &info, &space), XR_ERROR_VALIDATION_FAILURE);
  info.next = nullptr;
  ASSERT_EQ(xrCreateReferenceSpace(app.session, &info, &space), XR_SUCCESS);
  // XrSpaceVelocity does extend XrSpaceLocation.
  XrSpaceVelocity velocity{};
  velocity.type = XR_TYPE_SPACE_VELOCITY;
  XrSpaceLocation location{};
  location.type = XR_TYPE_SPACE_LOCATION;
  location.next = &velocity;
  EXPECT_EQ(xrLocateSpace(space, space, frame_time(1), &location), XR_SUCCESS);
  EXPECT_EQ(velocity.velocityFlags, 0u);
  // One element of an output array with the wrong type.
  std::array<XrView, 2> views{};
  views[0].type = XR_TYPE_VIEW;
  views[1].type = XR_TYPE_VIEW_STATE;
  XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO, nullptr,
                          XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, frame_time(1), space};
  XrViewState state{XR_TYPE_VIEW_STATE, nullptr, 0};
  uint32_t n = 0;
  EXPECT_EQ(xrLocateViews(app.session, &locate, &state, 2, &n, views.data()),
            XR_ERROR_VALIDATION_FAILURE);
  XR_EXPECT_OK(xrDestroySpace(space));
}

TEST_F(FramesWithoutLayer, SwapchainImagesGoAcquireWaitReleaseInTurn) {
  without_layer();
  XrTestApp app;
  ASSERT_TRUE(app.start());
  const XrSwapchain sc = app.swapchain(GL_RGBA8, 8, 8);
  EXPECT_EQ(app.images(sc).size(), 3u);
  XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO, nullptr, XR_INFINITE_DURATION};
  EXPECT_EQ(xrWaitSwapchainImage(sc, &wait), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_ERROR_CALL_ORDER_INVALID);
  uint32_t index = 9;
  for (uint32_t k = 0; k < 3; ++k) {
    EXPECT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_SUCCESS);
    EXPECT_EQ(index, k);  // round robin
  }
  EXPECT_EQ(xrAcquireSwapchainImage(sc, nullptr, &index), XR_ERROR_CALL_ORDER_INVALID);
  EXPECT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_ERROR_CALL_ORDER_INVALID);  // not waited
  EXPECT_EQ(xrWaitSwapchainImage(sc, &wait), XR_SUCCESS);
  EXPECT_EQ(xrReleaseSwapchainImage(sc, nullptr), XR_SUCCESS);
  // A static swapchain has one image, acquired once.
  XrSwapchainCreateInfo info{};
  info.type = XR_TYPE_SWAPCHAIN_CREATE_INFO;
  info.createFlags = XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT;
  info.format = GL_RGBA8;
  info.sampleCount = info.faceCount = info.arraySize = info.mipCount = 1;
  info.width = info.height = 8;
  XrSwapchain static_sc = XR_NULL_HANDLE;
  ASSERT_EQ(xrCreateSwapchain(app.session, &info, &static_sc), XR_SUCCESS);
  EXPECT_EQ(app.images(static_sc).size(), 1u);
  EXPECT_EQ(xrAcquireSwapchainImage(static_sc, nullptr, &index), XR_SUCCESS);
  EXPECT_EQ(xrWaitSwapchainImage(static_sc, &wait), XR_SUCCESS);
  EXPECT_EQ(xrReleaseSwapchainImage(static_sc, nullptr), XR_SUCCESS);
  EXPECT_EQ(xrAcquireSwapchainImage(static_sc, nullptr, &index), XR_ERROR_CALL_ORDER_INVALID);
  // What the runtime cannot make.
  info.createFlags = 0;
  info.sampleCount = 4;
  EXPECT_EQ(xrCreateSwapchain(app.session, &info, &static_sc), XR_ERROR_FEATURE_UNSUPPORTED);
  info.sampleCount = 1;
  info.format = GL_RGB8;
  EXPECT_EQ(xrCreateSwapchain(app.session, &info, &static_sc),
            XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
}

}  // namespace
}  // namespace vdfx::test_runtime
