/// @file
/// @brief The six effects on the GPU, in the paper's order, over a float eye buffer.
///
/// Blur: Gaussian, sigma in degrees converted to pixels at the optical centre (one pixel spans
/// (tan_right - tan_left) / W tangent units, and d angle / d tan = 1 / (1 + c^2) at tangent c),
/// border pixels replicated. BlurMethod::Exact (the default): separable, radius ceil(3 sigma_px),
/// weights normalised (their sum computed in double on the CPU), two taps per bilinear fetch, the
/// vertical half fused with the per-pixel effects. BlurMethod::Pyramid: blur_pyramid_gl.h.
/// Intermediate results stay in float textures (RGBA16F by default) so no 8-bit rounding happens
/// between passes. The vignette is centred on the eye's optical centre
/// (RenderView::optical_centre_tan).
///
/// Two parameter modes (the paper's): apply() takes one StackParams for the whole view (view
/// mode); apply_per_pixel() reads every pixel's parameters from the grid set by set_param_grid()
/// along that pixel's own view ray (per-pixel mode), for all six effects: the colour effects and
/// the vignette's radius and falloff (the angle still measured from the optical centre), and a
/// per-pixel blur that mixes a stack of uniformly blurred levels (sigmas tau_1 r^j, built with
/// the chosen BlurMethod) by each pixel's own sigma (effect_shaders.h).
#pragma once

#include <map>
#include <memory>
#include <vector>

#include "effects/effect_shaders.h"
#include "effects/effect_types.h"
#include "xr/headset/render_view.h"
#include "xr/render/blur_pyramid_gl.h"
#include "xr/render/gl_program.h"
#include "xr/render/gl_texture.h"
#include "xr/render/param_grid.h"

namespace vdfx::xr {

/// Blur radius in pixels along one axis of an eye buffer (exposed for the tests and the docs).
struct BlurPixels {
  double sigma_x = 0.0, sigma_y = 0.0;
  int radius_x = 0, radius_y = 0;
};
BlurPixels blur_pixels(double sigma_deg, const RenderView& view, int width, int height);

/// The margin (pixels on every side) the video layer should render around a view so the blur
/// never reaches the view's border: the kernel radius, 0 when blur is off (effects::view_renderer
/// does the same on the CPU). In per-pixel mode pass the grid's largest sigma.
int blur_margin(const effects::StackParams& p, unsigned mask, const RenderView& view, int width,
                int height);
/// `view` widened by `margin` pixels on every side at the same pixel pitch.
RenderView with_margin(const RenderView& view, int width, int height, int margin);

/// Smallest level sigma of the per-pixel blur, in pixels at the optical centre: below it a pixel
/// mixes the unblurred image with level 1 (its variance matched).
inline constexpr double kPerPixelFirstLevelPx = 0.5;

class EffectStackGl {
 public:
  explicit EffectStackGl(TexFormat scratch_format = TexFormat::RGBA16F,
                         BlurMethod blur = BlurMethod::Exact);
  ~EffectStackGl();

  /// Per-pixel mode: ratio r > 1 between successive blur level sigmas (kOctaveLevels,
  /// kHalfOctaveLevels); throws GlError otherwise.
  void set_level_ratio(double r);

  /// View mode: runs the effects of `mask` (bits: effects::shader_bit) with parameters `p` from
  /// `src` into `dst`. `src` is `dst` plus `margin` pixels on every side (rendered with
  /// with_margin()); with margin 0 the blur repeats the border pixel. An empty mask copies.
  /// Programs are generated per variant and cached.
  void apply(const GlTexture& src, const GlTarget& dst, const effects::StackParams& p,
             unsigned mask, const RenderView& view, int margin = 0);

  /// Uploads per-pixel mode's parameter grid as float textures (bilinear, repeating in azimuth).
  void set_param_grid(const ParamGrid& grid);
  bool has_param_grid() const { return grid_max_sigma_deg_ >= 0.0; }
  /// The uploaded grid's largest blur sigma in degrees (-1 without a grid).
  double grid_max_blur_sigma_deg() const { return grid_max_sigma_deg_; }
  /// Per-pixel mode: as apply(), every pixel's parameters read from the grid along its own view
  /// ray. Throws GlError without a grid.
  void apply_per_pixel(const GlTexture& src, const GlTarget& dst, unsigned mask,
                       const RenderView& view, int margin = 0);

  /// Number of compiled stack variants so far.
  std::size_t cached_variants() const { return programs_.size(); }

 private:
  const GlProgram& program_for(const effects::StackShader& variant);
  void check_sizes(const GlTexture& src, const GlTarget& dst, int margin) const;
  void set_geometry(const GlProgram& p, const RenderView& v, int w, int h, int margin) const;
  TexFormat scratch_format_;
  BlurMethod blur_method_;
  double level_ratio_ = kHalfOctaveLevels;
  GlProgram blur_h_;
  std::map<effects::StackShader, GlProgram> programs_;
  GlTarget scratch_;
  GlTexture taps_[2];  //!< paired-tap tables of the horizontal and vertical pass
  BlurPyramidGl pyramid_;
  GlTarget blurred_;              //!< view mode's pyramid result
  std::vector<GlTarget> levels_;  //!< per-pixel mode's blur levels
  GlTexture grid_[3];
  double grid_max_sigma_deg_ = -1.0;
  unsigned vao_ = 0;
};

}  // namespace vdfx::xr
