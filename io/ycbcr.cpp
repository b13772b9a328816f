/// @file
/// @brief Y'CbCr <-> R'G'B' on the CPU (the reference the GPU conversion is tested against).
#include "io/ycbcr.h"

#include <algorithm>
#include <array>
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
  // Per row: the two chroma rows around it blended once (cw samples), then spread to every
  // luma column (w samples per plane: bilinear, in the other order of the separable lerps), so
  // that the per-pixel loop reads three planes in step and vectorises.
  std::vector<float> cb_row(static_cast<std::size_t>(cw)), cr_row(static_cast<std::size_t>(cw));
  std::vector<float> cb(static_cast<std::size_t>(w)), cr(static_cast<std::size_t>(w));
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
    for (int x = 0; x < w; ++x) {
      const int a = cols.i0[x], b = cols.i1[x];
      const float fx = cols.f[x];
      cb[x] = cb_row[a] + fx * (cb_row[b] - cb_row[a]);
      cr[x] = cr_row[a] + fx * (cr_row[b] - cr_row[a]);
    }
    // Byte stores may alias anything: locals (no vector or capture reloads) let it vectorise.
    Out* dst = out.ptr<Out>(y);
    const float *pu = cb.data(), *pv = cr.data();
    const int n = w;
    for (int x = 0; x < n; ++x) {
      const float yy = py[x], u = pu[x], v = pv[x];
      const float r = std::clamp(m[0] * yy + m[1] * u + m[2] * v + o[0], 0.0f, 1.0f);
      const float g = std::clamp(m[3] * yy + m[4] * u + m[5] * v + o[1], 0.0f, 1.0f);
      const float bl = std::clamp(m[6] * yy + m[7] * u + m[8] * v + o[2], 0.0f, 1.0f);
      if constexpr (std::is_same_v<Out, cv::Vec3b>) {
        dst[x][0] = static_cast<std::uint8_t>(r * 255.0f + 0.5f);
        dst[x][1] = static_cast<std::uint8_t>(g * 255.0f + 0.5f);
        dst[x][2] = static_cast<std::uint8_t>(bl * 255.0f + 0.5f);
      } else {
        dst[x][0] = r;
        dst[x][1] = g;
        dst[x][2] = bl;
      }
    }
  }
}

template <typename T>
void convert(const Picture& p, PixelFormat format, cv::Mat& out, bool wrap_columns) {
  const YcbcrInfo& info = p.ycbcr;
  const int w = p.planes[0].cols, h = p.planes[0].rows;
  const ChromaTaps cols =
      chroma_taps(w, p.planes[1].cols, info.log2_chroma_w, info.chroma_x, wrap_columns);
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

/// The tent filter along one axis as runs the loops can stream: every output sample j in
/// [lo, hi) reads src[step j + offset[t]] with weight weight[t] (the same taps, shifted); the
/// samples near the edges, where the clamp changes them, keep their own lists.
struct TentFilter {
  int step = 1, lo = 0, hi = 0;
  std::vector<int> offset;
  std::vector<float> weight;
  std::vector<std::vector<std::pair<int, float>>> taps;  //!< every sample's own taps
};

TentFilter tent_filter(int out_n, int n, int log2_sub, double siting) {
  TentFilter f;
  f.taps = tent_taps(out_n, n, log2_sub, siting);
  f.step = 1 << log2_sub;
  // The pattern of a sample in the middle; the run is every sample whose taps are that pattern
  // shifted by step j (all of them but at most a few at each edge).
  const int mid = out_n / 2;
  for (const auto& [x, wgt] : f.taps[static_cast<std::size_t>(mid)]) {
    f.offset.push_back(x - f.step * mid);
    f.weight.push_back(wgt);
  }
  auto regular = [&](int j) {
    const auto& t = f.taps[static_cast<std::size_t>(j)];
    if (t.size() != f.offset.size()) return false;
    for (std::size_t k = 0; k < t.size(); ++k)
      if (t[k].first != f.step * j + f.offset[k] || t[k].second != f.weight[k]) return false;
    return true;
  };
  f.lo = mid;
  while (f.lo > 0 && regular(f.lo - 1)) --f.lo;
  f.hi = mid + 1;
  while (f.hi < out_n && regular(f.hi)) ++f.hi;
  return f;
}

/// out[j] = sum of the taps of sample j over src, j in [0, out_n).
void filter_line(const TentFilter& f, const float* src, float* out, int out_n) {
  for (int j = 0; j < out_n; ++j) {
    if (j == f.lo) j = f.hi;  // the regular run, below
    if (j >= out_n) break;
    float acc = 0.0f;
    for (const auto& [x, wgt] : f.taps[static_cast<std::size_t>(j)]) acc += wgt * src[x];
    out[j] = acc;
  }
  for (int j = f.lo; j < f.hi; ++j) out[j] = 0.0f;
  for (std::size_t k = 0; k < f.offset.size(); ++k) {
    const float wgt = f.weight[k];
    const float* s = src + f.offset[k];
    for (int j = f.lo; j < f.hi; ++j) out[j] += wgt * s[f.step * j];
  }
}

/// R'G'B' -> Y'CbCr codes of one conversion (rgb_to_ycbcr), its constants in float.
struct ToCodes {
  std::array<float, 9> m{};  //!< rows Y', Cb, Cr of rgb_to_ycbcr_map
  std::array<float, 3> offset{};
  float top = 255.0f;  //!< the largest code
  bool deep = false;   //!< 16-bit planes, codes LSB-aligned (io/picture.h)
};

/// The code of a value: codes are never negative here (offsets >= 0, inputs clamped), so
/// rounding is + 0.5 and a cut.
template <typename T>
inline T code_of(float v, float top) {
  return static_cast<T>(std::clamp(v + 0.5f, 0.0f, top));
}

/// Row y of an R'G'B' image (8-bit or float) as three lines of floats in [0, 1].
void read_rgb_row(const cv::Mat& rgb, int y, float* r, float* g, float* b) {
  const int w = rgb.cols;
  if (rgb.depth() == CV_8U) {
    const std::uint8_t* s = rgb.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      r[x] = s[3 * x] * (1.0f / 255.0f);
      g[x] = s[3 * x + 1] * (1.0f / 255.0f);
      b[x] = s[3 * x + 2] * (1.0f / 255.0f);
    }
    return;
  }
  const float* s = rgb.ptr<float>(y);
  for (int x = 0; x < w; ++x) {
    r[x] = clamp01(s[3 * x]);
    g[x] = clamp01(s[3 * x + 1]);
    b[x] = clamp01(s[3 * x + 2]);
  }
}

/// Luma codes of one row into `d`, and the row's Cb and Cr without their offsets into u, v.
template <typename T>
void luma_row(const ToCodes& c, const float* pr, const float* pg, const float* pb, int n, T* d,
              float* pu, float* pv) {
  // Byte stores may alias anything: locals (and no vector or capture reloads) let it vectorise.
  const std::array<float, 9> k = c.m;
  const float ko = c.offset[0], top = c.top;
  for (int x = 0; x < n; ++x)
    d[x] = code_of<T>(k[0] * pr[x] + k[1] * pg[x] + k[2] * pb[x] + ko, top);
  for (int x = 0; x < n; ++x) {
    pu[x] = k[3] * pr[x] + k[4] * pg[x] + k[5] * pb[x];
    pv[x] = k[6] * pr[x] + k[7] * pg[x] + k[8] * pb[x];
  }
}

/// The luma plane, and Cb and Cr (without their offsets) filtered along x onto the chroma
/// columns, row by row: cb_h, cr_h are h x cw.
void luma_and_chroma_columns(const cv::Mat& rgb, const ToCodes& c, const TentFilter& fx, Picture& p,
                             cv::Mat& cb_h, cv::Mat& cr_h) {
  const int w = rgb.cols, cw = cb_h.cols;
  cv::parallel_for_(cv::Range(0, rgb.rows), [&](const cv::Range& rows) {
    std::vector<float> r(static_cast<std::size_t>(w)), g(r.size()), b(r.size()), u(r.size()),
        v(r.size());
    for (int y = rows.start; y < rows.end; ++y) {
      read_rgb_row(rgb, y, r.data(), g.data(), b.data());
      if (c.deep)
        luma_row(c, r.data(), g.data(), b.data(), w, p.planes[0].ptr<std::uint16_t>(y), u.data(),
                 v.data());
      else
        luma_row(c, r.data(), g.data(), b.data(), w, p.planes[0].ptr<std::uint8_t>(y), u.data(),
                 v.data());
      filter_line(fx, u.data(), cb_h.ptr<float>(y), cw);
      filter_line(fx, v.data(), cr_h.ptr<float>(y), cw);
    }
  });
}

/// Cb and Cr codes of one chroma row from their values (offsets included).
template <typename T>
void chroma_codes(const float* pu, const float* pv, int n, float top, T* cb, T* cr) {
  for (int j = 0; j < n; ++j) {
    cb[j] = code_of<T>(pu[j], top);
    cr[j] = code_of<T>(pv[j], top);
  }
}

/// The chroma planes: cb_h, cr_h filtered along y onto the chroma rows, offsets added, coded.
void chroma_rows(const cv::Mat& cb_h, const cv::Mat& cr_h, const ToCodes& c, const TentFilter& fy,
                 Picture& p) {
  const int cw = cb_h.cols, ch = p.planes[1].rows;
  const float o1 = c.offset[1], o2 = c.offset[2];
  cv::parallel_for_(cv::Range(0, ch), [&](const cv::Range& rows) {
    std::vector<float> u(static_cast<std::size_t>(cw)), v(u.size());
    for (int i = rows.start; i < rows.end; ++i) {
      std::fill(u.begin(), u.end(), o1);
      std::fill(v.begin(), v.end(), o2);
      for (const auto& [y, wgt] : fy.taps[static_cast<std::size_t>(i)]) {
        const float* su = cb_h.ptr<float>(y);
        const float* sv = cr_h.ptr<float>(y);
        for (int j = 0; j < cw; ++j) {
          u[j] += wgt * su[j];
          v[j] += wgt * sv[j];
        }
      }
      if (c.deep)
        chroma_codes(u.data(), v.data(), cw, c.top, p.planes[1].ptr<std::uint16_t>(i),
                     p.planes[2].ptr<std::uint16_t>(i));
      else
        chroma_codes(u.data(), v.data(), cw, c.top, p.planes[1].ptr<std::uint8_t>(i),
                     p.planes[2].ptr<std::uint8_t>(i));
    }
  });
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

void to_rgb(const Picture& p, PixelFormat format, cv::Mat& out, bool wrap_columns) {
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
  if (depth == CV_8U) return convert<std::uint8_t>(p, format, out, wrap_columns);
  if (depth == CV_16U) return convert<std::uint16_t>(p, format, out, wrap_columns);
  throw std::invalid_argument("to_rgb: unsupported plane depth");
}

Picture rgb_to_ycbcr(const cv::Mat& rgb, const YcbcrInfo& info) {
  if (rgb.empty() || (rgb.type() != CV_32FC3 && rgb.type() != CV_8UC3))
    throw std::invalid_argument("rgb_to_ycbcr: CV_32FC3 or CV_8UC3 RGB expected");
  if (info.bit_depth != 8 && info.bit_depth != 10)
    throw std::invalid_argument("rgb_to_ycbcr: 8- or 10-bit codes only");
  ToCodes c;
  c.deep = info.bit_depth > 8;
  c.top = static_cast<float>((1 << info.bit_depth) - 1);
  const AffineMap3 a = rgb_to_ycbcr_map(info);
  for (int i = 0; i < 9; ++i) c.m[i] = static_cast<float>(a.m[i]);
  for (int i = 0; i < 3; ++i) c.offset[i] = static_cast<float>(a.offset[i]);
  const int w = rgb.cols, h = rgb.rows;
  const int cw = (w + (1 << info.log2_chroma_w) - 1) >> info.log2_chroma_w;
  const int ch = (h + (1 << info.log2_chroma_h) - 1) >> info.log2_chroma_h;
  Picture p;
  p.ycbcr = info;
  const int plane_type = c.deep ? CV_16UC1 : CV_8UC1;
  p.planes[0].create(h, w, plane_type);
  p.planes[1].create(ch, cw, plane_type);
  p.planes[2].create(ch, cw, plane_type);
  // Chroma: Cb and Cr of the clamped R'G'B' (without their offsets) filtered along x onto the
  // chroma columns, row by row with the luma; then along y. The filter is linear, so this is
  // filtering R'G'B' down to the chroma grid and converting there.
  const TentFilter fx = tent_filter(cw, w, info.log2_chroma_w, info.chroma_x);
  const TentFilter fy = tent_filter(ch, h, info.log2_chroma_h, info.chroma_y);
  cv::Mat cb_h(h, cw, CV_32FC1), cr_h(h, cw, CV_32FC1);
  luma_and_chroma_columns(rgb, c, fx, p, cb_h, cr_h);
  chroma_rows(cb_h, cr_h, c, fy, p);
  return p;
}

}  // namespace vdfx::io
