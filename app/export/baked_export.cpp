/// @file
/// @brief render_baked: per-pixel parameters on the sphere, angular blur, colour effects.
#include "app/export/baked_export.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <vector>

#include "effects/coords.h"
#include "effects/equirect_blur.h"
#include "effects/equirect_rotate.h"
#include "io/eye_picture.h"
#include "io/ycbcr.h"

namespace vdfx::app {
namespace {

using effects::EffectType;
using effects::StackParams;

/// Grid positions along one axis: every `step`-th pixel, and (rows) the last pixel too.
std::vector<int> grid_positions(int n, int step, bool include_last) {
  std::vector<int> p;
  for (int i = 0; i < n; i += step) p.push_back(i);
  if (include_last && p.back() != n - 1) p.push_back(n - 1);
  return p;
}

/// For each pixel along an axis: the two grid entries around it and the weight of the second.
struct Axis {
  std::vector<int> a, b;
  std::vector<double> t;
};

Axis axis_weights(int n, const std::vector<int>& pos, bool wrap) {
  Axis ax;
  ax.a.resize(static_cast<std::size_t>(n));
  ax.b.resize(static_cast<std::size_t>(n));
  ax.t.resize(static_cast<std::size_t>(n));
  std::size_t g = 0;
  for (int i = 0; i < n; ++i) {
    while (g + 1 < pos.size() && pos[g + 1] <= i) ++g;
    const bool last = g + 1 == pos.size();
    const int next = last ? (wrap ? pos[0] + n : pos[g]) : pos[g + 1];
    ax.a[static_cast<std::size_t>(i)] = static_cast<int>(g);
    ax.b[static_cast<std::size_t>(i)] =
        last ? (wrap ? 0 : static_cast<int>(g)) : static_cast<int>(g + 1);
    ax.t[static_cast<std::size_t>(i)] =
        next == pos[g] ? 0.0 : static_cast<double>(i - pos[g]) / (next - pos[g]);
  }
  return ax;
}

/// The direction of equirect pixel (x, y)'s centre (contract: u = 0.5 + az/360, v = 0.5 - alt/180;
/// a VR180 image spans `coverage` = 180 degrees of azimuth: u = 0.5 + az/180).
Eigen::Vector3d pixel_direction(int x, int y, int w, int h, int coverage) {
  const double az = ((x + 0.5) / w - 0.5) * coverage, alt = (0.5 - (y + 0.5) / h) * 180.0;
  return effects::to_unit({az, alt});
}

/// The flat parameters the baked export blends: blur sigma, the colour gain (tint, renormalised
/// as StackParams keeps it, times 2^stops), saturation, contrast.
constexpr int kFields = 6;
void flatten(const StackParams& p, double* f) {
  const double e = std::exp2(p.exposure_stops);
  f[0] = p.blur_sigma_deg;
  f[1] = p.tint_gain.x() * e;
  f[2] = p.tint_gain.y() * e;
  f[3] = p.tint_gain.z() * e;
  f[4] = p.saturation;
  f[5] = p.contrast;
}

/// apply_colour_pixel along a row, each parameter (gain r, g, b, saturation, contrast) blended
/// between the planes of two grid rows, a[k] + t (b[k] - a[k]), with the mask known at compile
/// time: a loop without branches, which vectorises.
template <bool Gain, bool Saturation, bool Contrast>
void colour_row_of(float* px, const float* const* a, const float* const* b, float t, int w) {
  constexpr ColourMask mask{Gain, Saturation, Contrast};
  for (int x = 0; x < w; ++x) {
    float f[5];
    for (int k = 0; k < 5; ++k) f[k] = a[k][x] + t * (b[k][x] - a[k][x]);
    apply_colour_pixel(px + 3 * x, f, mask);
  }
}

using ColourRow = void (*)(float*, const float* const*, const float* const*, float, int);
ColourRow colour_row(const ColourMask& m) {
  static constexpr ColourRow rows[8] = {
      colour_row_of<false, false, false>, colour_row_of<true, false, false>,
      colour_row_of<false, true, false>,  colour_row_of<true, true, false>,
      colour_row_of<false, false, true>,  colour_row_of<true, false, true>,
      colour_row_of<false, true, true>,   colour_row_of<true, true, true>};
  return rows[(m.gain ? 1 : 0) + (m.saturation ? 2 : 0) + (m.contrast ? 4 : 0)];
}

}  // namespace

int baked_param_step(const BakedOptions& o, int width) {
  if (o.param_step > 0) return o.param_step;
  return std::max(1, (width + 511) / 512);
}

bool baked_drops_effects(const effects::StackInterpolator& stack) {
  return stack.active(EffectType::Vignette);
}

BakedGridCache::Grid BakedGridCache::find(const std::vector<std::int64_t>& key) const {
  const std::lock_guard lock(mutex_);
  return key == key_ ? grid_ : nullptr;
}

BakedGridCache::Grid BakedGridCache::get_or_make(const std::vector<std::int64_t>& key,
                                                 const std::function<Grid()>& make) {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (grid_ && key == key_) return grid_;
    if (std::find(making_.begin(), making_.end(), key) == making_.end()) break;
    made_.wait(lock);
  }
  making_.push_back(key);
  lock.unlock();
  Grid grid;
  try {
    grid = make();
  } catch (...) {
    lock.lock();
    making_.erase(std::find(making_.begin(), making_.end(), key));
    made_.notify_all();
    throw;
  }
  lock.lock();
  making_.erase(std::find(making_.begin(), making_.end(), key));
  key_ = key;
  grid_ = grid;
  made_.notify_all();
  return grid;
}

namespace {

/// The parameters at the grid's pixels, computed.
BakedGridCache::Grid make_grid(const effects::StackInterpolator& stack, std::int64_t frame, int w,
                               int h, const std::vector<int>& gx, const std::vector<int>& gy,
                               const Axis& ax, int coverage) {
  const std::size_t cols = gx.size();
  auto grid = std::make_shared<BakedGrid>();
  grid->fields = kFields;
  grid->rows.resize(gy.size() * kFields * static_cast<std::size_t>(w));
  const effects::StackAtFrame at(stack, frame);  // anchored centres turned once for the frame
  cv::parallel_for_(cv::Range(0, static_cast<int>(gy.size())), [&](const cv::Range& r) {
    std::vector<double> exact(cols * kFields);  // one grid row's exact parameters
    for (int j = r.start; j < r.end; ++j) {
      const auto jj = static_cast<std::size_t>(j);
      for (std::size_t i = 0; i < cols; ++i)
        flatten(at.evaluate(pixel_direction(gx[i], gy[jj], w, h, coverage)), &exact[i * kFields]);
      for (int k = 0; k < kFields; ++k) {
        float* plane = grid->rows.data() + (jj * kFields + static_cast<std::size_t>(k)) * w;
        for (int x = 0; x < w; ++x) {
          const auto xx = static_cast<std::size_t>(x);
          const double a = exact[static_cast<std::size_t>(ax.a[xx]) * kFields + k];
          const double b = exact[static_cast<std::size_t>(ax.b[xx]) * kFields + k];
          plane[x] = static_cast<float>(a + ax.t[xx] * (b - a));
        }
      }
    }
  });
  return grid;
}

/// The parameters at the grid's pixels (BakedGrid), from the cache when the frame every active
/// effect evaluates at is the one it was computed for (an anchored effect turns by its frame's
/// rotation: its frame itself).
BakedGridCache::Grid parameter_grid(const effects::StackInterpolator& stack, std::int64_t frame,
                                    int w, int h, int step, const std::vector<int>& gx,
                                    const std::vector<int>& gy, const Axis& ax, int coverage,
                                    BakedGridCache* cache) {
  std::vector<std::int64_t> key{w, h, step, coverage};
  for (int t = 0; t < effects::kEffectCount; ++t)
    if (const auto* rbf = stack.interpolator(static_cast<EffectType>(t))) {
      key.push_back(rbf->effective_frame(frame));
      if (!stack.anchor(static_cast<EffectType>(t)).identity()) key.push_back(frame);
    }
  if (cache)
    return cache->get_or_make(key,
                              [&] { return make_grid(stack, frame, w, h, gx, gy, ax, coverage); });
  return make_grid(stack, frame, w, h, gx, gy, ax, coverage);
}

}  // namespace

cv::Mat render_baked(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                     std::int64_t frame, const BakedOptions& options) {
  cv::Mat out = equirect.clone();
  render_baked_into(out, stack, frame, options);
  return out;
}

FrameRenderer baked_frame_renderer(const effects::StackInterpolator& stack, BakedOptions options,
                                   const io::YcbcrInfo& out, const effects::StereoLayout& layout) {
  auto cache = std::make_shared<BakedGridCache>();
  options.cache = cache.get();
  options.coverage_deg = layout.coverage_deg;
  return [&stack, options, out, cache, layout](const io::Picture& source, std::int64_t frame) {
    thread_local cv::Mat rgb, scratch, half, turned;  // each thread's frame buffers, reused
    // After the effects (evaluated at each pixel's video direction): into the world frame.
    auto stabilize = [&](cv::Mat& image) {
      if (options.stabilize.identity()) return;
      effects::rotate_equirect(image, options.stabilize.at(frame), turned, options.coverage_deg);
      cv::swap(image, turned);
    };
    // Each eye decoded from its own planes and encoded from its own half (io/eye_picture.h): no
    // chroma sample mixes the eyes at the boundary between the halves.
    io::to_rgb_by_eye(source, layout, io::PixelFormat::RgbF32, rgb);
    if (!layout.stereo()) {
      render_baked_into(rgb, stack, frame, options, &scratch);
      stabilize(rgb);
      return io::rgb_to_ycbcr(rgb, out);
    }
    // Each eye's half on its own (the same per-pixel parameters: the halves are the same size
    // and span the same sphere, so they share one grid): nothing reads across the boundary.
    for (const effects::EyeIndex eye : {effects::EyeIndex::Left, effects::EyeIndex::Right}) {
      const effects::PixelRect r = effects::eye_rect(layout, eye, rgb.cols, rgb.rows);
      const cv::Rect rect(r.x, r.y, r.width, r.height);
      rgb(rect).copyTo(half);
      render_baked_into(half, stack, frame, options, &scratch);
      stabilize(half);
      half.copyTo(rgb(rect));
    }
    return io::rgb_to_ycbcr_by_eye(rgb, out, layout);
  };
}

void render_baked_into(cv::Mat& rgb, const effects::StackInterpolator& stack, std::int64_t frame,
                       const BakedOptions& options, cv::Mat* scratch) {
  const int w = rgb.cols, h = rgb.rows;
  const int step = baked_param_step(options, w);
  // A 360 image's grid wraps across the seam; a VR180 image's ends at its last column.
  const bool wrap = options.coverage_deg == 360;
  const std::vector<int> gx = grid_positions(w, step, !wrap), gy = grid_positions(h, step, true);
  const Axis ax = axis_weights(w, gx, wrap), ay = axis_weights(h, gy, false);
  const BakedGridCache::Grid grid_ptr =
      parameter_grid(stack, frame, w, h, step, gx, gy, ax, options.coverage_deg, options.cache);
  const BakedGrid& grid = *grid_ptr;
  // Bilinear, split: each grid row is blended along x once per grid (BakedGrid::rows), then
  // image row y blends the two grid rows around it.
  struct RowBlend {
    std::size_t a, b;
    float t;
  };
  auto blend_of = [&](int y) {
    const auto yy = static_cast<std::size_t>(y);
    return RowBlend{static_cast<std::size_t>(ay.a[yy]), static_cast<std::size_t>(ay.b[yy]),
                    static_cast<float>(ay.t[yy])};
  };

  // Blur first (the contract's order), each pixel with its own sigma, on the sphere.
  if (stack.active(EffectType::Blur)) {
    // Reused by this thread: no fresh map (and its page faults) per frame. A reference, so that
    // the pool's threads below write this thread's map, not their own thread_local ones.
    thread_local cv::Mat sigma_buffer;
    cv::Mat& sigma = sigma_buffer;
    sigma.create(h, w, CV_32FC1);
    cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
      for (int y = r.start; y < r.end; ++y) {
        const RowBlend rb = blend_of(y);
        const float* a = grid.plane(rb.a, 0, w);
        const float* b = grid.plane(rb.b, 0, w);
        float* s = sigma.ptr<float>(y);
        for (int x = 0; x < w; ++x) s[x] = a[x] + rb.t * (b[x] - a[x]);
      }
    });
    // A VR180 image's edges are clamped, never wrapped (blur_half_equirect_varying).
    cv::Mat fresh;
    cv::Mat& blurred = scratch ? *scratch : fresh;
    if (wrap)
      effects::blur_equirect_varying(rgb, sigma, blurred);
    else
      effects::blur_half_equirect_varying(rgb, sigma, blurred);
    cv::swap(rgb, blurred);
  }
  const ColourMask mask{stack.active(EffectType::Tint) || stack.active(EffectType::Exposure),
                        stack.active(EffectType::Saturation), stack.active(EffectType::Contrast)};
  if (!mask.any()) return;
  const ColourRow colour = colour_row(mask);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const RowBlend rb = blend_of(y);
      const float *a[5], *b[5];
      for (int k = 0; k < 5; ++k) {
        a[k] = grid.plane(rb.a, k + 1, w);
        b[k] = grid.plane(rb.b, k + 1, w);
      }
      colour(rgb.ptr<float>(y), a, b, rb.t, w);
    }
  });
}

}  // namespace vdfx::app
