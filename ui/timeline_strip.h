/// @file
/// @brief TimelineStrip: frame thumbnails, keyframe markers and a playhead that scrubs by drag.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "ui/canvas.h"
#include "ui/widget.h"

namespace vdfx::ui {

class TimelineStrip : public Widget {
 public:
  TimelineStrip(std::string id, int frame_count);
  int frame_count() const { return frame_count_; }
  void set_frame_count(int n);
  int playhead() const { return playhead_; }
  /// Moves the playhead. Only what the playhead draws is damaged (its line and handle, a
  /// keyframe diamond under it, its frame label, at the old and the new frame), so playback
  /// redraws two narrow columns rather than the strip.
  void set_playhead(int frame);
  /// Thumbnails in time order, shown side by side across the strip (BGR or BGRA cv::Mat,
  /// centre-cropped to their cell). Replacing them always re-renders.
  void set_thumbnails(std::vector<cv::Mat> images);
  /// Frames that hold keyframes (of the selected effect).
  void set_keyframes(std::vector<int> frames);
  const std::vector<int>& keyframes() const { return keyframes_; }
  /// Keyframes drawn highlighted (selected); keyframes at the playhead are highlighted too.
  void set_highlighted(std::vector<int> frames);
  /// A subject track's span, drawn as a band along the thumbnails' bottom edge, with the frames
  /// where the subject was lost (its direction held) marked on it.
  struct TrackBand {
    int first = -1, last = -1;  //!< -1: no track
    std::vector<int> held;
    bool operator==(const TrackBand&) const = default;
  };
  void set_track_band(TrackBand band);
  const TrackBand& track_band() const { return band_; }

  /// Frame under a panel x (nearest), clamped to [0, frame_count - 1].
  int frame_at(double x) const;
  /// Panel x of a frame's centre.
  double x_of(int frame) const;

  glm::dvec2 value() const override { return {static_cast<double>(playhead_), 0.0}; }
  bool focusable() const override { return true; }
  bool steppable() const override { return true; }
  bool draggable() const override { return true; }
  void drag_to(glm::dvec2 p) override { set_playhead(frame_at(p.x)); }
  /// A push of x steps one frame; held on, frames pass at up to kStickFramesPerSecond.
  void step(glm::ivec2 direction) override;
  void thumbstick(glm::dvec2 stick, double dt) override;
  void draw(DrawContext& ctx) const override;

  static constexpr double kStickFramesPerSecond = 30.0;

 private:
  Rect track() const;
  /// The pixels the playhead draws at a frame (see set_playhead), or an empty rect when that
  /// cannot be known yet (nothing drawn so far).
  Rect playhead_area(int frame) const;
  /// The playhead's frame label box at a frame (needs the font of the last draw).
  Rect frame_label_rect(int frame) const;
  void draw_track_band(Canvas& c, const Theme& t) const;
  int frame_count_;
  int playhead_ = 0;
  std::vector<cv::Mat> thumbs_;
  mutable std::vector<ScaledImage> scaled_;  //!< thumbs_ scaled to their cells, per thumbnail
  std::vector<int> keyframes_, highlighted_;
  TrackBand band_;
  double pending_ = 0.0;
  //! The label font and size of the last draw, so a playhead move can bound its new label.
  mutable const Font* label_font_ = nullptr;
  mutable int label_size_ = 0;
};

}  // namespace vdfx::ui
