/// @file
/// @brief Angular Gaussian blur of equirect images (constant and per-pixel sigma).
#include "effects/equirect_blur.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace vdfx::effects {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// Altitude (radians) of row y's texel centres in an image `h` rows high.
double row_altitude(int y, int h) {
  return 0.5 * kPi - (y + 0.5) * kPi / h;
}

/// Per output row of a gather: the column runs [first, last) it computes (none: row skipped).
/// Runs never wrap: a range across the seam is two runs.
using RowRuns = std::vector<std::vector<std::pair<int, int>>>;

/// acc[x] += wgt * src[(x + shift) mod w] over x in [a, b), three channels: two contiguous runs.
inline void add_shifted(float* acc, const float* src, float wgt, int shift, int w, int a, int b) {
  const int split = std::clamp(w - shift, a, b);  // x < split reads x + shift, the rest wraps
  if (split > a) {
    float* o = acc + 3 * a;
    const float* p = src + 3 * (a + shift);
    for (int t = 0; t < 3 * (split - a); ++t) o[t] += wgt * p[t];
  }
  if (b > split) {
    float* o = acc + 3 * split;
    const float* p = src + 3 * (split + shift - w);
    for (int t = 0; t < 3 * (b - split); ++t) o[t] += wgt * p[t];
  }
}

/// The exact angular gather at this image's own resolution (sigma in radians), at the texels of
/// `runs` only (all when null; the others are left unset, or 0 on the rows computed with
/// `clear_rows`: a reduced level is read back along whole rows).
cv::Mat gather(const cv::Mat& img, double sigma, const RowRuns* runs, bool clear_rows) {
  const int w = img.cols, h = img.rows;
  const double radius = 3.0 * sigma, cos_radius = std::cos(radius);
  const double dphi = kPi / h, dlam = 2.0 * kPi / w;
  std::vector<double> s(static_cast<std::size_t>(h)), c(static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    s[static_cast<std::size_t>(y)] = std::sin(row_altitude(y, h));
    c[static_cast<std::size_t>(y)] = std::cos(row_altitude(y, h));
  }
  const int reach = static_cast<int>(std::ceil(radius / dphi));
  const std::vector<std::pair<int, int>> whole{{0, w}};
  cv::Mat out(h, w, CV_32FC3);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& rows) {
    std::vector<float> acc(static_cast<std::size_t>(3 * w));
    std::vector<std::pair<int, float>> taps;
    for (int i = rows.start; i < rows.end; ++i) {
      const auto& row_runs = runs ? (*runs)[static_cast<std::size_t>(i)] : whole;
      if (row_runs.empty()) continue;
      for (const auto& [a, b] : row_runs) std::fill(acc.begin() + 3 * a, acc.begin() + 3 * b, 0.0f);
      double norm = 0.0;
      const double si = s[static_cast<std::size_t>(i)], ci = c[static_cast<std::size_t>(i)];
      for (int j = std::max(0, i - reach); j <= std::min(h - 1, i + reach); ++j) {
        const double sj = s[static_cast<std::size_t>(j)], cj = c[static_cast<std::size_t>(j)];
        // Widest column offset still within the radius: cos(dlambda) >= (cos R - si sj) / (ci cj).
        int k = w / 2;
        const double den = ci * cj;
        if (den > 1e-12) {
          const double q = (cos_radius - si * sj) / den;
          if (q >= 1.0) continue;  // this row is farther than the radius everywhere
          if (q > -1.0) k = std::min(k, static_cast<int>(std::floor(std::acos(q) / dlam)) + 1);
        }
        // Each column once: offsets -k..k, or every column of the row when that wraps.
        const int lo = 2 * k + 1 > w ? -(w / 2) : -k;
        const int hi = 2 * k + 1 > w ? w - 1 - w / 2 : k;
        taps.clear();
        for (int d = lo; d <= hi; ++d) {
          const double cos_theta = std::clamp(si * sj + ci * cj * std::cos(d * dlam), -1.0, 1.0);
          const double theta = std::acos(cos_theta);
          if (theta > radius) continue;
          const double wgt = std::exp(-theta * theta / (2.0 * sigma * sigma)) * cj;
          taps.emplace_back(d, static_cast<float>(wgt));
          norm += wgt;
        }
        const float* src = img.ptr<float>(j);
        for (const auto& [d, wgt] : taps)
          for (const auto& [a, b] : row_runs)
            add_shifted(acc.data(), src, wgt, ((d % w) + w) % w, w, a, b);
      }
      float* dst = out.ptr<float>(i);
      if (clear_rows) std::fill(dst, dst + 3 * w, 0.0f);
      const float inv = static_cast<float>(1.0 / norm);
      for (const auto& [a, b] : row_runs)
        for (int t = 3 * a; t < 3 * b; ++t) dst[t] = acc[static_cast<std::size_t>(t)] * inv;
    }
  });
  return out;
}

/// The image box-reduced by powers of two, each texel the average of its f x f texels weighted
/// by solid angle (cos altitude), so a reduced image holds the same light as the original. Made
/// once per blur and shared by its levels, each step from the one before (2 x 2 texels of it,
/// weighted by their rows' carried weights: a weighted average of weighted averages is exact)
/// while the sizes halve exactly, else from the full image.
class Pyramid {
 public:
  explicit Pyramid(const cv::Mat& rgb) {
    std::vector<float> cosines(static_cast<std::size_t>(rgb.rows));
    for (int y = 0; y < rgb.rows; ++y)
      cosines[static_cast<std::size_t>(y)] =
          static_cast<float>(std::cos(row_altitude(y, rgb.rows)));
    steps_.push_back({rgb, std::move(cosines)});
  }

  /// The image reduced by f (a power of two).
  const cv::Mat& at(int f) {
    while ((1 << (steps_.size() - 1)) < f) {
      const Step& last = steps_.back();
      const int g = 2 << (steps_.size() - 1);
      steps_.push_back(last.image.rows % 2 == 0 && last.image.cols % 2 == 0 && last.exact
                           ? halve(last)
                           : from_full(g));
    }
    return steps_[static_cast<std::size_t>(std::countr_zero(static_cast<unsigned>(f)))].image;
  }

 private:
  struct Step {
    cv::Mat image;
    std::vector<float> weight;  //!< each row's mean cos(altitude) over its source rows
    bool exact = true;          //!< the size is exactly the full size / f
  };

  static Step halve(const Step& s) {
    const int h = s.image.rows / 2, w = s.image.cols / 2;
    Step out{cv::Mat(h, w, CV_32FC3), std::vector<float>(static_cast<std::size_t>(h)), true};
    cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
      std::vector<float> rows(static_cast<std::size_t>(6 * w));
      for (int i = r.start; i < r.end; ++i) {
        const float wa = s.weight[static_cast<std::size_t>(2 * i)];
        const float wb = s.weight[static_cast<std::size_t>(2 * i + 1)];
        out.weight[static_cast<std::size_t>(i)] = 0.5f * (wa + wb);
        const float ka = wa / (2.0f * (wa + wb)), kb = wb / (2.0f * (wa + wb));
        const float* a = s.image.ptr<float>(2 * i);
        const float* b = s.image.ptr<float>(2 * i + 1);
        float* d = out.image.ptr<float>(i);
        // The two rows blended first (a streaming loop), then pairs of texels summed.
        float* m = rows.data();
        for (int t = 0; t < 6 * w; ++t) m[t] = ka * a[t] + kb * b[t];
        for (int x = 0; x < w; ++x)
          for (int c = 0; c < 3; ++c) d[3 * x + c] = m[6 * x + c] + m[6 * x + 3 + c];
      }
    });
    return out;
  }

  /// Straight from the full image (sizes that do not halve exactly: OpenCV's area resize).
  Step from_full(int f) const {
    const Step& full = steps_.front();
    const int h = full.image.rows;
    cv::Mat weighted = full.image.clone();
    const cv::Mat cosines(full.weight, true);  // h x 1
    for (int y = 0; y < h; ++y) weighted.row(y) *= full.weight[static_cast<std::size_t>(y)];
    Step out;
    cv::Mat small_cos;
    cv::resize(weighted, out.image, cv::Size(full.image.cols / f, h / f), 0, 0, cv::INTER_AREA);
    cv::resize(cosines, small_cos, cv::Size(1, h / f), 0, 0, cv::INTER_AREA);
    out.weight.resize(static_cast<std::size_t>(out.image.rows));
    for (int y = 0; y < out.image.rows; ++y) {
      out.weight[static_cast<std::size_t>(y)] = small_cos.at<float>(y, 0);
      out.image.row(y) /= small_cos.at<float>(y, 0);
    }
    out.exact = false;
    return out;
  }

  std::vector<Step> steps_;
};

/// The reduction of a level of sigma `sigma_deg` on a w x h image: the largest power of two
/// keeping sigma >= 1 reduced texel (and the reduced image at least 8 x 4).
int level_factor(double sigma_deg, int w, int h) {
  const double sigma_px = sigma_deg / (360.0 / w);  // in texels at the equator
  int f = 1;
  while (sigma_px / (2 * f) >= 1.0 && w / (2 * f) >= 8 && h / (2 * f) >= 4) f *= 2;
  return f;
}

/// blur_equirect at its reduced resolution (not sampled back), at the texels of `runs` (all
/// when null). The reduction (a box of f texels) and the bilinear read-back (a tent of f texels)
/// blur too, by variances f^2/12 and f^2/6 (in full-resolution texels): the gather's own sigma
/// is smaller by that, so the whole chain has the asked-for sigma.
cv::Mat blurred_level(Pyramid& pyramid, int w, int h, double sigma_deg, const RowRuns* runs) {
  const double texel_deg = 360.0 / w;
  const double sigma_px = sigma_deg / texel_deg;
  const int f = level_factor(sigma_deg, w, h);
  if (f == 1) return gather(pyramid.at(1), sigma_deg * kPi / 180.0, runs, false);
  const double gather_px = std::sqrt(sigma_px * sigma_px - 0.25 * f * f);
  return gather(pyramid.at(f), gather_px * texel_deg * kPi / 180.0, runs, runs != nullptr);
}

/// Bilinear read-back along one axis: full-resolution index i reads reduced samples a[i], b[i]
/// with weight t[i] on b (columns wrap: azimuth; rows clamp).
struct Taps {
  std::vector<int> a, b;
  std::vector<float> t;
};

Taps read_back_taps(int n, int m, bool wrap) {
  Taps taps;
  taps.a.resize(static_cast<std::size_t>(n));
  taps.b.resize(static_cast<std::size_t>(n));
  taps.t.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double l = (i + 0.5) * m / n - 0.5;
    const int i0 = static_cast<int>(std::floor(l));
    const auto k = static_cast<std::size_t>(i);
    taps.t[k] = static_cast<float>(l - i0);
    if (wrap) {
      taps.a[k] = ((i0 % m) + m) % m;
      taps.b[k] = (taps.a[k] + 1) % m;
    } else {
      taps.a[k] = std::clamp(i0, 0, m - 1);
      taps.b[k] = std::clamp(i0 + 1, 0, m - 1);
    }
  }
  return taps;
}

/// A level sampled back to full resolution, added to output rows with per-pixel weights. A
/// reduced level is first read back along x on each level row it has (`runs`: the level rows
/// computed; all when null), so that each output row is a blend of two such wide rows: the
/// per-pixel loop streams, with no index lookups.
class ReadBack {
 public:
  ReadBack(const cv::Mat& level, int w, int h, const RowRuns* runs)
      : level_(level), full_(level.cols == w && level.rows == h) {
    if (full_) return;
    rows_ = read_back_taps(h, level.rows, false);
    const Taps cols = read_back_taps(w, level.cols, true);
    wide_.create(level.rows, w, CV_32FC3);
    const int lw = level.cols;
    const std::vector<std::pair<int, int>> whole{{0, lw}};
    cv::parallel_for_(cv::Range(0, level.rows), [&](const cv::Range& r) {
      for (int i = r.start; i < r.end; ++i) {
        const float* src = level.ptr<float>(i);
        float* d = wide_.ptr<float>(i);
        // Only the columns under the level's runs (the pixels that mix it read nothing else).
        for (const auto& [c0, c1] : runs ? (*runs)[static_cast<std::size_t>(i)] : whole) {
          const int x0 = c0 * w / lw, x1 = std::min(w, (c1 * w + lw - 1) / lw);
          for (int x = x0; x < x1; ++x) {
            const auto xx = static_cast<std::size_t>(x);
            const float fx = cols.t[xx];
            const float* p = src + 3 * cols.a[xx];
            const float* q = src + 3 * cols.b[xx];
            for (int c = 0; c < 3; ++c) d[3 * x + c] = p[c] * (1.0f - fx) + q[c] * fx;
          }
        }
      }
    });
  }

  /// The two rows full-resolution row y blends and the weight of the second (a full level: its
  /// own row twice, weight 0).
  void sources(int y, const float*& top, const float*& bottom, float& fy) const {
    if (full_) {
      top = bottom = level_.ptr<float>(y);
      fy = 0.0f;
      return;
    }
    const auto yy = static_cast<std::size_t>(y);
    top = wide_.ptr<float>(rows_.a[yy]);
    bottom = wide_.ptr<float>(rows_.b[yy]);
    fy = rows_.t[yy];
  }

  /// dst[x] = lerp(A(x, y), B(x, y), clamp((s[x] - base) rise, 0, 1)) over x in [a, b).
  static void mix(float* dst, int y, int a, int b, const ReadBack& la, const ReadBack& lb,
                  const float* s, float base, float rise) {
    const float *ta, *ba, *tb, *bb;
    float fa, fb;
    la.sources(y, ta, ba, fa);
    lb.sources(y, tb, bb, fb);
    const float ga = 1.0f - fa, gb = 1.0f - fb;
    for (int x = a; x < b; ++x) {
      const float t = std::clamp((s[x] - base) * rise, 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) {
        const float va = ta[3 * x + c] * ga + ba[3 * x + c] * fa;
        const float vb = tb[3 * x + c] * gb + bb[3 * x + c] * fb;
        dst[3 * x + c] = va + t * (vb - va);
      }
    }
  }

  /// dst[x] += weight[x] * level(x, y) over x in [a, b) (weight null: 1); with `assign`,
  /// dst[x] = ... (the first level a pixel gets).
  void add(float* dst, int y, int a, int b, const float* weight, bool assign) const {
    if (assign)
      put<true>(dst, y, a, b, weight);
    else
      put<false>(dst, y, a, b, weight);
  }

 private:
  const cv::Mat& level_;
  bool full_;
  Taps rows_;
  cv::Mat wide_;  //!< reduced level: its rows read back along x to full width

  template <bool Assign>
  void put(float* dst, int y, int a, int b, const float* weight) const {
    auto store = [](float& d, float v) {
      if constexpr (Assign)
        d = v;
      else
        d += v;
    };
    if (full_) {
      const float* src = level_.ptr<float>(y);
      for (int x = a; x < b; ++x) {
        const float k = weight ? weight[x] : 1.0f;
        for (int c = 0; c < 3; ++c) store(dst[3 * x + c], k * src[3 * x + c]);
      }
      return;
    }
    const float *top, *bottom;
    float fy;
    sources(y, top, bottom, fy);
    const float gy = 1.0f - fy;
    for (int x = a; x < b; ++x) {
      const float k = weight ? weight[x] : 1.0f;
      for (int c = 0; c < 3; ++c)
        store(dst[3 * x + c], k * (top[3 * x + c] * gy + bottom[3 * x + c] * fy));
    }
  }
};

void check_input(const cv::Mat& rgb) {
  if (rgb.empty() || rgb.type() != CV_32FC3)
    throw std::invalid_argument("equirect blur: a CV_32FC3 image expected");
}

/// Side of the square tiles the varying blur decides its levels on (full-resolution pixels).
constexpr int kTile = 8;

/// The levels each tile of the sigma map mixes: [first, last] (0 is the image itself).
struct TileLevels {
  int tiles_w = 0, tiles_h = 0;
  std::vector<int> first, last;
};

/// Level k of `sigmas` (ascending, sigmas[0] = 0) a pixel of sigma s > 0 mixes with k - 1.
int upper_level(const std::vector<double>& sigmas, double s) {
  const auto it = std::lower_bound(sigmas.begin() + 1, sigmas.end(), s);
  return it == sigmas.end() ? static_cast<int>(sigmas.size()) - 1
                            : static_cast<int>(it - sigmas.begin());
}

TileLevels tile_levels(const cv::Mat& sigma, const std::vector<double>& sigmas) {
  TileLevels t;
  t.tiles_w = (sigma.cols + kTile - 1) / kTile;
  t.tiles_h = (sigma.rows + kTile - 1) / kTile;
  t.first.assign(static_cast<std::size_t>(t.tiles_w * t.tiles_h), 0);
  t.last.assign(t.first.size(), 0);
  cv::parallel_for_(cv::Range(0, t.tiles_h), [&](const cv::Range& r) {
    constexpr float kNone = std::numeric_limits<float>::infinity();
    std::vector<float> lo(static_cast<std::size_t>(t.tiles_w)), hi(lo.size());
    // Per column over the tile's rows first (a streaming loop), then per tile along x.
    std::vector<float> col_lo(static_cast<std::size_t>(sigma.cols)), col_hi(col_lo.size());
    for (int ty = r.start; ty < r.end; ++ty) {
      std::fill(col_lo.begin(), col_lo.end(), kNone);
      std::fill(col_hi.begin(), col_hi.end(), 0.0f);
      for (int y = ty * kTile; y < std::min(sigma.rows, (ty + 1) * kTile); ++y) {
        const float* s = sigma.ptr<float>(y);
        float *pl = col_lo.data(), *ph = col_hi.data();
        for (int x = 0; x < sigma.cols; ++x) {
          pl[x] = std::min(pl[x], s[x]);
          ph[x] = std::max(ph[x], s[x]);
        }
      }
      for (int tx = 0; tx < t.tiles_w; ++tx) {
        float l = kNone, u = 0.0f;
        for (int x = tx * kTile; x < std::min(sigma.cols, (tx + 1) * kTile); ++x) {
          l = std::min(l, col_lo[static_cast<std::size_t>(x)]);
          u = std::max(u, col_hi[static_cast<std::size_t>(x)]);
        }
        lo[static_cast<std::size_t>(tx)] = l;
        hi[static_cast<std::size_t>(tx)] = u;
      }
      for (int tx = 0; tx < t.tiles_w; ++tx) {
        const auto k = static_cast<std::size_t>(ty * t.tiles_w + tx);
        if (!(hi[static_cast<std::size_t>(tx)] > 0.0f)) continue;  // only the image itself
        const float low = lo[static_cast<std::size_t>(tx)];        // sigma <= 0: the image itself
        t.first[k] = low > 0.0f ? upper_level(sigmas, low) - 1 : 0;
        t.last[k] = upper_level(sigmas, hi[static_cast<std::size_t>(tx)]);
      }
    }
  });
  return t;
}

/// The runs [first, last) of tiles of tile row ty whose levels [first, last] satisfy `pick`.
template <typename Pick>
std::vector<std::pair<int, int>> tile_runs_where(const TileLevels& t, int ty, Pick pick) {
  std::vector<std::pair<int, int>> runs;
  const int* first = t.first.data() + static_cast<std::ptrdiff_t>(ty) * t.tiles_w;
  const int* last = t.last.data() + static_cast<std::ptrdiff_t>(ty) * t.tiles_w;
  for (int tx = 0; tx < t.tiles_w;) {
    if (!pick(first[tx], last[tx])) {
      ++tx;
      continue;
    }
    const int a = tx;
    while (tx < t.tiles_w && pick(first[tx], last[tx])) ++tx;
    runs.emplace_back(a, tx);
  }
  return runs;
}

/// The runs [first, last) of tiles of tile row ty that mix level k.
std::vector<std::pair<int, int>> tile_runs(const TileLevels& t, int ty, int k) {
  return tile_runs_where(t, ty, [k](int first, int last) { return k >= first && k <= last; });
}

/// The texels of a level (`lw` x `lh`, read back bilinearly onto the w x h image) that the tiles
/// mixing level k read, as runs per level row.
RowRuns level_runs(const TileLevels& t, int k, int w, int h, int lw, int lh) {
  // The level samples full-resolution index i reads: floor((i + 0.5) m / n - 0.5) and one more.
  auto low = [](int i, int n, int m) {
    return static_cast<int>(std::floor((i + 0.5) * m / n - 0.5));
  };
  RowRuns spans(static_cast<std::size_t>(lh));  // unwrapped column spans, may overlap
  for (int ty = 0; ty < t.tiles_h; ++ty) {
    const auto runs = tile_runs(t, ty, k);
    if (runs.empty()) continue;
    const int y0 = std::max(0, low(ty * kTile, h, lh));
    const int y1 = std::min(lh - 1, low(std::min(h, (ty + 1) * kTile) - 1, h, lh) + 1);
    for (const auto& [a, b] : runs) {
      const int x0 = low(a * kTile, w, lw), x1 = low(std::min(w, b * kTile) - 1, w, lw) + 2;
      for (int y = y0; y <= y1; ++y) spans[static_cast<std::size_t>(y)].emplace_back(x0, x1);
    }
  }
  // Wrapped into [0, lw) (split at the seam), sorted, merged.
  for (auto& row : spans) {
    std::vector<std::pair<int, int>> pieces;
    for (const auto& [a, b] : row) {
      if (b - a >= lw) {
        pieces.emplace_back(0, lw);
        continue;
      }
      const int a0 = ((a % lw) + lw) % lw, b0 = a0 + (b - a);
      pieces.emplace_back(a0, std::min(b0, lw));
      if (b0 > lw) pieces.emplace_back(0, b0 - lw);
    }
    std::sort(pieces.begin(), pieces.end());
    row.clear();
    for (const auto& piece : pieces)
      if (!row.empty() && piece.first <= row.back().second)
        row.back().second = std::max(row.back().second, piece.second);
      else
        row.push_back(piece);
  }
  return spans;
}

/// The levels' sigmas: level 0 is the image itself (sigma 0); then half a texel, growing by
/// `ratio` up to the first at or above `max_sigma`.
std::vector<double> level_sigmas(int w, double max_sigma, double ratio) {
  std::vector<double> sigmas{0.0};
  for (double s = 0.5 * 360.0 / w;; s *= ratio) {
    sigmas.push_back(s);
    if (s >= max_sigma) break;
  }
  return sigmas;
}

/// Pixel weight of level k: a hat in sigma, rising from sigma_{k-1} to 1 at sigma_k and falling
/// to 0 at sigma_{k+1} (level 0 is 1 at sigma <= 0, the last 1 from its sigma on):
/// clamp(min((s - s_{k-1}) rise, (s_{k+1} - s) fall), 0, 1), the linear mix in sigma.
struct LevelHats {
  std::vector<float> base, rise, top, fall;

  explicit LevelHats(const std::vector<double>& sigmas) {
    constexpr float kFlat = 1e30f;
    const std::size_t count = sigmas.size();
    base.resize(count);
    rise.resize(count);
    top.resize(count);
    fall.resize(count);
    for (std::size_t i = 0; i < count; ++i) {
      base[i] = i == 0 ? -kFlat : static_cast<float>(sigmas[i - 1]);
      rise[i] = i == 0 ? 1.0f : static_cast<float>(1.0 / (sigmas[i] - sigmas[i - 1]));
      top[i] = i + 1 == count ? kFlat : static_cast<float>(sigmas[i + 1]);
      fall[i] = i + 1 == count ? 1.0f : static_cast<float>(1.0 / (sigmas[i + 1] - sigmas[i]));
    }
  }
};

/// The output's tile rows mixed from the levels' read-backs, by the tiles' levels and each
/// pixel's sigma.
struct LevelMix {
  const TileLevels& tiles;
  const std::vector<ReadBack>& backs;
  const cv::Mat& sigma_deg;
  const LevelHats& hats;
  int w, h;

  /// Tiles mixing exactly two levels k - 1 and k (nearly all): one pass, the linear mix in
  /// sigma of the two read-backs, lerp(A, B, (s - s_{k-1}) rise_k) (every sigma of such a tile
  /// is in (s_{k-1}, s_k]).
  void two_level_tiles(cv::Mat& out, int ty) const {
    const int count = static_cast<int>(backs.size());
    for (int k = 1; k < count; ++k) {
      const auto runs = tile_runs_where(
          tiles, ty, [k](int first, int last) { return first == k - 1 && last == k; });
      const auto i = static_cast<std::size_t>(k);
      for (int y = ty * kTile; y < std::min(h, (ty + 1) * kTile); ++y)
        for (const auto& [first, last] : runs)
          ReadBack::mix(out.ptr<float>(y), y, first * kTile, std::min(w, last * kTile),
                        backs[i - 1], backs[i], sigma_deg.ptr<float>(y), hats.base[i],
                        hats.rise[i]);
    }
  }

  /// The other tiles, level by level, each pixel weighted by its hat (`weight`: w floats).
  void other_tiles(cv::Mat& out, int ty, std::vector<float>& weight) const {
    const int count = static_cast<int>(backs.size());
    for (int k = 0; k < count; ++k) {
      const auto runs = tile_runs_where(tiles, ty, [k](int first, int last) {
        return k >= first && k <= last && !(first + 1 == last);
      });
      if (runs.empty()) continue;
      for (int y = ty * kTile; y < std::min(h, (ty + 1) * kTile); ++y)
        for (const auto& [first, last] : runs) other_run(out, ty, k, y, first, last, weight);
    }
  }

 private:
  /// Level k added to row y of the run of tiles [first, last) of tile row ty.
  void other_run(cv::Mat& out, int ty, int k, int y, int first, int last,
                 std::vector<float>& weight) const {
    const auto i = static_cast<std::size_t>(k);
    const auto at = [&](int x) { return static_cast<std::size_t>(ty * tiles.tiles_w + x); };
    const float* s = sigma_deg.ptr<float>(y);
    const int a = first * kTile, b = std::min(w, last * kTile);
    for (int x = a; x < b; ++x) {
      const float v =
          std::min((s[x] - hats.base[i]) * hats.rise[i], (hats.top[i] - s[x]) * hats.fall[i]);
      weight[static_cast<std::size_t>(x)] = std::clamp(v, 0.0f, 1.0f);
    }
    // Split where the tiles' first level changes between k and below it.
    for (int tx = first; tx < last;) {
      const bool assign = tiles.first[at(tx)] == k;
      const int from = tx;
      while (tx < last && (tiles.first[at(tx)] == k) == assign) ++tx;
      backs[i].add(out.ptr<float>(y), y, from * kTile, std::min(w, tx * kTile), weight.data(),
                   assign);
    }
  }
};

}  // namespace

cv::Mat blur_equirect(const cv::Mat& rgb, double sigma_deg) {
  check_input(rgb);
  if (!(sigma_deg > 0.0)) return rgb.clone();
  Pyramid pyramid(rgb);
  const cv::Mat level = blurred_level(pyramid, rgb.cols, rgb.rows, sigma_deg, nullptr);
  if (level.size() == rgb.size()) return level;
  cv::Mat out(rgb.size(), CV_32FC3);
  const ReadBack back(level, rgb.cols, rgb.rows, nullptr);
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y)
      back.add(out.ptr<float>(y), y, 0, rgb.cols, nullptr, true);
  });
  return out;
}

cv::Mat blur_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, double ratio) {
  cv::Mat out;
  blur_equirect_varying(rgb, sigma_deg, out, ratio);
  return out;
}

void blur_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, cv::Mat& out,
                           double ratio) {
  check_input(rgb);
  if (out.data == rgb.data && !rgb.empty())
    throw std::invalid_argument("equirect blur: the output must not be the input's buffer");
  if (sigma_deg.size() != rgb.size() || sigma_deg.type() != CV_32FC1)
    throw std::invalid_argument(
        "equirect blur: the sigma map must be CV_32FC1 of the image's size");
  if (!(ratio > 1.0)) throw std::invalid_argument("equirect blur: level ratio must exceed 1");
  double max_sigma = 0.0;
  cv::minMaxLoc(sigma_deg, nullptr, &max_sigma);
  if (!(max_sigma > 0.0)) {
    rgb.copyTo(out);
    return;
  }
  const int w = rgb.cols, h = rgb.rows;
  const std::vector<double> sigmas = level_sigmas(w, max_sigma, ratio);
  const int count = static_cast<int>(sigmas.size());
  // Each pixel mixes only the two levels around its sigma: a level is computed only at the
  // texels its tiles' read-back reaches.
  const TileLevels tiles = tile_levels(sigma_deg, sigmas);
  Pyramid pyramid(rgb);
  std::vector<cv::Mat> levels{rgb};
  std::vector<RowRuns> runs{RowRuns{}};
  for (int k = 1; k < count; ++k) {
    const int f = level_factor(sigmas[static_cast<std::size_t>(k)], w, h);
    const cv::Size size = pyramid.at(f).size();
    runs.push_back(level_runs(tiles, k, w, h, size.width, size.height));
    levels.push_back(
        blurred_level(pyramid, w, h, sigmas[static_cast<std::size_t>(k)], &runs.back()));
  }
  std::vector<ReadBack> backs;
  backs.reserve(levels.size());
  for (std::size_t k = 0; k < levels.size(); ++k) backs.emplace_back(levels[k], w, h, &runs[k]);
  const LevelHats hats(sigmas);
  const LevelMix mix{tiles, backs, sigma_deg, hats, w, h};
  // Levels go in ascending order: a pixel's first (its tile's first level) is stored, the
  // others added, so the output needs no clearing.
  out.create(rgb.size(), CV_32FC3);
  cv::parallel_for_(cv::Range(0, tiles.tiles_h), [&](const cv::Range& r) {
    std::vector<float> weight(static_cast<std::size_t>(w));
    for (int ty = r.start; ty < r.end; ++ty) {
      mix.two_level_tiles(out, ty);
      mix.other_tiles(out, ty, weight);
    }
  });
}

void blur_half_equirect_varying(const cv::Mat& rgb, const cv::Mat& sigma_deg, cv::Mat& out,
                                double ratio) {
  check_input(rgb);
  if (sigma_deg.size() != rgb.size() || sigma_deg.type() != CV_32FC1)
    throw std::invalid_argument(
        "equirect blur: the sigma map must be CV_32FC1 of the image's size");
  const int w = rgb.cols, h = rgb.rows;
  // The canvas spans a whole turn at the image's texel size: the image in columns [0, w) (the
  // 360 blur is the same wherever the seam falls), then the half turn it does not cover, the
  // first half of it east of the image's right edge (its last column repeated), the rest west
  // of its left edge (its first column). Buffers kept by each calling thread.
  // References: the pool's threads below must fill this thread's canvas, not their own.
  thread_local cv::Mat canvas_buffer, sigma_buffer, out_buffer;
  cv::Mat &canvas = canvas_buffer, &canvas_sigma = sigma_buffer, &canvas_out = out_buffer;
  canvas.create(h, 2 * w, CV_32FC3);
  canvas_sigma.create(h, 2 * w, CV_32FC1);
  const int east = (w + 1) / 2;
  rgb.copyTo(canvas.colRange(0, w));
  sigma_deg.copyTo(canvas_sigma.colRange(0, w));
  canvas_sigma.colRange(w, 2 * w).setTo(0.0f);
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
    for (int y = r.start; y < r.end; ++y) {
      const auto* src = rgb.ptr<cv::Vec3f>(y);
      auto* dst = canvas.ptr<cv::Vec3f>(y);
      std::fill(dst + w, dst + w + east, src[w - 1]);
      std::fill(dst + w + east, dst + 2 * w, src[0]);
    }
  });
  blur_equirect_varying(canvas, canvas_sigma, canvas_out, ratio);
  canvas_out.colRange(0, w).copyTo(out);
}

}  // namespace vdfx::effects
