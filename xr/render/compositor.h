/// @file
/// @brief The simulated headset's compositor: per eye, video layer -> effect stack -> world-space
/// layers (flare, grain: xr/render/eye_layer.h) -> quad layers -> lens pre-distortion -> display;
/// mirror modes; offscreen readback.
///
/// Effects see only the video; the world-space layers and then the UI quads are composited after
/// them, so a UI panel is never blurred, vignetted or flared. Everything renders into textures; the
/// mirror window (or a test) reads them. The eye buffers are float (RGBA16F by default): no 8-bit
/// rounding happens before the display image.
#pragma once

#include <array>
#include <memory>
#include <opencv2/core.hpp>
#include <span>

#include "effects/effect_types.h"
#include "xr/headset/session.h"
#include "xr/render/blur_method.h"
#include "xr/render/distortion_gl.h"
#include "xr/render/eye_layer.h"
#include "xr/render/gpu_timer.h"
#include "xr/render/mirror.h"
#include "xr/render/param_grid.h"
#include "xr/render/video_layer.h"

namespace vdfx::xr {

struct CompositorConfig {
  int eye_width = 1440, eye_height = 1600;  //!< per eye, eye buffer and display image
  TexFormat eye_format = TexFormat::RGBA16F;
  LodMode lod = LodMode::Analytic;
  DistortionSettings distortion;
  effects::LensModel lens;
  bool gpu_timing = false;              //!< timestamp queries per stage (stage_times())
  BlurMethod blur = BlurMethod::Exact;  //!< exact separable, or the pyramid (blur_pyramid_gl.h)
  /// Per-pixel mode: ratio between successive blur level sigmas (blur_method.h).
  double blur_level_ratio = kHalfOctaveLevels;
};

/// What changes per eye per frame.
struct EyeInput {
  RenderView view;
  effects::StackParams params;
  unsigned active_effects = 0;  //!< effects::shader_bit mask: only these are compiled in
  /// Per-pixel mode: every pixel's parameters come from the grid given to
  /// Compositor::set_param_grid, looked up along its own view ray (`params` is then unused).
  bool per_pixel = false;
  /// World-space layers drawn over the effects and under the quads, in this order (flare, then
  /// grain); each already holds this frame's content.
  std::span<EyeLayer* const> layers = {};
};

class Compositor {
 public:
  /// Needs a current GL 4.3 context (GlContext).
  explicit Compositor(CompositorConfig config);
  ~Compositor();

  /// The video's stereo layout and coverage (VideoLayerGl::set_layout); drops the frame.
  void set_video_layout(const effects::StereoLayout& layout);
  /// Which eye's image of stereo video the desktop view shows (0 left, 1 right).
  void set_desktop_eye(int eye);
  void set_video_frame(const cv::Mat& equirect);
  /// A decoded frame as it is (Y'CbCr converted on the GPU: VideoLayerGl::set_frame).
  void set_video_frame(const io::Picture& picture);
  /// Per-pixel mode's parameter grid (uploaded as float textures; used by eyes with per_pixel).
  void set_param_grid(const ParamGrid& grid);
  /// Renders one eye (0 left, 1 right). Quads are placed with Session::to_local(head_in_local).
  void render_eye(int eye, const EyeInput& in, std::span<const QuadLayer> quads = {},
                  const Pose& head_in_local = {});
  /// Renders one eye's buffer only: video layer, effects and world-space layers, no quads and no
  /// lens (a real OpenXR runtime composites the panels as quad layers and distorts itself). The
  /// OpenXR backend copies eye_buffer(eye) into the eye's swapchain.
  void render_eye_buffer(int eye, const EyeInput& in);
  /// Draws quad layers over eye `eye`'s buffer as seen from its last rendered view (the OpenXR
  /// mirror: the left eye as submitted, with the panels the runtime composites over it).
  void draw_quads(int eye, std::span<const QuadLayer> quads, const Pose& head_in_local);
  /// Renders the desktop view (MirrorMode::Desktop): `in.view` is the cyclopean pinhole
  /// (xr::desktop_view); video and effects are rendered at video_scale of width x height and
  /// scaled up, then the quads are drawn at the full width x height (sharp UI panel text), no lens.
  void render_desktop(const EyeInput& in, int width, int height, double video_scale,
                      std::span<const QuadLayer> quads = {}, const Pose& head_in_local = {});
  /// Draws the mirror into `target` (or the default framebuffer when null): the desktop view
  /// 1:1 (render_desktop at this size), or the eyes fitted as xr::mirror_eye_rect says.
  void draw_mirror(MirrorMode mode, const GlTarget* target, int width, int height);
  /// The desktop view as last rendered (CV_32FC4 BGRA, upright).
  cv::Mat read_desktop() const;

  /// Undistorted eye buffer (effects and quads), CV_32FC4 BGRA, upright.
  cv::Mat read_eye_buffer(int eye) const;
  /// Pre-distorted display image (what the headset's display shows), CV_32FC4 BGRA, upright.
  cv::Mat read_display(int eye) const;
  const GlTarget& eye_buffer(int eye) const;
  const GlTarget& display(int eye) const;
  /// Per-stage GPU times of the frames rendered since the last call (gpu_timing on).
  std::vector<StageTime> stage_times();
  const CompositorConfig& config() const { return config_; }

 private:
  struct Impl;
  CompositorConfig config_;
  std::unique_ptr<Impl> impl_;
};

/// Options of render_view_gpu beyond the view and its parameters.
struct GpuViewOptions {
  DistortionSettings distortion{DistortionMethod::None};  //!< None: the undistorted eye image
  effects::LensModel lens;                                //!< with distortion
  BlurMethod blur = BlurMethod::Exact;
  double blur_level_ratio = kHalfOctaveLevels;  //!< per-pixel mode (blur_method.h)
  /// Per-pixel mode when set: every pixel's parameters from this grid along its own ray (the
  /// `params` argument is then unused; `active_effects` still selects the compiled effects).
  const ParamGrid* param_grid = nullptr;
  /// World-space layers (flare, grain) drawn after the effects, as EyeInput::layers.
  std::span<EyeLayer* const> layers = {};
  /// The frame's stereo layout and coverage, and the eye whose image the view shows (0 left,
  /// 1 right; mono: either shows the frame).
  effects::StereoLayout layout;
  int eye = 0;
};

/// One offscreen view for `vdfx render --gpu` (and tests): video layer -> effects ->
/// optional pre-distortion, read back as 8-bit BGR, clamped only at the end. Needs a current GL
/// context.
cv::Mat render_view_gpu(const cv::Mat& equirect, const RenderView& view, int width, int height,
                        const effects::StackParams& params, unsigned active_effects,
                        const GpuViewOptions& options = {});

}  // namespace vdfx::xr
