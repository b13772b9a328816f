/// @file
/// @brief Panel: widgets on a W x H pixel surface shown as a w x h metre quad in the world.
///
/// Panel space: the quad is centred on pose().position, its local +x is right, +y up and it
/// faces its local +z (like an OpenXR quad layer): rays must come from the +z side to hit it.
/// Pixel (0, 0) is the top-left corner. The texture is re-rendered only when a widget or the
/// panel changed since the last render (render_count() counts renders), and then only in the
/// damaged rectangles: the old and new paint_bounds() of every widget whose revision moved. A
/// partial render clears those rectangles and redraws the background and every widget meeting
/// them, clipped to them, so its pixels equal a full render's exactly.
///
/// Layout and texture: widgets are laid out in panel pixels (width_px x height_px, the layout);
/// the texture is the layout drawn at render_scale() (Canvas::set_scale), so a panel covering
/// 320 screen pixels can be rendered at 320 pixels with its fonts rasterised at that size.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/pose.h"
#include "ui/theme.h"
#include "ui/widget.h"

namespace vdfx::ui {

class Panel {
 public:
  /// size_m: quad width and height in metres; fonts shared between panels.
  Panel(std::string id, int width_px, int height_px, glm::dvec2 size_m,
        std::shared_ptr<const FontSet> fonts, const Theme& theme = Theme::dark());
  ~Panel();
  Panel(const Panel&) = delete;
  Panel& operator=(const Panel&) = delete;

  const std::string& id() const { return id_; }
  int width_px() const { return width_; }    //!< layout pixels
  int height_px() const { return height_; }  //!< layout pixels
  glm::dvec2 size_m() const { return size_m_; }
  void set_size_m(glm::dvec2 size_m) { size_m_ = size_m; }
  /// Texture pixels per layout pixel (default 1). A change re-renders the whole texture.
  void set_render_scale(double scale);
  double render_scale() const { return scale_; }
  int texture_width() const;  //!< round(width_px * render_scale)
  int texture_height() const;
  const Theme& theme() const { return theme_; }
  const FontSet& fonts() const { return *fonts_; }

  // ---- widgets
  template <class W, class... Args>
  W& add(Args&&... args) {
    auto w = std::make_unique<W>(std::forward<Args>(args)...);
    W& ref = *w;
    widgets_.push_back(std::move(w));
    ++revision_;
    return ref;
  }
  const std::vector<std::unique_ptr<Widget>>& widgets() const { return widgets_; }
  Widget* find(std::string_view id) const;
  template <class W>
  W* find_as(std::string_view id) const {
    return dynamic_cast<W*>(find(id));
  }
  /// The last-added interactive widget whose hit test contains the pixel (widgets added later
  /// draw on top), or nullptr.
  Widget* widget_at(glm::dvec2 pixel) const;

  // ---- placement
  /// World pose of the quad's centre.
  const Pose& pose() const { return world_; }
  bool attached_to_hand() const { return attached_; }
  /// Locks the panel in the world at this pose.
  void set_world_pose(const Pose& world);
  /// Attaches to the hand with the given pose relative to the grip pose.
  void attach_to_hand(const Pose& grip_to_panel);
  /// Attaches to the hand keeping the panel where it is now (offset = grip^-1 * world).
  void attach_keeping_pose(const Pose& grip_world);
  /// Detaches: the panel stays at its current world pose.
  void lock_in_world() { attached_ = false; }
  /// Call once per frame with the grip pose; moves an attached panel, ignored otherwise.
  void update_hand(const Pose& grip_world);
  const Pose& hand_offset() const { return offset_; }

  // ---- mapping between panel pixels, panel-local metres and the world
  glm::dvec2 pixel_of_local(glm::dvec2 local_m) const;
  glm::dvec2 local_of_pixel(glm::dvec2 pixel) const;
  glm::dvec3 world_of_pixel(glm::dvec2 pixel) const;
  glm::dvec3 normal() const { return world_.rotate({0.0, 0.0, 1.0}); }

  // ---- rendering
  bool visible() const { return visible_; }
  void set_visible(bool v) { visible_ = v; }
  /// True when the texture is stale.
  bool dirty() const;
  /// Forces the next render (e.g. after a theme swap).
  void mark_dirty() { ++revision_; }
  /// Re-renders if dirty; returns whether it did.
  bool render_if_dirty();
  /// The texture (premultiplied RGBA8, see canvas.h), rendered first if dirty. Later renders
  /// draw into the same buffer unless a copy of this cv::Mat header is still held elsewhere:
  /// then the pixels are copied first, so a texture kept by a caller never changes.
  const cv::Mat& texture();
  int render_count() const { return render_count_; }
  /// Renders that drew the whole panel (the first, after add()/mark_dirty(), when more than
  /// kFullRenderFraction of it was damaged, or every render with partial rendering off).
  int full_render_count() const { return full_render_count_; }
  /// Whole texture-pixel rectangles the next render redraws: empty when clean, the whole texture
  /// when a full render is due. Overlapping rectangles are merged.
  std::vector<Rect> dirty_rects() const;
  /// On (the default): renders redraw only dirty_rects(). Off: every render is full.
  void set_partial_render(bool on) { partial_ = on; }
  bool partial_render() const { return partial_; }
  /// Above this fraction of the panel's area damaged, a full render is cheaper than clipping.
  static constexpr double kFullRenderFraction = 0.6;

 private:
  struct Damage {
    std::vector<Rect> rects;
    bool full = false;
  };
  Damage damage() const;
  Rect whole() const { return {0, 0, static_cast<double>(width_), static_cast<double>(height_)}; }
  Rect whole_texture() const {
    return {0, 0, static_cast<double>(texture_width()), static_cast<double>(texture_height())};
  }
  void draw_region(Canvas& canvas, const Rect* clip) const;
  std::string id_;
  int width_, height_;
  glm::dvec2 size_m_;
  double scale_ = 1.0;
  std::shared_ptr<const FontSet> fonts_;
  const Theme& theme_;
  std::vector<std::unique_ptr<Widget>> widgets_;
  Pose world_, offset_;
  bool attached_ = false;
  bool visible_ = true;
  std::uint64_t revision_ = 1;
  std::optional<std::uint64_t> rendered_revision_;        //!< revision_ at the last render
  std::vector<std::uint64_t> rendered_widget_revisions_;  //!< per widget, at the last render
  std::vector<Rect> rendered_bounds_;                     //!< per widget paint_bounds(), ditto
  std::unique_ptr<Canvas> canvas_;                        //!< holds the texture between renders
  bool partial_ = true;
  int render_count_ = 0;
  int full_render_count_ = 0;
};

}  // namespace vdfx::ui
