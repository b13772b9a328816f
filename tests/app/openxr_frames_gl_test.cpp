/// @file
/// @brief What the OpenXR backend submits, read back by the simulated runtime: each eye equals
/// the sim's undistorted eye render of the same pose and FOV within 2/255 (sRGB and linear
/// swapchains), the quad layers carry the editor's panels at their poses, and a runtime that
/// changes the current GL context inside its calls (SteamVR's habit) changes nothing.
#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <chrono>
#include <glm/gtc/quaternion.hpp>
#include <opencv2/imgproc.hpp>

#include "app/editor/editor.h"
#include "app/window/editor_client.h"
#include "app/window/frame_loop.h"
#include "app/window/player.h"
#include "io/sidecar.h"
#include "io/video_source.h"
#include "tests/app/openxr_editor_loop.h"
#include "tests/app/openxr_test_support.h"
#include "xr/input/input_backend.h"
#include "xr/openxr/gl/openxr_runtime.h"
#include "xr/openxr/openxr_format.h"
#include "xr/render/compositor.h"
#include "xr/render/gl_context.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::gaze_script;
using testing::write_script;

/// Every stack effect but blur, constant over the sphere (one keyframe each), so the eye's
/// parameters are known whatever the view; the vignette is centred on each eye's own optical
/// axis, which the runtime's asymmetric FOVs move off the image centre.
std::string constant_effects_sidecar() {
  return R"({"format": "vdfx.sidecar", "version": 1,
  "video": {"path": "pano.png", "fps": 30.0, "frames": 1, "width": 256, "height": 128},
  "interpolation": {"exponent": 1.0, "time_scale": 1.0},
  "effects": [
    {"type": "tint", "keyframes": [{"azimuth_deg": 0, "altitude_deg": 0, "frame": 0,
      "params": {"gain": [1.2, 1.0, 0.8]}}]},
    {"type": "exposure", "keyframes": [{"azimuth_deg": 0, "altitude_deg": 0, "frame": 0,
      "params": {"stops": 0.6}}]},
    {"type": "saturation", "keyframes": [{"azimuth_deg": 0, "altitude_deg": 0, "frame": 0,
      "params": {"amount": 1.4}}]},
    {"type": "vignette", "keyframes": [{"azimuth_deg": 0, "altitude_deg": 0, "frame": 0,
      "params": {"radius_deg": 30.0, "falloff_deg": 25.0}}]}]})";
}

xr::Pose pose_of(const json& j) {
  xr::Pose p;
  p.orientation = glm::dquat(j["q"][0], j["q"][1], j["q"][2], j["q"][3]);
  p.position = {j["p"][0], j["p"][1], j["p"][2]};
  return p;
}

/// The eye as the sim renders it for the submitted pose and FOV: the compositor's eye buffer
/// (video layer and effects, no lens) of the same decoded picture, with the player's parameters.
cv::Mat sim_eye(const json& view, const fs::path& pano, const fs::path& sidecar) {
  auto video = io::VideoSource::open(pano, {});
  const auto frame = video->frame_at(0, std::chrono::seconds(10));
  EXPECT_TRUE(frame.has_value());
  Player player(io::read_sidecar(sidecar), video->properties(), {});
  xr::EyeView v;
  v.pose = pose_of(view["pose"]);
  const double d = effects::kRadToDeg;
  v.fov.angle_left = view["fov"]["angleLeft"].get<double>() * d;
  v.fov.angle_right = view["fov"]["angleRight"].get<double>() * d;
  v.fov.angle_up = view["fov"]["angleUp"].get<double>() * d;
  v.fov.angle_down = view["fov"]["angleDown"].get<double>() * d;
  xr::CompositorConfig c;
  c.eye_width = view["swapchain"]["width"];
  c.eye_height = view["swapchain"]["height"];
  c.distortion.method = xr::DistortionMethod::None;
  xr::Compositor comp(c);
  comp.set_video_frame(frame->picture);
  const effects::Direction ahead = xr::forward_direction(v.pose);
  comp.render_eye_buffer(0, {xr::render_view(v), player.params(ahead, 0), player.active_effects()});
  return xr::to_bgr8(comp.read_eye_buffer(0));
}

class OpenXrFrames : public testing::OpenXrTest {
 protected:
  void SetUp() override {
    OpenXrTest::SetUp();
    pano_ = testing::write_test_panorama(dir(), 16);
    sidecar_ = dir() / "constant.vdfx.json";
    testing::write_text(sidecar_, constant_effects_sidecar());
  }
  /// Plays the panorama with a scripted oblique gaze and captures frame 20.
  void play_and_capture() {
    write_script(dir() / "s.vdrec.jsonl", gaze_script(40.0, 15.0, 30));
    knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
    knob("VDFX_TEST_RUNTIME_CAPTURE", "20");
    const auto r = run("play " + pano_.string() + " --sidecar " + sidecar_.string() +
                       " --runtime openxr --hidden --scale 0.2");
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  /// Both submitted eyes against the sim's render: the largest difference in 8-bit steps.
  void expect_eyes_match(const char* encoding) {
    const json frame = frame_json(20);
    const json& projection = frame["layers"][0];
    ASSERT_EQ(projection["type"], "projection");
    ASSERT_EQ(projection["views"].size(), 2u);
    xr::GlContextOptions go;
    auto gl = xr::GlContext::create(go);
    for (int e = 0; e < 2; ++e) {
      const json& view = projection["views"][e];
      EXPECT_EQ(view["encoding"], encoding);
      const cv::Mat got =
          cv::imread((frame_dir(20) / view["image"].get<std::string>()).string(), cv::IMREAD_COLOR);
      const cv::Mat want = sim_eye(view, pano_, sidecar_);
      ASSERT_EQ(got.size(), want.size()) << "eye " << e;
      cv::Mat diff;
      cv::absdiff(got, want, diff);
      double worst = 0.0;
      cv::minMaxLoc(diff.reshape(1), nullptr, &worst);
      EXPECT_LE(worst, 2.0) << "eye " << e << ": submitted pixels differ from the sim's render";
      // Not a vacuous match: the effects changed the picture (the plain video is far off).
      EXPECT_GT(cv::norm(want, cv::NORM_L1) / want.total(), 10.0);
    }
  }
  fs::path pano_, sidecar_;
};

TEST_F(OpenXrFrames, EachEyeIsTheSimsUndistortedEyeRenderWithin2Of255) {
  play_and_capture();
  expect_eyes_match("stored");  // GL_SRGB8_ALPHA8: vdfx's encoded values as they are
  const json view = frame_json(20)["layers"][0]["views"][0];
  EXPECT_EQ(view["swapchain"]["format"], "GL_SRGB8_ALPHA8");
  // Each eye has its own pose: half the IPD either side of the head.
  const json views = frame_json(20)["layers"][0]["views"];
  const xr::Pose l = pose_of(views[0]["pose"]), r = pose_of(views[1]["pose"]);
  EXPECT_NEAR(glm::length(r.position - l.position), 0.063, 0.002);
}

TEST_F(OpenXrFrames, ALinearSwapchainGetsTheDecodedValuesAndShowsTheSame) {
  // No sRGB format offered: vdfx decodes to linear light, the runtime encodes for display.
  knob("VDFX_TEST_RUNTIME_SWAPCHAIN_FORMATS", "GL_RGBA16F,GL_RGBA8");
  play_and_capture();
  EXPECT_EQ(frame_json(20)["layers"][0]["views"][0]["swapchain"]["format"], "GL_RGBA16F");
  expect_eyes_match("linear-to-srgb");
}

TEST_F(OpenXrFrames, ARuntimeThatChangesTheGlContextChangesNothing) {
  play_and_capture();
  const std::string plain = test_files::slurp(frame_dir(20) / "layer0-view0.png");
  knob("VDFX_TEST_RUNTIME_SWITCH_CONTEXT", "1");
  play_and_capture();
  EXPECT_EQ(test_files::slurp(frame_dir(20) / "layer0-view0.png"), plain)
      << "the eye drawn with the runtime's context current?";
}

/// The editor as the frame loop's client, keeping each frame's quads and their textures' pixels
/// (read while the loop's context is current).
class RecordingClient : public FrameClient {
 public:
  explicit RecordingClient(EditorClient& inner) : inner_(inner) {}
  void update(const xr::InputState& in, std::int64_t t, FrameInfo& info) override {
    inner_.update(in, t, info);
  }
  effects::StackParams params(const effects::Direction& d, std::int64_t f) override {
    return inner_.params(d, f);
  }
  unsigned active_effects() const override { return inner_.active_effects(); }
  std::vector<xr::QuadLayer> quads() override { return last_ = inner_.quads(); }
  std::vector<xr::QuadLayer> last_;
  EditorClient& inner_;
};

/// A GL texture's level 0 as premultiplied RGBA8, first row at the top (the quads' convention:
/// the texture's first row is the image's top), like the runtime's read-back.
cv::Mat texture_rgba(unsigned texture) {
  GLint w = 0, h = 0;
  glBindTexture(GL_TEXTURE_2D, texture);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
  glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
  cv::Mat m(h, w, CV_8UC4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, m.data);
  glBindTexture(GL_TEXTURE_2D, 0);
  return m;
}

/// The largest difference (in 8-bit steps) between a layer's image `got` (BGRA) and the
/// premultiplied texture `tex` (RGBA) it copies, against what an sRGB image must store:
/// encode(decode(colour) x alpha) (unchanged where it is opaque); `opaque`: its opaque texels.
double srgb_copy_error(const cv::Mat& tex, const cv::Mat& got, int& opaque) {
  double worst = 0.0;
  opaque = 0;
  for (int y = 0; y < tex.rows; ++y)
    for (int x = 0; x < tex.cols; ++x) {
      const cv::Vec4b t = tex.at<cv::Vec4b>(y, x), g = got.at<cv::Vec4b>(y, x);
      const double a = t[3] / 255.0;
      opaque += t[3] == 255;
      worst = std::max(worst, std::abs(double(g[3]) - t[3]));
      for (int c = 0; c < 3; ++c) {
        const double straight = a > 0.0 ? std::min(t[c] / 255.0 / a, 1.0) : 0.0;
        const double want = xr::linear_to_srgb(xr::srgb_to_linear(straight) * a) * 255.0;
        worst = std::max(worst, std::abs(g[2 - c] - want));
      }
    }
  return worst;
}

TEST_F(OpenXrFrames, QuadLayersCarryTheEditorsPanelsAtTheirPoses) {
  write_script(dir() / "s.vdrec.jsonl", gaze_script(10.0, -5.0, 40));
  knob("VDFX_TEST_RUNTIME_SCRIPT", (dir() / "s.vdrec.jsonl").string());
  knob("VDFX_TEST_RUNTIME_CAPTURE", "25");
  env_->apply();
  for (const auto& [k, v] : knobs_) setenv(k.c_str(), v.c_str(), 1);

  auto video = io::VideoSource::open(pano_, {});
  io::Sidecar sidecar = io::read_sidecar(sidecar_);
  const std::unique_ptr<Editor> editor = testing::headset_test_editor(sidecar);
  EditorClient inner(*editor, create_gl_panel_textures());
  RecordingClient client(inner);
  FrameLoopOptions o = testing::openxr_loop_options();
  auto input = o.openxr->create_input_backend();
  std::vector<xr::QuadLayer> quads_25;
  std::vector<cv::Mat> images_25;
  o.on_frame = [&](xr::Compositor&, std::int64_t n) {
    if (n != 25) return;
    quads_25 = client.last_;
    for (const xr::QuadLayer& q : quads_25) images_25.push_back(texture_rgba(q.texture));
  };
  {
    FrameLoop loop(o, *input, *video, client);
    loop.run();
    inner.release_textures();
  }
  input.reset();
  for (const auto& [k, v] : knobs_) unsetenv(k.c_str());

  const json layers = frame_json(25)["layers"];
  ASSERT_GE(quads_25.size(), 2u) << "the editor's two panels at least";
  ASSERT_EQ(layers.size(), quads_25.size() + 1) << "the projection, then one quad per panel";
  for (std::size_t i = 0; i < quads_25.size(); ++i) {
    SCOPED_TRACE("quad " + std::to_string(i));
    const xr::QuadLayer& q = quads_25[i];
    const json& l = layers[i + 1];
    EXPECT_EQ(l["type"], "quad");
    EXPECT_EQ(l["space"], q.space == xr::ReferenceSpace::View ? "VIEW" : "STAGE");
    EXPECT_NE(std::find(l["flags"].begin(), l["flags"].end(), "blend_texture_source_alpha"),
              l["flags"].end());
    EXPECT_NEAR(l["size_m"][0].get<double>(), q.size_m.x(), 1e-6);
    EXPECT_NEAR(l["size_m"][1].get<double>(), q.size_m.y(), 1e-6);
    const xr::Pose p = pose_of(l["pose"]);
    EXPECT_LT(glm::length(p.position - q.pose.position), 1e-5);
    EXPECT_GT(std::abs(glm::dot(p.orientation, glm::normalize(q.pose.orientation))), 1.0 - 1e-9);
    // The panel's pixels, as the copy must store them in an sRGB image (srgb_copy_error).
    const cv::Mat got =
        cv::imread((frame_dir(25) / l["image"].get<std::string>()).string(), cv::IMREAD_UNCHANGED);
    const cv::Mat& tex = images_25[i];
    ASSERT_EQ(got.size(), tex.size());
    ASSERT_EQ(got.type(), CV_8UC4);
    int opaque = 0;
    EXPECT_LE(srgb_copy_error(tex, got, opaque), 1.5) << "quad " << i << " pixels";
    if (tex.total() > 64 * 64) {
      EXPECT_GT(opaque, 0) << "a panel is mostly opaque";
    }
  }
}

}  // namespace
}  // namespace vdfx::app
