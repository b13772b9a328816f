/// @file
/// @brief TimelineStrip.
#include "ui/timeline_strip.h"

#include <algorithm>
#include <cmath>

#include "ui/canvas.h"
#include "ui/font.h"
#include "ui/theme.h"

namespace vdfx::ui {

namespace {
constexpr double kMarkerBand = 56.0;  // keyframe diamonds below the thumbnails
constexpr double kLabelBand = 48.0;   // frame numbers below the markers
constexpr double kSide = 28.0;        // horizontal inset so end markers are not cut

cv::Mat centre_crop(const cv::Mat& m, double aspect) {
  if (m.empty()) return m;
  const double a = static_cast<double>(m.cols) / m.rows;
  if (a > aspect) {
    const int w = std::max(1, static_cast<int>(std::lround(m.rows * aspect)));
    return m(cv::Rect((m.cols - w) / 2, 0, w, m.rows));
  }
  const int h = std::max(1, static_cast<int>(std::lround(m.cols / aspect)));
  return m(cv::Rect(0, (m.rows - h) / 2, m.cols, h));
}
}  // namespace

TimelineStrip::TimelineStrip(std::string id, int frame_count)
    : Widget(std::move(id)), frame_count_(std::max(1, frame_count)) {}

void TimelineStrip::set_frame_count(int n) {
  set(frame_count_, std::max(1, n));
  set_playhead(playhead_);
}

void TimelineStrip::set_playhead(int frame) {
  const int f = std::clamp(frame, 0, frame_count_ - 1);
  if (f == playhead_) return;
  const int old = playhead_;
  playhead_ = f;
  if (!label_font_) {
    touch();
    return;
  }
  touch(playhead_area(old));
  touch(playhead_area(f));
}

Rect TimelineStrip::frame_label_rect(int frame) const {
  const std::string ftxt = "frame " + std::to_string(frame);
  const double fw = label_font_->measure(ftxt, label_size_) + 8;
  const Rect lab{rect().x, track().bottom() + kMarkerBand, rect().w, kLabelBand};
  const double fx =
      std::clamp(x_of(frame) - 0.5 * fw, lab.x + kSide + 60, lab.right() - kSide - 110 - fw);
  return {fx, lab.y, fw, lab.h};
}

Rect TimelineStrip::playhead_area(int frame) const {
  // A column over the line, its handle and the larger diamond of a keyframe at the playhead
  // (20 px + outline), plus the label; a few pixels more for anti-aliasing and glyph overhang.
  constexpr double kHalf = 28.0, kAa = 4.0;
  const Rect r = rect();
  const double px = x_of(frame);
  const Rect col{px - kHalf, r.y - kAa, 2 * kHalf, r.h + 2 * kAa};
  const Rect lab = frame_label_rect(frame).inset(-kAa - 2.0);
  const double x0 = std::min(col.x, lab.x), y0 = std::min(col.y, lab.y);
  return {x0, y0, std::max(col.right(), lab.right()) - x0,
          std::max(col.bottom(), lab.bottom()) - y0};
}

void TimelineStrip::set_thumbnails(std::vector<cv::Mat> images) {
  thumbs_ = std::move(images);
  scaled_.assign(thumbs_.size(), ScaledImage{});
  touch();
}

void TimelineStrip::set_keyframes(std::vector<int> frames) {
  set(keyframes_, frames);
}
void TimelineStrip::set_highlighted(std::vector<int> frames) {
  set(highlighted_, frames);
}

void TimelineStrip::set_track_band(TrackBand band) {
  set(band_, band);
}

void TimelineStrip::draw_track_band(Canvas& c, const Theme& t) const {
  if (band_.first < 0 || band_.last < band_.first) return;
  constexpr double kBand = 16.0;
  const Rect tr = track();
  const double half = frame_count_ > 1 ? 0.5 * tr.w / (frame_count_ - 1.0) : 0.5 * tr.w;
  const double y = tr.bottom() - kBand - 4.0;
  const double x0 = std::max(tr.x, x_of(band_.first) - half);
  const double x1 = std::min(tr.right(), x_of(band_.last) + half);
  c.fill_rounded_rect({x0, y, x1 - x0, kBand}, 4.0, t.accent);
  // Lost frames in red, at least a few pixels wide so one frame of a long clip still shows.
  const double w = std::max(2.0 * half, 6.0);
  for (const int f : band_.held) c.fill_rect({x_of(f) - 0.5 * w, y, w, kBand}, Rgba::hex(0xe0483c));
}

Rect TimelineStrip::track() const {
  const Rect r = rect();
  return {r.x + kSide, r.y, r.w - 2 * kSide, r.h - kMarkerBand - kLabelBand};
}

int TimelineStrip::frame_at(double x) const {
  const Rect t = track();
  if (frame_count_ <= 1) return 0;
  const double f = (x - t.x) / t.w * (frame_count_ - 1);
  return std::clamp(static_cast<int>(std::lround(f)), 0, frame_count_ - 1);
}

double TimelineStrip::x_of(int frame) const {
  const Rect t = track();
  return frame_count_ <= 1 ? t.x : t.x + t.w * frame / (frame_count_ - 1.0);
}

void TimelineStrip::step(glm::ivec2 d) {
  if (d.x != 0) set_playhead(playhead_ + d.x);
}

void TimelineStrip::thumbstick(glm::dvec2 stick, double dt) {
  if (stick.x == 0.0) {
    pending_ = 0.0;
    return;
  }
  pending_ += stick.x * kStickFramesPerSecond * dt;
  const double whole = std::trunc(pending_);
  pending_ -= whole;
  set_playhead(playhead_ + static_cast<int>(whole));
}

void TimelineStrip::draw(DrawContext& ctx) const {
  const Theme& t = ctx.theme;
  Canvas& c = ctx.canvas;
  const Rect tr = track();
  c.fill_rounded_rect(tr, 8.0, t.surface_pressed);
  if (!thumbs_.empty()) {
    const double cell = tr.w / static_cast<double>(thumbs_.size());
    c.push_clip(tr);
    for (size_t i = 0; i < thumbs_.size(); ++i) {
      const Rect cr{tr.x + cell * i, tr.y, cell, tr.h};
      const Rect inner = cr.inset(2.0);
      c.image(scaled_[i].get(centre_crop(thumbs_[i], inner.w / inner.h), inner, ChannelOrder::Bgr,
                             c.scale()),
              inner, ChannelOrder::Rgb);
    }
    c.pop_clip();
  }
  draw_track_band(c, t);
  if (focused()) c.stroke_rounded_rect(tr.inset(-6.0), 12.0, t.focus_width, t.accent);
  // Keyframe diamonds on a rail below the thumbnails, over the playhead line.
  const double my = tr.bottom() + 0.5 * kMarkerBand;
  const double px = x_of(playhead_);
  c.line({tr.x, my}, {tr.right(), my}, 3.0, t.track);
  c.line({px, tr.y}, {px, tr.bottom() + kMarkerBand}, pressed() ? 6.0 : 4.0, t.playhead);
  for (int f : keyframes_) {
    const bool hi = f == playhead_ ||
                    std::find(highlighted_.begin(), highlighted_.end(), f) != highlighted_.end();
    const double s = hi ? 20.0 : 14.0;
    const glm::dvec2 ctr{x_of(f), my};
    const glm::dvec2 d[4] = {ctr + glm::dvec2(0, -s), ctr + glm::dvec2(s, 0),
                             ctr + glm::dvec2(0, s), ctr + glm::dvec2(-s, 0)};
    c.fill_convex(d, hi ? t.keyframe_highlight : t.keyframe);
    if (hi) c.polyline(d, 3.0, t.text, true);
  }
  // Frame numbers: start, end and the playhead.
  const Rect lab{rect().x, tr.bottom() + kMarkerBand, rect().w, kLabelBand};
  c.text(*ctx.fonts.regular, t.font_small, "0", {lab.x + kSide - 10, lab.y, 200, lab.h},
         Align::Left, t.text_muted);
  c.text(*ctx.fonts.regular, t.font_small, std::to_string(frame_count_ - 1),
         {lab.right() - kSide - 190, lab.y, 200, lab.h}, Align::Right, t.text_muted);
  // Playhead: a line over the thumbnails with a handle on top.
  const glm::dvec2 head[3] = {{px - 16, tr.y}, {px + 16, tr.y}, {px, tr.y + 22}};
  c.fill_convex(head, t.playhead);
  label_font_ = ctx.fonts.regular.get();
  label_size_ = t.font_small;
  c.text(*ctx.fonts.regular, t.font_small, "frame " + std::to_string(playhead_),
         frame_label_rect(playhead_), Align::Centre, t.text);
}

}  // namespace vdfx::ui
