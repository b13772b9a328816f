/// @file
/// @brief Software rasteriser of canvas.h: signed-distance coverage, premultiplied "over".
#include "ui/canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "ui/font.h"
#include "ui/utf8.h"

namespace vdfx::ui {

namespace {

void premultiply(Rgba c, float out[4]) {
  out[0] = c.r * c.a * 255.f;
  out[1] = c.g * c.a * 255.f;
  out[2] = c.b * c.a * 255.f;
  out[3] = c.a * 255.f;
}

/// lround(v) clamped to [0, 255] for v > -0.5 (blend sums are never below zero): v + 0.5 is
/// exact in double for any float v below 2^28, so truncation rounds half away from zero exactly
/// as lround does, without the libm call.
inline std::uint8_t round_u8(float v) {
  const double r = static_cast<double>(v) + 0.5;
  return r >= 255.0 ? 255 : r <= 0.0 ? 0 : static_cast<std::uint8_t>(r);
}

/// One premultiplied colour "over" RGBA8 pixels: out = src * coverage + dst * (1 - coverage a).
/// Every path computes bit-for-bit what the per-pixel float formula gives (the goldens depend on
/// it); the fast paths only avoid recomputing it.
class Paint {
 public:
  explicit Paint(Rgba c) {
    premultiply(c, pm_);
    keep1_ = 1.f - 1.f * pm_[3] / 255.f;
    if (keep1_ == 0.f) {  // opaque: full coverage writes the colour whatever was there
      std::uint8_t px[4];
      for (int k = 0; k < 4; ++k) px[k] = round_u8(pm_[k]);
      std::memcpy(&solid_, px, 4);
    }
  }
  explicit Paint(const float pm[4]) {
    std::copy(pm, pm + 4, pm_);
    keep1_ = 1.f - 1.f * pm_[3] / 255.f;
  }

  /// Partial coverage in (0, 1].
  void blend(std::uint8_t* d, float coverage) const {
    const float keep = 1.f - coverage * pm_[3] / 255.f;
    for (int k = 0; k < 4; ++k) d[k] = round_u8(pm_[k] * coverage + d[k] * keep);
  }
  /// Full coverage of n consecutive pixels. Interiors mostly lie over one uniform colour, so
  /// the result of the last distinct destination pixel is reused.
  void fill(std::uint8_t* d, int n) {
    if (keep1_ == 0.f) {
      for (int i = 0; i < n; ++i) std::memcpy(d + 4 * i, &solid_, 4);
      return;
    }
    constexpr int kBlock = 8;
    for (int i = 0; i < n;) {
      if (memo_valid_ && i + kBlock <= n) {  // 8 pixels equal to the memo: one branch
        std::uint32_t v[kBlock];
        std::memcpy(v, d + 4 * i, sizeof v);
        std::uint32_t differ = 0;
        for (int j = 0; j < kBlock; ++j) differ |= v[j] ^ memo_in_;
        if (!differ) {
          for (int j = 0; j < kBlock; ++j) v[j] = memo_out_;
          std::memcpy(d + 4 * i, v, sizeof v);
          i += kBlock;
          continue;
        }
      }
      std::uint32_t v;
      std::memcpy(&v, d + 4 * i, 4);
      if (!memo_valid_ || v != memo_in_) {
        memo_in_ = v;
        std::uint8_t px[4];
        std::memcpy(px, &v, 4);
        for (int k = 0; k < 4; ++k) px[k] = round_u8(pm_[k] * 1.f + px[k] * keep1_);
        std::memcpy(&memo_out_, px, 4);
        memo_valid_ = true;
      }
      std::memcpy(d + 4 * i, &memo_out_, 4);
      ++i;
    }
  }

 private:
  float pm_[4];
  float keep1_;
  std::uint32_t solid_ = 0;
  std::uint32_t memo_in_ = 0, memo_out_ = 0;
  bool memo_valid_ = false;
};

/// How many further pixels along a row are certainly on the same side as one at signed distance
/// margin beyond the half-pixel coverage ramp: the distances are 1-Lipschitz (exact SDFs, or max
/// / abs of them), so moving j pixels changes d by at most j. The epsilon keeps float rounding
/// of d from ever deciding a pixel the per-pixel evaluation would have decided otherwise.
inline int certain_run(double margin) {
  constexpr double kEps = 1e-6;
  return margin > kEps ? static_cast<int>(std::min(margin - kEps, 1e9)) : 0;
}

double rounded_box_distance(glm::dvec2 p, const Rect& r, double radius) {
  const glm::dvec2 half{0.5 * r.w, 0.5 * r.h};
  radius = std::clamp(radius, 0.0, std::min(half.x, half.y));
  const glm::dvec2 q = glm::abs(p - r.centre()) - half + glm::dvec2(radius);
  return glm::length(glm::max(q, glm::dvec2(0.0))) + std::min(std::max(q.x, q.y), 0.0) - radius;
}

double segment_distance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a, ap = p - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(ap - t * ab);
}

Rect bounds_of(std::span<const glm::dvec2> pts, double pad) {
  glm::dvec2 lo = pts.front(), hi = pts.front();
  for (auto p : pts) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return {lo.x - pad, lo.y - pad, hi.x - lo.x + 2 * pad, hi.y - lo.y + 2 * pad};
}

}  // namespace

Canvas::Canvas(int width, int height)
    : image_(height, width, CV_8UC4, cv::Scalar::all(0)),
      clips_{Rect{0, 0, static_cast<double>(width), static_cast<double>(height)}} {}

Canvas::Canvas(cv::Mat pixels)
    : image_(std::move(pixels)),
      clips_{Rect{0, 0, static_cast<double>(image_.cols), static_cast<double>(image_.rows)}} {
  if (image_.type() != CV_8UC4)
    throw std::invalid_argument("Canvas: pixels must be CV_8UC4 (premultiplied RGBA8), got type " +
                                std::to_string(image_.type()));
}

cv::Mat unpremultiply(const cv::Mat& premultiplied) {
  cv::Mat out = premultiplied.clone();
  out.forEach<cv::Vec4b>([](cv::Vec4b& p, const int*) {
    if (p[3] == 0) {
      p = cv::Vec4b(0, 0, 0, 0);
      return;
    }
    for (int k = 0; k < 3; ++k)
      p[k] = static_cast<uchar>(std::min(255, (p[k] * 255 + p[3] / 2) / p[3]));
  });
  return out;
}

cv::Mat Canvas::to_straight_rgba() const {
  return unpremultiply(image_);
}

void Canvas::clear(Rgba c) {
  float pm[4];
  premultiply(c, pm);
  image_.setTo(
      cv::Scalar(std::round(pm[0]), std::round(pm[1]), std::round(pm[2]), std::round(pm[3])));
}

void Canvas::set_scale(double scale) {
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument("Canvas::set_scale: scale must be > 0");
  scale_ = scale;
}

int Canvas::font_px(int size) const {
  return scale_ == 1.0 ? size : std::max(1, static_cast<int>(std::lround(size * scale_)));
}

double Canvas::text_width(const Font& font, int px_size, std::string_view utf8) const {
  return font.measure(utf8, font_px(px_size)) / scale_;
}

Rect Canvas::clip() const {
  const Rect& c = clips_.back();
  return {c.x / scale_, c.y / scale_, c.w / scale_, c.h / scale_};
}

void Canvas::clear_rect(const Rect& layout_rect, Rgba c) {
  const Rect r = px(layout_rect);
  float pm[4];
  premultiply(c, pm);
  // Whole pixels whose centres lie in r (pixel_box rounds outwards, so cut it again).
  const PixelBox b = pixel_box(r);
  const int x0 = std::max(b.x0, static_cast<int>(std::ceil(r.x - 0.5)));
  const int y0 = std::max(b.y0, static_cast<int>(std::ceil(r.y - 0.5)));
  const int x1 = std::min(b.x1, static_cast<int>(std::ceil(r.right() - 0.5)));
  const int y1 = std::min(b.y1, static_cast<int>(std::ceil(r.bottom() - 0.5)));
  if (x1 <= x0 || y1 <= y0) return;
  image_(cv::Rect(x0, y0, x1 - x0, y1 - y0))
      .setTo(
          cv::Scalar(std::round(pm[0]), std::round(pm[1]), std::round(pm[2]), std::round(pm[3])));
}

void Canvas::push_clip(const Rect& r) {
  clips_.push_back(clips_.back().intersect(px(r)));
}

void Canvas::pop_clip() {
  if (clips_.size() <= 1) throw std::logic_error("Canvas::pop_clip without push_clip");
  clips_.pop_back();
}

Canvas::PixelBox Canvas::pixel_box(const Rect& r) const {
  const Rect c = clips_.back();
  // The clip is applied on whole pixels: a pixel is drawn if its centre lies inside the clip.
  const int cx0 = static_cast<int>(std::ceil(c.x - 0.5)),
            cy0 = static_cast<int>(std::ceil(c.y - 0.5));
  const int cx1 = static_cast<int>(std::ceil(c.right() - 0.5));
  const int cy1 = static_cast<int>(std::ceil(c.bottom() - 0.5));
  PixelBox b{static_cast<int>(std::floor(r.x)), static_cast<int>(std::floor(r.y)),
             static_cast<int>(std::ceil(r.right())), static_cast<int>(std::ceil(r.bottom()))};
  b.x0 = std::max({b.x0, cx0, 0});
  b.y0 = std::max({b.y0, cy0, 0});
  b.x1 = std::min({b.x1, cx1, width()});
  b.y1 = std::min({b.y1, cy1, height()});
  return b;
}

template <class Distance>
void Canvas::fill_distance(const Rect& bounds, Rgba c, Distance&& dist) {
  if (c.a <= 0.f) return;
  const PixelBox b = pixel_box(bounds.inset(-1.0));
  if (b.x1 <= b.x0 || b.y1 <= b.y0) return;
  Paint paint(c);
  // Walk each row: evaluate d only where coverage may be fractional; where |d| says the next
  // pixels are certainly outside (coverage 0) skip them, certainly inside (coverage 1) fill them
  // as a span. Coverage where evaluated is clamp(0.5 - d, 0, 1), as everywhere in the canvas.
  for (int y = b.y0; y < b.y1; ++y) {
    std::uint8_t* row = image_.ptr<std::uint8_t>(y);
    const double cy = y + 0.5;
    int x = b.x0;
    while (x < b.x1) {
      const double d = dist(glm::dvec2(x + 0.5, cy));
      if (d >= 0.5) {
        x += 1 + certain_run(d - 0.5);
      } else if (d <= -0.5) {
        const int n = std::min(b.x1 - x, 1 + certain_run(-0.5 - d));
        paint.fill(row + 4 * x, n);
        x += n;
      } else {
        paint.blend(row + 4 * x, static_cast<float>(std::clamp(0.5 - d, 0.0, 1.0)));
        ++x;
      }
    }
  }
}

void Canvas::fill_rounded_rect(const Rect& layout_rect, double radius, Rgba c) {
  if (layout_rect.empty()) return;
  const Rect r = px(layout_rect);
  radius = px(radius);
  fill_distance(r, c, [&](glm::dvec2 p) { return rounded_box_distance(p, r, radius); });
}

void Canvas::stroke_rounded_rect(const Rect& layout_rect, double radius, double width, Rgba c) {
  if (layout_rect.empty()) return;
  const Rect r = px(layout_rect);
  radius = px(radius);
  width = px(width);
  fill_distance(r, c, [&](glm::dvec2 p) {
    const double d = rounded_box_distance(p, r, radius);
    return std::abs(d + 0.5 * width) - 0.5 * width;
  });
}

void Canvas::fill_circle(glm::dvec2 centre, double radius, Rgba c) {
  centre = px(centre);
  radius = px(radius);
  const Rect b{centre.x - radius, centre.y - radius, 2 * radius, 2 * radius};
  fill_distance(b, c, [&](glm::dvec2 p) { return glm::length(p - centre) - radius; });
}

void Canvas::stroke_circle(glm::dvec2 centre, double radius, double width, Rgba c) {
  centre = px(centre);
  radius = px(radius);
  width = px(width);
  const double outer = radius + 0.5 * width;
  const Rect b{centre.x - outer, centre.y - outer, 2 * outer, 2 * outer};
  fill_distance(
      b, c, [&](glm::dvec2 p) { return std::abs(glm::length(p - centre) - radius) - 0.5 * width; });
}

void Canvas::line(glm::dvec2 a, glm::dvec2 b, double width, Rgba c) {
  a = px(a);
  b = px(b);
  width = px(width);
  const glm::dvec2 pts[2] = {a, b};
  fill_distance(bounds_of(pts, 0.5 * width), c,
                [&](glm::dvec2 p) { return segment_distance(p, a, b) - 0.5 * width; });
}

void Canvas::polyline(std::span<const glm::dvec2> layout_pts, double width, Rgba c, bool closed) {
  if (layout_pts.size() < 2 || c.a <= 0.f) return;
  std::vector<glm::dvec2> scaled;
  if (scale_ != 1.0)
    for (const glm::dvec2 p : layout_pts) scaled.push_back(px(p));
  const std::span<const glm::dvec2> pts =
      scale_ != 1.0 ? std::span<const glm::dvec2>(scaled) : layout_pts;
  width = px(width);
  // Coverage is the max over segments, gathered in a mask first so joints are blended once.
  const double hw = 0.5 * width;
  const PixelBox box = pixel_box(bounds_of(pts, hw + 1.0));
  if (box.x1 <= box.x0 || box.y1 <= box.y0) return;
  cv::Mat1f mask(box.y1 - box.y0, box.x1 - box.x0, 0.f);
  const size_t n = closed ? pts.size() : pts.size() - 1;
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec2 a = pts[i], b = pts[(i + 1) % pts.size()];
    const glm::dvec2 seg[2] = {a, b};
    const Rect sb = bounds_of(seg, hw + 1.0);
    const int x0 = std::max(box.x0, static_cast<int>(std::floor(sb.x)));
    const int y0 = std::max(box.y0, static_cast<int>(std::floor(sb.y)));
    const int x1 = std::min(box.x1, static_cast<int>(std::ceil(sb.right())));
    const int y1 = std::min(box.y1, static_cast<int>(std::ceil(sb.bottom())));
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const double d = segment_distance({x + 0.5, y + 0.5}, a, b) - hw;
        float& m = mask(y - box.y0, x - box.x0);
        m = std::max(m, static_cast<float>(std::clamp(0.5 - d, 0.0, 1.0)));
      }
  }
  Paint paint(c);
  for (int y = box.y0; y < box.y1; ++y) {
    std::uint8_t* row = image_.ptr<std::uint8_t>(y);
    const float* m = mask.ptr<float>(y - box.y0);
    for (int x = box.x0; x < box.x1; ++x)
      if (const float cov = m[x - box.x0]; cov > 0.f) paint.blend(row + 4 * x, cov);
  }
}

void Canvas::fill_convex(std::span<const glm::dvec2> layout_pts, Rgba c) {
  if (layout_pts.size() < 3) return;
  std::vector<glm::dvec2> scaled;
  if (scale_ != 1.0)
    for (const glm::dvec2 p : layout_pts) scaled.push_back(px(p));
  const std::span<const glm::dvec2> pts =
      scale_ != 1.0 ? std::span<const glm::dvec2>(scaled) : layout_pts;
  // Signed area tells the winding, so edge normals can point outwards either way.
  double area = 0.0;
  for (size_t i = 0; i < pts.size(); ++i) {
    const glm::dvec2 a = pts[i], b = pts[(i + 1) % pts.size()];
    area += a.x * b.y - b.x * a.y;
  }
  const double sign = area > 0 ? 1.0 : -1.0;
  fill_distance(bounds_of(pts, 0.0), c, [&](glm::dvec2 p) {
    double d = -1e9;  // max over edges of the distance outside that edge's half-plane
    for (size_t i = 0; i < pts.size(); ++i) {
      const glm::dvec2 a = pts[i], b = pts[(i + 1) % pts.size()];
      const glm::dvec2 e = glm::normalize(b - a);
      const glm::dvec2 outward = sign * glm::dvec2(e.y, -e.x);
      d = std::max(d, glm::dot(p - a, outward));
    }
    return d;
  });
}

namespace {

/// Whole-pixel placement of an image drawn into dst: x0, y0 and the scaled size.
cv::Rect image_placement(const Rect& dst) {
  const int x0 = static_cast<int>(std::lround(dst.x)), y0 = static_cast<int>(std::lround(dst.y));
  return {x0, y0, static_cast<int>(std::lround(dst.right())) - x0,
          static_cast<int>(std::lround(dst.bottom())) - y0};
}

/// src as straight RGBA8 (see Canvas::image for the accepted types).
cv::Mat to_rgba(const cv::Mat& src, ChannelOrder order) {
  cv::Mat rgba;
  switch (src.type()) {
    case CV_8UC1: cv::cvtColor(src, rgba, cv::COLOR_GRAY2RGBA); break;
    case CV_8UC3:
      cv::cvtColor(src, rgba, order == ChannelOrder::Bgr ? cv::COLOR_BGR2RGBA : cv::COLOR_RGB2RGBA);
      break;
    case CV_8UC4:
      if (order == ChannelOrder::Bgr)
        cv::cvtColor(src, rgba, cv::COLOR_BGRA2RGBA);
      else
        rgba = src;
      break;
    case CV_32FC3: {
      cv::Mat u8;
      src.convertTo(u8, CV_8UC3, 255.0);
      cv::cvtColor(u8, rgba, order == ChannelOrder::Bgr ? cv::COLOR_BGR2RGBA : cv::COLOR_RGB2RGBA);
      break;
    }
    default:
      throw std::invalid_argument("Canvas::image: unsupported cv::Mat type " +
                                  std::to_string(src.type()));
  }
  return rgba;
}

/// rgba resampled to size (INTER_AREA when shrinking); shared, not copied, when it fits already.
cv::Mat scale_to(const cv::Mat& rgba, cv::Size size) {
  if (rgba.size() == size) return rgba;
  cv::Mat scaled;
  const bool shrink = size.width < rgba.cols || size.height < rgba.rows;
  cv::resize(rgba, scaled, size, 0, 0, shrink ? cv::INTER_AREA : cv::INTER_LINEAR);
  return scaled;
}

}  // namespace

const cv::Mat& ScaledImage::get(const cv::Mat& src, const Rect& layout_dst, ChannelOrder order,
                                double scale) {
  const Rect dst{layout_dst.x * scale, layout_dst.y * scale, layout_dst.w * scale,
                 layout_dst.h * scale};
  if (src.data != src_data_ || src.size() != src_size_ || src.type() != src_type_ ||
      order != order_ || !(dst == dst_) || rgba_.empty()) {
    const cv::Rect place = image_placement(dst);
    rgba_ = src.empty() || place.width <= 0 || place.height <= 0
                ? cv::Mat()
                : scale_to(to_rgba(src, order), place.size()).clone();
    src_data_ = src.data, src_size_ = src.size(), src_type_ = src.type();
    order_ = order, dst_ = dst;
  }
  return rgba_;
}

void Canvas::image(const cv::Mat& src, const Rect& layout_dst, ChannelOrder order, float opacity) {
  if (src.empty() || layout_dst.empty()) return;
  const Rect dst = px(layout_dst);
  const cv::Rect place = image_placement(dst);
  const int x0 = place.x, y0 = place.y, w = place.width, h = place.height;
  if (w <= 0 || h <= 0) return;
  const cv::Mat scaled = scale_to(to_rgba(src, order), place.size());
  const PixelBox b = pixel_box(Rect{static_cast<double>(x0), static_cast<double>(y0),
                                    static_cast<double>(w), static_cast<double>(h)});
  for (int y = b.y0; y < b.y1; ++y) {
    std::uint8_t* row = image_.ptr<std::uint8_t>(y);
    const std::uint8_t* srow = scaled.ptr<std::uint8_t>(y - y0);
    for (int x = b.x0; x < b.x1; ++x) {
      const std::uint8_t* s = srow + 4 * (x - x0);
      if (s[3] == 255 && opacity == 1.f) {  // opaque: "over" gives the source exactly
        std::memcpy(row + 4 * x, s, 3);
        row[4 * x + 3] = 255;
        continue;
      }
      const float a = s[3] / 255.f * opacity;
      if (a <= 0.f) continue;
      const float pm[4] = {s[0] * a, s[1] * a, s[2] * a, a * 255.f};
      Paint(pm).blend(row + 4 * x, 1.f);
    }
  }
}

void Canvas::text_at(const Font& font, int size, std::u32string_view text, double x,
                     double baseline, Rgba c) {
  const int fpx = font_px(size);
  draw_line(font, fpx, font.layout(text, fpx), px(x), px(baseline), c);
}

void Canvas::draw_line(const Font& font, int px, const LineLayout& line, double x, double baseline,
                       Rgba c) {
  if (c.a <= 0.f) return;
  Paint paint(c);
  const int base = static_cast<int>(std::lround(baseline));
  for (const PlacedGlyph& g : line.glyphs) {
    // Integer pen plus a quarter-pixel bucket: sharp stems, even spacing, a bounded cache.
    const double pen = x + g.x;
    double whole = std::floor(pen);
    int sub = static_cast<int>(std::lround((pen - whole) * 4.0));
    if (sub == 4) whole += 1.0, sub = 0;
    const GlyphBitmap& bm = font.glyph(g.glyph, px, sub);
    if (bm.coverage.empty()) continue;
    const int gx = static_cast<int>(whole) + bm.left, gy = base + bm.top;
    const PixelBox b =
        pixel_box(Rect{static_cast<double>(gx), static_cast<double>(gy),
                       static_cast<double>(bm.width), static_cast<double>(bm.height)});
    for (int y = b.y0; y < b.y1; ++y) {
      std::uint8_t* row = image_.ptr<std::uint8_t>(y);
      const std::uint8_t* cov = bm.coverage.data() + static_cast<size_t>(y - gy) * bm.width - gx;
      for (int xx = b.x0; xx < b.x1; ++xx) {
        if (cov[xx] == 255)
          paint.fill(row + 4 * xx, 1);
        else if (cov[xx])
          paint.blend(row + 4 * xx, cov[xx] / 255.f);
      }
    }
  }
}

double Canvas::text(const Font& font, int size, std::string_view utf8, const Rect& layout_box,
                    Align align, Rgba c) {
  const int px = font_px(size);
  const Rect box = this->px(layout_box);
  // Lay the line out once; only text that does not fit is cut (as fit_text does) and redone.
  LineLayout line = font.layout(decode_utf8(utf8), px);
  if (line.width > box.w) line = font.layout(decode_utf8(fit_text(font, px, utf8, box.w)), px);
  const double width = line.width;
  const FontMetrics m = font.metrics(px);
  double x = box.x;
  if (align == Align::Centre) x = box.x + 0.5 * (box.w - width);
  if (align == Align::Right) x = box.right() - width;
  const double baseline = box.y + 0.5 * (box.h - (m.ascent + m.descent)) + m.ascent;
  clips_.push_back(clips_.back().intersect(box));  // box is in pixels already
  draw_line(font, px, line, x, baseline, c);
  clips_.pop_back();
  return width / scale_;
}

std::string fit_text(const Font& font, int px, std::string_view utf8, double max_width) {
  std::u32string s = decode_utf8(utf8);
  if (font.layout(s, px).width <= max_width) return std::string(utf8);
  const std::u32string ellipsis = U"\u2026";
  // Binary search on the prefix length: width grows with length (advances are positive).
  size_t lo = 0, hi = s.size();
  while (lo < hi) {
    const size_t mid = (lo + hi + 1) / 2;
    if (font.layout(s.substr(0, mid) + ellipsis, px).width <= max_width)
      lo = mid;
    else
      hi = mid - 1;
  }
  while (lo > 0 && s[lo - 1] == U' ') --lo;  // no "word …"
  std::string out;
  for (size_t i = 0; i < lo; ++i) out += encode_utf8(s[i]);
  return out + encode_utf8(ellipsis[0]);
}

}  // namespace vdfx::ui
