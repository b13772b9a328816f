/// @file
/// @brief The six effects on the GPU, in the paper's order, over a float eye buffer.
///
/// Blur: separable Gaussian, sigma in degrees converted to pixels at the optical centre
/// (one pixel spans (tan_right - tan_left) / W tangent units, and d angle / d tan = 1 / (1 + c^2)
/// at tangent c), radius ceil(3 sigma_px), border pixels replicated, weights normalised (their sum
/// computed in double on the CPU), two taps per bilinear fetch. Intermediate results stay in
/// float textures (RGBA16F by default) so no 8-bit rounding happens between passes. The per-pixel effects follow in the pass
/// that does the vertical blur; the vignette is centred on the eye's optical centre
/// (RenderView::optical_centre_tan).
#pragma once

#include <map>
#include <memory>

#include "effects/effect_types.h"
#include "xr/gl_program.h"
#include "xr/gl_texture.h"
#include "xr/render_view.h"

namespace vdfx::xr {

/// Blur radius in pixels along one axis of an eye buffer (exposed for the tests and the docs).
struct BlurPixels {
  double sigma_x = 0.0, sigma_y = 0.0;
  int radius_x = 0, radius_y = 0;
};
BlurPixels blur_pixels(double sigma_deg, const RenderView& view, int width, int height);

/// The margin (pixels on every side) the video layer should render around a view so the blur
/// never reaches the view's border: the kernel radius, 0 when blur is off (effects::view_renderer
/// does the same on the CPU).
int blur_margin(const effects::StackParams& p, unsigned mask, const RenderView& view, int width,
                int height);
/// `view` widened by `margin` pixels on every side at the same pixel pitch.
RenderView with_margin(const RenderView& view, int width, int height, int margin);

class EffectStackGl {
 public:
  explicit EffectStackGl(TexFormat scratch_format = TexFormat::RGBA16F);
  ~EffectStackGl();

  /// Runs the effects of `mask` (bits: effects::shader_bit) with parameters `p` from `src` into
  /// `dst`. `src` is `dst` plus `margin` pixels on every side (rendered with with_margin());
  /// with margin 0 the blur repeats the border pixel. An empty mask copies. Programs are
  /// generated per mask and cached.
  void apply(const GlTexture& src, const GlTarget& dst, const effects::StackParams& p,
             unsigned mask, const RenderView& view, int margin = 0);
  /// Number of compiled stack variants so far (the cache is keyed by the mask).
  std::size_t cached_variants() const { return programs_.size(); }

 private:
  const GlProgram& program_for(unsigned mask);
  void set_gaussian(const GlProgram& p, double sigma, int radius, int unit);
  TexFormat scratch_format_;
  GlProgram blur_h_;
  std::map<unsigned, GlProgram> programs_;
  GlTarget scratch_;
  GlTexture taps_[2];  //!< paired-tap tables of the horizontal and vertical pass
  unsigned vao_ = 0;
};

}  // namespace vdfx::xr
