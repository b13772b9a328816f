/// @file
/// @brief render_baked: per-pixel parameters on the sphere, angular blur, colour effects.
#include "app/export_baked.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <vector>

#include "effects/coords.h"
#include "effects/equirect_blur.h"
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

/// The direction of equirect pixel (x, y)'s centre (contract: u = 0.5 + az/360, v = 0.5 - alt/180).
Eigen::Vector3d pixel_direction(int x, int y, int w, int h) {
  const double az = ((x + 0.5) / w - 0.5) * 360.0, alt = (0.5 - (y + 0.5) / h) * 180.0;
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

void BakedGridCache::store(std::vector<std::int64_t> key, Grid grid) {
  const std::lock_guard lock(mutex_);
  key_ = std::move(key);
  grid_ = std::move(grid);
}

namespace {

/// The exact parameters at the grid's pixels (flattened, kFields per entry, row by row), from the
/// cache when the frame every active effect evaluates at is the one it was computed for.
BakedGridCache::Grid parameter_grid(const effects::StackInterpolator& stack, std::int64_t frame,
                                    int w, int h, int step, const std::vector<int>& gx,
                                    const std::vector<int>& gy, BakedGridCache* cache) {
  std::vector<std::int64_t> key{w, h, step};
  for (int t = 0; t < effects::kEffectCount; ++t)
    if (const auto* rbf = stack.interpolator(static_cast<EffectType>(t)))
      key.push_back(rbf->effective_frame(frame));
  if (cache)
    if (auto hit = cache->find(key)) return hit;
  const std::size_t cols = gx.size();
  auto grid = std::make_shared<std::vector<double>>(cols * gy.size() * kFields);
  cv::parallel_for_(cv::Range(0, static_cast<int>(gy.size())), [&](const cv::Range& r) {
    for (int j = r.start; j < r.end; ++j)
      for (std::size_t i = 0; i < cols; ++i)
        flatten(
            stack.evaluate(pixel_direction(gx[i], gy[static_cast<std::size_t>(j)], w, h), frame),
            &(*grid)[(static_cast<std::size_t>(j) * cols + i) * kFields]);
  });
  if (cache) cache->store(std::move(key), grid);
  return grid;
}

}  // namespace

cv::Mat render_baked(const cv::Mat& equirect, const effects::StackInterpolator& stack,
                     std::int64_t frame, const BakedOptions& options) {
  cv::Mat out = equirect.clone();
  render_baked_into(out, stack, frame, options);
  return out;
}

FrameRenderer baked_frame_renderer(const effects::StackInterpolator& stack, BakedOptions options,
                                   const io::YcbcrInfo& out) {
  auto cache = std::make_shared<BakedGridCache>();
  options.cache = cache.get();
  return [&stack, options, out, cache](const io::Picture& source, std::int64_t frame) {
    thread_local cv::Mat rgb;  // each render thread's frame buffer, reused
    io::to_rgb(source, io::PixelFormat::RgbF32, rgb);
    render_baked_into(rgb, stack, frame, options);
    return io::rgb_to_ycbcr(rgb, out);
  };
}

void render_baked_into(cv::Mat& rgb, const effects::StackInterpolator& stack, std::int64_t frame,
                       const BakedOptions& options) {
  const int w = rgb.cols, h = rgb.rows;
  const int step = baked_param_step(options, w);
  const std::vector<int> gx = grid_positions(w, step, false), gy = grid_positions(h, step, true);
  const BakedGridCache::Grid grid_ptr =
      parameter_grid(stack, frame, w, h, step, gx, gy, options.cache);
  const std::vector<double>& grid = *grid_ptr;
  const Axis ax = axis_weights(w, gx, true), ay = axis_weights(h, gy, false);
  // Bilinear, split: the two grid rows around image row y are blended once per row, then each
  // pixel blends two neighbouring entries of that row.
  auto grid_row = [&](int y, std::vector<float>& row) {
    const std::size_t ya = static_cast<std::size_t>(ay.a[static_cast<std::size_t>(y)]);
    const std::size_t yb = static_cast<std::size_t>(ay.b[static_cast<std::size_t>(y)]);
    const double ty = ay.t[static_cast<std::size_t>(y)];
    row.resize(gx.size() * kFields);
    for (std::size_t i = 0; i < row.size(); ++i) {
      const double a = grid[ya * gx.size() * kFields + i], b = grid[yb * gx.size() * kFields + i];
      row[i] = static_cast<float>(a + ty * (b - a));
    }
  };
  std::vector<float> axis_t(ax.t.begin(), ax.t.end());
  auto params_at = [&](const std::vector<float>& row, int x, float* f) {
    const std::size_t xa = static_cast<std::size_t>(ax.a[static_cast<std::size_t>(x)]) * kFields;
    const std::size_t xb = static_cast<std::size_t>(ax.b[static_cast<std::size_t>(x)]) * kFields;
    const float tx = axis_t[static_cast<std::size_t>(x)];
    for (int k = 0; k < kFields; ++k) f[k] = row[xa + k] + tx * (row[xb + k] - row[xa + k]);
  };

  // Blur first (the contract's order), each pixel with its own sigma, on the sphere.
  if (stack.active(EffectType::Blur)) {
    cv::Mat sigma(h, w, CV_32FC1);
    cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
      float f[kFields];
      std::vector<float> row;
      for (int y = r.start; y < r.end; ++y) {
        grid_row(y, row);
        for (int x = 0; x < w; ++x) {
          params_at(row, x, f);
          sigma.at<float>(y, x) = static_cast<float>(f[0]);
        }
      }
    });
    rgb = effects::blur_equirect_varying(rgb, sigma);
  }
  const ColourMask mask{stack.active(EffectType::Tint) || stack.active(EffectType::Exposure),
                        stack.active(EffectType::Saturation), stack.active(EffectType::Contrast)};
  if (!mask.any()) return;
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
    float f[kFields];
    std::vector<float> row;
    for (int y = r.start; y < r.end; ++y) {
      grid_row(y, row);
      cv::Vec3f* px = rgb.ptr<cv::Vec3f>(y);
      for (int x = 0; x < w; ++x) {
        params_at(row, x, f);
        apply_colour_pixel(&px[x][0], f + 1, mask);
      }
    }
  });
}

}  // namespace vdfx::app
