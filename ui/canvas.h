/// @file
/// @brief An RGBA8 software canvas with anti-aliased shapes, image blits and text.
///
/// Pixels are stored PREMULTIPLIED: (r*a, g*a, b*a, a) in sRGB values, CV_8UC4 in R,G,B,A order,
/// row 0 at the top. That is what a quad layer blended with (ONE, ONE_MINUS_SRC_ALPHA) wants, and
/// "over" composites stay exact at translucent edges. to_straight_rgba() converts for PNG files.
/// Shapes are anti-aliased by signed distance: pixel coverage = clamp(0.5 - d, 0, 1) where d is
/// the distance in pixels from the pixel centre to the shape's edge (negative inside).
/// No GL anywhere: the compositor uploads image() as a texture.
///
/// Scale: a canvas may draw at a scale (set_scale): every coordinate, size, stroke width, clip
/// and font size given to it is in layout units, multiplied by the scale to reach its pixels.
/// Panels use it to render their fixed layout at the resolution they cover on screen, so text
/// is rasterised at its on-screen size (crisp) instead of being scaled down afterwards.
#pragma once

#include <glm/vec2.hpp>
#include <opencv2/core.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ui/colour.h"
#include "ui/rect.h"

namespace vdfx::ui {

class Font;
struct LineLayout;

enum class Align { Left, Centre, Right };
/// Channel order of colour images given to Canvas::image (OpenCV decodes to BGR).
enum class ChannelOrder { Bgr, Rgb };

class Canvas {
 public:
  Canvas(int width, int height);
  /// Draws into existing premultiplied RGBA8 pixels (CV_8UC4), sharing the buffer; throws
  /// std::invalid_argument for any other type.
  explicit Canvas(cv::Mat pixels);

  int width() const { return image_.cols; }   //!< pixels
  int height() const { return image_.rows; }  //!< pixels
  /// Pixels per layout unit (default 1). Fonts are rasterised at round(px * scale).
  void set_scale(double scale);
  double scale() const { return scale_; }
  /// Width in layout units of one line of text as this canvas draws it (at its scale).
  double text_width(const Font& font, int px, std::string_view utf8) const;
  /// Premultiplied RGBA8 pixels.
  const cv::Mat& image() const { return image_; }
  /// Straight-alpha RGBA8 copy (PNG convention).
  cv::Mat to_straight_rgba() const;

  /// Sets every pixel (ignores the clip).
  void clear(Rgba c = {0, 0, 0, 0});
  /// Sets the pixels whose centres lie in r and in the clip (no blending): how a partial
  /// re-render wipes the region it redraws.
  void clear_rect(const Rect& r, Rgba c = {0, 0, 0, 0});
  /// Restricts drawing to r intersected with the current clip, until the matching pop_clip.
  void push_clip(const Rect& r);
  void pop_clip();
  Rect clip() const;  //!< layout units

  void fill_rect(const Rect& r, Rgba c) { fill_rounded_rect(r, 0.0, c); }
  void fill_rounded_rect(const Rect& r, double radius, Rgba c);
  /// A stroke of the given width lying inside r's outline.
  void stroke_rounded_rect(const Rect& r, double radius, double width, Rgba c);
  void fill_circle(glm::dvec2 centre, double radius, Rgba c);
  /// A ring of the given width centred on the circle of the given radius.
  void stroke_circle(glm::dvec2 centre, double radius, double width, Rgba c);
  /// A segment with round caps.
  void line(glm::dvec2 a, glm::dvec2 b, double width, Rgba c);
  /// Joined segments with round joins; each pixel is covered once, so translucent colours do not
  /// darken at the joints.
  void polyline(std::span<const glm::dvec2> points, double width, Rgba c, bool closed = false);
  /// A convex polygon (triangles, diamonds), any winding.
  void fill_convex(std::span<const glm::dvec2> points, Rgba c);
  /// Scales an image into dst (rounded to whole pixels). Accepts CV_8UC1, CV_8UC3, CV_8UC4
  /// (straight alpha) and CV_32FC3 (values in [0, 1]); colour images in the given channel order.
  void image(const cv::Mat& src, const Rect& dst, ChannelOrder order = ChannelOrder::Bgr,
             float opacity = 1.f);
  /// One line of UTF-8 text in box, vertically centred, clipped to box; text wider than the box
  /// is cut and ends in an ellipsis. Returns the drawn width in pixels.
  double text(const Font& font, int px, std::string_view utf8, const Rect& box, Align align,
              Rgba c);
  /// Text with its baseline starting at (x, baseline); no fitting.
  void text_at(const Font& font, int px, std::u32string_view text, double x, double baseline,
               Rgba c);

 private:
  /// Blends c with coverage clamp(0.5 - dist(pixel centre), 0, 1) over bounds (grown by one
  /// pixel). dist must be 1-Lipschitz (a signed distance, or min/max/abs of them): rows are
  /// walked in jumps of |d| and interiors filled as spans, evaluating dist only near edges.
  template <class Distance>
  void fill_distance(const Rect& bounds, Rgba c, Distance&& dist);
  void draw_line(const Font& font, int px, const LineLayout& line, double x, double baseline,
                 Rgba c);
  struct PixelBox {
    int x0, y0, x1, y1;
  };
  PixelBox pixel_box(const Rect& r) const;  // r rounded outwards, intersected with the clip
  // Layout units to pixels.
  Rect px(const Rect& r) const { return {r.x * scale_, r.y * scale_, r.w * scale_, r.h * scale_}; }
  glm::dvec2 px(glm::dvec2 p) const { return p * scale_; }
  double px(double v) const { return v * scale_; }
  int font_px(int size) const;

  cv::Mat image_;
  std::vector<Rect> clips_;  //!< pixels
  double scale_ = 1.0;
};

/// An image converted and scaled for one destination rectangle, kept by widgets that draw the
/// same picture every render: Canvas::image(rgba, dst, ChannelOrder::Rgb, opacity) then skips
/// the conversion and resampling and gives the same pixels as drawing the source.
class ScaledImage {
 public:
  /// Straight RGBA8 at dst's whole-pixel size on a canvas of the given scale (Canvas::scale()),
  /// rebuilt only when src's buffer, dst or the scale changed.
  const cv::Mat& get(const cv::Mat& src, const Rect& dst, ChannelOrder order = ChannelOrder::Bgr,
                     double scale = 1.0);

 private:
  const void* src_data_ = nullptr;
  cv::Size src_size_;
  int src_type_ = -1;
  ChannelOrder order_ = ChannelOrder::Bgr;
  Rect dst_;
  cv::Mat rgba_;
};

/// The longest prefix of utf8 that fits max_width with a trailing "…", or utf8 itself if it
/// fits. Cuts at code point boundaries.
std::string fit_text(const Font& font, int px, std::string_view utf8, double max_width);

/// Converts a premultiplied RGBA8 image to straight alpha (fully transparent pixels become 0).
cv::Mat unpremultiply(const cv::Mat& premultiplied);

}  // namespace vdfx::ui
