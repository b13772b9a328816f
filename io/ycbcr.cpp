/// @file
/// @brief Y'CbCr <-> R'G'B' on the CPU (the reference the GPU conversion is tested against).
#include "io/ycbcr.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <vector>

namespace vdfx::io {
namespace {

/// Code value scales of H.273 for n-bit codes.
struct CodeScales {
  double y_offset, y_scale;  //!< E'Y = (Y - y_offset) * y_scale
  double c_offset, c_scale;  //!< E'C = (C - c_offset) * c_scale
};

CodeScales code_scales(const YcbcrInfo& info) {
  const int n = info.bit_depth;
  if (n < 1 || n > 16)
    throw std::invalid_argument("Y'CbCr bit depth " + std::to_string(n) + " is not 1..16");
  const double s = std::ldexp(1.0, n - 8);
  const double c_offset = std::ldexp(1.0, n - 1);
  if (info.full_range) {
    const double max = std::ldexp(1.0, n) - 1.0;
    return {0.0, 1.0 / max, c_offset, 1.0 / max};
  }
  return {16.0 * s, 1.0 / (219.0 * s), c_offset, 1.0 / (224.0 * s)};
}

/// Per luma column (or row): the two chroma samples it blends and the weight of the second.
struct ChromaTaps {
  std::vector<int> i0, i1;
  std::vector<float> f;
};

/// `wrap`: the axis is periodic (an equirect's columns: azimuth), else clamped at the edges.
ChromaTaps chroma_taps(int luma_count, int chroma_count, int log2_sub, double siting, bool wrap) {
  ChromaTaps t;
  t.i0.resize(luma_count);
  t.i1.resize(luma_count);
  t.f.resize(luma_count);
  const double step = std::ldexp(1.0, log2_sub);
  for (int x = 0; x < luma_count; ++x) {
    const double c = (x - siting) / step;
    const double c0 = std::floor(c);
    const int i = static_cast<int>(c0);
    if (wrap) {
      t.i0[x] = ((i % chroma_count) + chroma_count) % chroma_count;
      t.i1[x] = (t.i0[x] + 1) % chroma_count;
    } else {
      t.i0[x] = std::clamp(i, 0, chroma_count - 1);
      t.i1[x] = std::clamp(i + 1, 0, chroma_count - 1);
    }
    t.f[x] = static_cast<float>(c - c0);
  }
  return t;
}

template <typename T, typename Out>
void convert_rows(const Picture& p, const AffineMap3& map, const ChromaTaps& cols,
                  const ChromaTaps& rows, cv::Mat& out, const cv::Range& range) {
  std::array<float, 9> m{};
  std::array<float, 3> o{};
  for (int i = 0; i < 9; ++i) m[i] = static_cast<float>(map.m[i]);
  for (int i = 0; i < 3; ++i) o[i] = static_cast<float>(map.offset[i]);
  const int w = p.planes[0].cols, cw = p.planes[1].cols;
  // Per row: the two chroma rows around it blended once (cw samples, vectorised), then each
  // pixel blends two neighbours of that row: bilinear, in the other order of the separable lerps.
  std::vector<float> cb_row(static_cast<std::size_t>(cw)), cr_row(static_cast<std::size_t>(cw));
  for (int y = range.start; y < range.end; ++y) {
    const T* py = p.planes[0].ptr<T>(y);
    const T* u0 = p.planes[1].ptr<T>(rows.i0[y]);
    const T* u1 = p.planes[1].ptr<T>(rows.i1[y]);
    const T* v0 = p.planes[2].ptr<T>(rows.i0[y]);
    const T* v1 = p.planes[2].ptr<T>(rows.i1[y]);
    const float fy = rows.f[y];
    for (int j = 0; j < cw; ++j) {
      cb_row[j] = u0[j] + fy * (static_cast<float>(u1[j]) - u0[j]);
      cr_row[j] = v0[j] + fy * (static_cast<float>(v1[j]) - v0[j]);
    }
    Out* dst = out.ptr<Out>(y);
    for (int x = 0; x < w; ++x) {
      const int a = cols.i0[x], b = cols.i1[x];
      const float fx = cols.f[x];
      const float cb = cb_row[a] + fx * (cb_row[b] - cb_row[a]);
      const float cr = cr_row[a] + fx * (cr_row[b] - cr_row[a]);
      const float yy = py[x];
      for (int c = 0; c < 3; ++c) {
        const float v =
            std::clamp(m[3 * c] * yy + m[3 * c + 1] * cb + m[3 * c + 2] * cr + o[c], 0.0f, 1.0f);
        if constexpr (std::is_same_v<Out, cv::Vec3b>)
          dst[x][c] = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
        else
          dst[x][c] = v;
      }
    }
  }
}

template <typename T>
void convert(const Picture& p, PixelFormat format, cv::Mat& out) {
  const YcbcrInfo& info = p.ycbcr;
  const int w = p.planes[0].cols, h = p.planes[0].rows;
  const ChromaTaps cols = chroma_taps(w, p.planes[1].cols, info.log2_chroma_w, info.chroma_x, true);
  const ChromaTaps rows =
      chroma_taps(h, p.planes[1].rows, info.log2_chroma_h, info.chroma_y, false);
  const AffineMap3 map = ycbcr_to_rgb_map(info);
  out.create(h, w, format == PixelFormat::Rgb8 ? CV_8UC3 : CV_32FC3);
  // Rows are independent: OpenCV's pool splits them (serial when called from inside a pool task).
  cv::parallel_for_(cv::Range(0, h), [&](const cv::Range& r) {
    if (format == PixelFormat::Rgb8)
      convert_rows<T, cv::Vec3b>(p, map, cols, rows, out, r);
    else
      convert_rows<T, cv::Vec3f>(p, map, cols, rows, out, r);
  });
}

/// Taps of the tent filter that makes chroma sample j (centred on its siting, half-width one
/// subsampling step), over `n` source samples (clamped at the edges), normalised.
std::vector<std::vector<std::pair<int, float>>> tent_taps(int out_n, int n, int log2_sub,
                                                          double siting) {
  const double step = std::ldexp(1.0, log2_sub);
  std::vector<std::vector<std::pair<int, float>>> taps(static_cast<std::size_t>(out_n));
  for (int j = 0; j < out_n; ++j) {
    const double centre = j * step + siting;
    const int lo = static_cast<int>(std::ceil(centre - step));
    const int hi = static_cast<int>(std::floor(centre + step));
    double sum = 0.0;
    auto& t = taps[static_cast<std::size_t>(j)];
    for (int x = lo; x <= hi; ++x) {
      const double wgt = 1.0 - std::abs(x - centre) / step;
      if (wgt <= 0.0) continue;
      t.emplace_back(std::clamp(x, 0, n - 1), static_cast<float>(wgt));
      sum += wgt;
    }
    for (auto& tap : t) tap.second = static_cast<float>(tap.second / sum);
  }
  return taps;
}

inline float clamp01(float v) {
  return v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
}
inline cv::Vec3f clamp01(const cv::Vec3f& v) {
  return {clamp01(v[0]), clamp01(v[1]), clamp01(v[2])};
}

/// R'G'B' (CV_32FC3 or CV_8UC3, clamped to [0, 1] on the way) filtered down to the chroma grid:
/// along x, then along y; the result is CV_32FC3 of cw x ch.
cv::Mat chroma_rgb(const cv::Mat& rgb, int cw, int ch, const YcbcrInfo& info) {
  const auto tx = tent_taps(cw, rgb.cols, info.log2_chroma_w, info.chroma_x);
  const auto ty = tent_taps(ch, rgb.rows, info.log2_chroma_h, info.chroma_y);
  const bool bytes = rgb.depth() == CV_8U;
  auto pixel = [&](int y, int x) {
    if (bytes) return cv::Vec3f(rgb.at<cv::Vec3b>(y, x)) * (1.0f / 255.0f);
    return clamp01(rgb.at<cv::Vec3f>(y, x));
  };
  cv::Mat horizontal(rgb.rows, cw, CV_32FC3), out(ch, cw, CV_32FC3);
  std::vector<cv::Vec3f> line(static_cast<std::size_t>(rgb.cols));
  for (int y = 0; y < rgb.rows; ++y) {
    for (int x = 0; x < rgb.cols; ++x) line[static_cast<std::size_t>(x)] = pixel(y, x);
    cv::Vec3f* d = horizontal.ptr<cv::Vec3f>(y);
    for (int j = 0; j < cw; ++j) {
      cv::Vec3f acc(0, 0, 0);
      for (const auto& [x, wgt] : tx[static_cast<std::size_t>(j)])
        acc += line[static_cast<std::size_t>(x)] * wgt;
      d[j] = acc;
    }
  }
  for (int i = 0; i < ch; ++i) {
    cv::Vec3f* d = out.ptr<cv::Vec3f>(i);
    for (int j = 0; j < cw; ++j) d[j] = cv::Vec3f(0, 0, 0);
    for (const auto& [y, wgt] : ty[static_cast<std::size_t>(i)]) {
      const cv::Vec3f* s = horizontal.ptr<cv::Vec3f>(y);
      for (int j = 0; j < cw; ++j) d[j] += s[j] * wgt;
    }
  }
  return out;
}

}  // namespace

LumaWeights luma_weights(YcbcrMatrix matrix) {
  switch (matrix) {
    case YcbcrMatrix::Bt601: return {0.299, 0.114};
    case YcbcrMatrix::Bt709: return {0.2126, 0.0722};
    case YcbcrMatrix::Bt2020: return {0.2627, 0.0593};
  }
  return {0.2126, 0.0722};
}

AffineMap3 ycbcr_to_rgb_map(const YcbcrInfo& info) {
  const LumaWeights k = luma_weights(info.matrix);
  const CodeScales s = code_scales(info);
  const double r_cr = 2.0 * (1.0 - k.kr), b_cb = 2.0 * (1.0 - k.kb);
  const double g_cb = -b_cb * k.kb / k.kg(), g_cr = -r_cr * k.kr / k.kg();
  AffineMap3 a;
  // Rows R, G, B; columns Y, Cb, Cr, each already scaled from code values.
  const double rows[3][3] = {{1.0, 0.0, r_cr}, {1.0, g_cb, g_cr}, {1.0, b_cb, 0.0}};
  for (int r = 0; r < 3; ++r) {
    a.m[3 * r + 0] = rows[r][0] * s.y_scale;
    a.m[3 * r + 1] = rows[r][1] * s.c_scale;
    a.m[3 * r + 2] = rows[r][2] * s.c_scale;
    a.offset[r] = -(a.m[3 * r + 0] * s.y_offset + (a.m[3 * r + 1] + a.m[3 * r + 2]) * s.c_offset);
  }
  return a;
}

AffineMap3 rgb_to_ycbcr_map(const YcbcrInfo& info) {
  const LumaWeights k = luma_weights(info.matrix);
  const CodeScales s = code_scales(info);
  // E'Y = Kr R + Kg G + Kb B, E'Cb = (B - E'Y) / (2 (1 - Kb)), E'Cr = (R - E'Y) / (2 (1 - Kr)).
  const double ey[3] = {k.kr, k.kg(), k.kb};
  const double cb_d = 2.0 * (1.0 - k.kb), cr_d = 2.0 * (1.0 - k.kr);
  AffineMap3 a;
  for (int c = 0; c < 3; ++c) {
    a.m[c] = ey[c] / s.y_scale;
    a.m[3 + c] = ((c == 2 ? 1.0 : 0.0) - ey[c]) / cb_d / s.c_scale;
    a.m[6 + c] = ((c == 0 ? 1.0 : 0.0) - ey[c]) / cr_d / s.c_scale;
  }
  a.offset = {s.y_offset, s.c_offset, s.c_offset};
  return a;
}

cv::Mat to_rgb(const Picture& p, PixelFormat format) {
  cv::Mat out;
  to_rgb(p, format, out);
  return out;
}

void to_rgb(const Picture& p, PixelFormat format, cv::Mat& out) {
  if (p.empty()) throw std::invalid_argument("to_rgb: empty picture");
  if (!p.is_ycbcr()) {
    const bool want8 = format == PixelFormat::Rgb8;
    if (want8 == (p.rgb.depth() == CV_8U))
      p.rgb.copyTo(out);
    else if (want8)
      p.rgb.convertTo(out, CV_8UC3, 255.0);  // rounds to nearest, saturates
    else
      p.rgb.convertTo(out, CV_32FC3, 1.0 / 255.0);
    return;
  }
  const int depth = p.planes[0].depth();
  for (const cv::Mat& plane : p.planes)
    if (plane.empty() || plane.depth() != depth || plane.channels() != 1)
      throw std::invalid_argument(
          "to_rgb: Y'CbCr planes must be one-channel 8- or 16-bit, all alike");
  if (depth == CV_8U) return convert<std::uint8_t>(p, format, out);
  if (depth == CV_16U) return convert<std::uint16_t>(p, format, out);
  throw std::invalid_argument("to_rgb: unsupported plane depth");
}

Picture rgb_to_ycbcr(const cv::Mat& rgb, const YcbcrInfo& info) {
  if (rgb.empty() || (rgb.type() != CV_32FC3 && rgb.type() != CV_8UC3))
    throw std::invalid_argument("rgb_to_ycbcr: CV_32FC3 or CV_8UC3 RGB expected");
  if (info.bit_depth != 8) throw std::invalid_argument("rgb_to_ycbcr: 8-bit codes only");
  const AffineMap3 a = rgb_to_ycbcr_map(info);
  const int w = rgb.cols, h = rgb.rows;
  const int cw = (w + (1 << info.log2_chroma_w) - 1) >> info.log2_chroma_w;
  const int ch = (h + (1 << info.log2_chroma_h) - 1) >> info.log2_chroma_h;
  Picture p;
  p.ycbcr = info;
  p.planes[0].create(h, w, CV_8UC1);
  p.planes[1].create(ch, cw, CV_8UC1);
  p.planes[2].create(ch, cw, CV_8UC1);
  // Codes are never negative here (offsets >= 0, inputs clamped): rounding is + 0.5 and a cut.
  auto code = [](float v) { return static_cast<std::uint8_t>(std::clamp(v + 0.5f, 0.0f, 255.0f)); };
  const float m0 = static_cast<float>(a.m[0]), m1 = static_cast<float>(a.m[1]),
              m2 = static_cast<float>(a.m[2]);
  const float o0 = static_cast<float>(a.offset[0]);
  for (int y = 0; y < h; ++y) {
    std::uint8_t* d = p.planes[0].ptr<std::uint8_t>(y);
    if (rgb.depth() == CV_8U) {
      const cv::Vec3b* s = rgb.ptr<cv::Vec3b>(y);
      for (int x = 0; x < w; ++x)
        d[x] = code((m0 * s[x][0] + m1 * s[x][1] + m2 * s[x][2]) * (1.0f / 255.0f) + o0);
    } else {
      const cv::Vec3f* s = rgb.ptr<cv::Vec3f>(y);
      for (int x = 0; x < w; ++x)
        d[x] = code(m0 * clamp01(s[x][0]) + m1 * clamp01(s[x][1]) + m2 * clamp01(s[x][2]) + o0);
    }
  }
  // Chroma: R'G'B' filtered down to the chroma grid (linear, so the same as filtering Cb, Cr).
  const cv::Mat sub = chroma_rgb(rgb, cw, ch, info);
  for (int y = 0; y < ch; ++y) {
    const cv::Vec3f* s = sub.ptr<cv::Vec3f>(y);
    std::uint8_t* cb = p.planes[1].ptr<std::uint8_t>(y);
    std::uint8_t* cr = p.planes[2].ptr<std::uint8_t>(y);
    for (int x = 0; x < cw; ++x) {
      cb[x] = code(
          static_cast<float>(a.m[3] * s[x][0] + a.m[4] * s[x][1] + a.m[5] * s[x][2] + a.offset[1]));
      cr[x] = code(
          static_cast<float>(a.m[6] * s[x][0] + a.m[7] * s[x][1] + a.m[8] * s[x][2] + a.offset[2]));
    }
  }
  return p;
}

}  // namespace vdfx::io
