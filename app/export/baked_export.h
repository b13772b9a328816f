/// @file
/// @brief The baked export's frame: every equirect pixel gets the effects' parameters
/// interpolated at its own direction and frame (the paper's per-pixel mode over the whole
/// sphere), the blur is an angular blur on the sphere (effects/equirect_blur.h), and the colour
/// effects apply per pixel with the contract's formulas (apply_colour_pixel, tested against the
/// CPU reference effects/effect_stack.h).
///
/// View-dependent by nature, and therefore left out: the vignette (its falloff is measured from
/// the eye's optical centre, which a baked sphere does not have) and flare and grain.
///
/// Parameters: evaluated exactly (StackInterpolator) at the pixels of a grid every `param_step`
/// pixels in both directions (wrapping across the azimuth seam, always including the bottom
/// row), bilinear in between: the blur sigma, the colour gain (tint x 2^stops), saturation and
/// contrast. param_step 1 evaluates every pixel exactly. docs/export.md gives the measured
/// difference between the default step and 1.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <vector>

#include "app/export/pipeline.h"
#include "effects/anchor.h"
#include "effects/stack_interpolator.h"
#include "effects/stereo_layout.h"
#include "io/picture.h"

namespace vdfx::app {

class BakedGridCache;

/// One frame's parameters (`fields` of them: blur sigma, gain r, g, b, saturation, contrast),
/// evaluated exactly at the grid's pixels and each grid row already blended along x to every pixel
/// column (one plane per field), so that an image row is a blend of two such rows whose loops
/// stream.
struct BakedGrid {
  int fields = 0;
  std::vector<float> rows;  //!< [grid row][field][x], the image's width per plane
  const float* plane(std::size_t grid_row, int field, int width) const {
    return rows.data() +
           (grid_row * static_cast<std::size_t>(fields) + static_cast<std::size_t>(field)) *
               static_cast<std::size_t>(width);
  }
};

struct BakedOptions {
  int param_step = 0;  //!< 0: automatic (the grid at most 512 columns: 1 up to 512-wide video)
  /// Where the parameter grid of one frame is kept for the next (null: computed every frame).
  BakedGridCache* cache = nullptr;
  /// Degrees of azimuth the image spans (360, or 180 for one eye of VR180: its pixels' directions
  /// span azimuth -90..90, its grid does not wrap and its blur clamps at its edges).
  int coverage_deg = 360;
  /// baked_frame_renderer: the camera's orientation per frame (effects::AnchorFrames::world) to
  /// turn each rendered frame back into the world frame (`--stabilize`: the picture's direction
  /// w shows the video at q_f^-1 w q_f); identity: the video frame as it is.
  effects::AnchorFrames stabilize{};
};

/// The last parameter grid, reused while every effect's interpolant evaluates at the same frame
/// (held outside its keyframes' frame span, docs/interpolation.md): a sidecar whose keyframes
/// share one frame computes its grid once per export. Safe to share between render threads.
class BakedGridCache {
 public:
  using Grid = std::shared_ptr<const BakedGrid>;
  /// The grid stored under `key`, or null.
  Grid find(const std::vector<std::int64_t>& key) const;
  /// The grid under `key`: the stored one; or, while another thread is making the grid of that
  /// key, that one (waited for: the render threads starting an export together compute the
  /// shared grid once, not once each); else `make()`'s, stored.
  Grid get_or_make(const std::vector<std::int64_t>& key, const std::function<Grid()>& make);

 private:
  mutable std::mutex mutex_;
  std::condition_variable made_;
  std::vector<std::int64_t> key_;
  Grid grid_;
  std::vector<std::vector<std::int64_t>> making_;  //!< keys other threads are making now
};

/// The step `options` resolves to for a video `width` pixels wide.
int baked_param_step(const BakedOptions& options, int width);

/// True when the stack has an effect a baked export leaves out (the vignette).
bool baked_drops_effects(const effects::StackInterpolator& stack);

/// The colour effects a baked frame applies at one pixel, each only when the stack has it.
struct ColourMask {
  bool gain = false;  //!< tint or exposure
  bool saturation = false, contrast = false;
  bool any() const { return gain || saturation || contrast; }
};

/// Tint, exposure, saturation and contrast of one RGB pixel `c` (in place, float, unclamped),
/// the contract's formulas of effects/effect_stack.h in its order, written for a whole frame's
/// worth of pixels: p = {gain r, g, b, saturation, contrast}, where gain = tint (renormalised) x
/// 2^stops (tint and exposure are one multiplication). Tested against
/// effects::apply_colour_stack, the reference.
inline void apply_colour_pixel(float* c, const float* p, const ColourMask& m) {
  float r = c[0], g = c[1], b = c[2];
  if (m.gain) {
    r *= p[0];
    g *= p[1];
    b *= p[2];
  }
  if (m.saturation) {  // Y + S (C - Y), Y = C . [0.25, 0.5, 0.25]
    const float y = 0.25f * r + 0.5f * g + 0.25f * b;
    r = y + p[3] * (r - y);
    g = y + p[3] * (g - y);
    b = y + p[3] * (b - y);
  }
  if (m.contrast) {  // 0.5 + X (C - 0.5)
    r = 0.5f + p[4] * (r - 0.5f);
    g = 0.5f + p[4] * (g - 0.5f);
    b = 0.5f + p[4] * (b - 0.5f);
  }
  c[0] = r;
  c[1] = g;
  c[2] = b;
}

/// Renders frame `frame` of an equirect (CV_32FC3 RGB, display-encoded): unclamped CV_32FC3.
cv::Mat render_baked(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                     std::int64_t frame, const BakedOptions& options = {});
/// The same in place: `rgb` becomes the rendered frame (its buffer is reused unless a blur needs
/// a new one). With `scratch`, the blur writes into it and the two are swapped: a caller keeping
/// both from frame to frame allocates nothing per frame. On coverage 180 the blur clamps at the
/// image's edges (effects::blur_half_equirect_varying).
void render_baked_into(cv::Mat& rgb, const effects::StackInterpolator& stack, std::int64_t frame,
                       const BakedOptions& options = {}, cv::Mat* scratch = nullptr);

/// `vdfx export --baked`'s frame renderer: decoded picture -> RGB float (one buffer per render
/// thread, reused: no fresh 4K float image, and its page faults, per frame) -> render_baked_into
/// -> Y'CbCr in `out`'s layout, with one BakedGridCache for the whole export. `stack` must outlive
/// the renderer. A stereo `layout` bakes each eye's half on its own (its coverage from `layout`),
/// the frame keeping its layout. With options.stabilize each rendered frame (each eye) is then
/// turned into the world frame: the effects stay evaluated at the video direction each pixel
/// shows.
FrameRenderer baked_frame_renderer(const effects::StackInterpolator& stack, BakedOptions options,
                                   const io::YcbcrInfo& out,
                                   const effects::StereoLayout& layout = {});

}  // namespace vdfx::app
