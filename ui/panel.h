/// @file
/// @brief Panel: widgets on a W x H pixel surface shown as a w x h metre quad in the world.
///
/// Panel space: the quad is centred on pose().position, its local +x is right, +y up and it
/// faces its local +z (like an OpenXR quad layer): rays must come from the +z side to hit it.
/// Pixel (0, 0) is the top-left corner. The texture is re-rendered only when a widget or the
/// panel changed since the last render (render_count() counts renders).
#pragma once

#include "ui/font.h"
#include "ui/pose.h"
#include "ui/theme.h"
#include "ui/widget.h"

#include <opencv2/core.hpp>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace vdfx::ui {

class Panel {
 public:
  /// size_m: quad width and height in metres; fonts shared between panels.
  Panel(std::string id, int width_px, int height_px, glm::dvec2 size_m,
        std::shared_ptr<const FontSet> fonts, const Theme& theme = Theme::dark());

  const std::string& id() const { return id_; }
  int width_px() const { return width_; }
  int height_px() const { return height_; }
  glm::dvec2 size_m() const { return size_m_; }
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
  W* find_as(std::string_view id) const { return dynamic_cast<W*>(find(id)); }
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
  /// The texture (premultiplied RGBA8, see canvas.h), rendered first if dirty.
  const cv::Mat& texture();
  int render_count() const { return render_count_; }

 private:
  std::uint64_t state_revision() const;
  std::string id_;
  int width_, height_;
  glm::dvec2 size_m_;
  std::shared_ptr<const FontSet> fonts_;
  const Theme& theme_;
  std::vector<std::unique_ptr<Widget>> widgets_;
  Pose world_, offset_;
  bool attached_ = false;
  bool visible_ = true;
  std::uint64_t revision_ = 1;
  std::optional<std::uint64_t> rendered_revision_;
  cv::Mat texture_;
  int render_count_ = 0;
};

}  // namespace vdfx::ui
