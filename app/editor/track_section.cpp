/// @file
/// @brief TrackSection: building the tracking buttons and showing a TrackView on them.
#include "app/editor/track_section.h"

#include <cmath>
#include <optional>
#include <string>

#include "app/editor/editor_panels.h"
#include "effects/anchor.h"

namespace vdfx::app {

void TrackSection::build(ui::Panel& p, ui::Stack& col, bool two_rows) {
  using namespace ui;
  const double gap = p.theme().gap, row_h = p.theme().row_height;
  subject_ = &p.add<Button>("track_subject", "Track subject");
  camera_ = &p.add<Button>("track_camera", "Track camera");
  correct_ = &p.add<Button>("track_correct", "Correct here");
  anchor_ = &p.add<Button>("track_anchor", "Anchor: video");
  delete_ = &p.add<Button>("track_delete", "Delete track");
  rename_ = &p.add<Button>("track_rename", "Rename track");
  Button* const order[] = {subject_, camera_, correct_, anchor_, rename_, delete_};
  if (two_rows) {
    const Rect a = col.next(row_h), b = col.next(row_h), c = col.next(row_h);
    for (int i = 0; i < 4; ++i) order[i]->set_rect(split_cols(i < 2 ? a : b, 2, i % 2, gap));
    rename_->set_rect(split_cols(c, 2, 0, gap));
    delete_->set_rect(split_cols(c, 2, 1, gap));  // under the anchor, away from Track subject
  } else {
    const Rect row = col.next(row_h);
    for (int i = 0; i < 6; ++i) order[i]->set_rect(split_cols(row, 6, i, gap));
  }
}

void TrackSection::show(const TrackView& v) {
  const std::string cancel =
      "Cancel " + std::to_string(static_cast<int>(std::lround(100.0 * v.progress))) + " %";
  const auto put = [&](ui::Button* b, const char* job, const std::string& label, bool can) {
    const bool mine = v.running == job;
    b->set_label(mine ? cancel : label);
    b->set_enabled(mine || (v.running.empty() && v.available && can));
  };
  put(subject_, "subject", "Track subject", true);
  put(camera_, "camera", "Track camera", true);
  put(correct_, "correct", v.track.empty() ? "Correct here" : "Correct " + v.track,
      !v.track.empty());
  // A track by its name alone: "track:" would take the room the name needs on the button.
  const std::optional<effects::Anchor> a = effects::parse_anchor(v.anchor);
  const bool track = a && a->kind == effects::Anchor::Kind::Track;
  anchor_->set_label("Anchor: " + (track ? a->track : v.anchor));
  anchor_->set_enabled(v.running.empty());
  delete_->set_label(v.track.empty() ? "Delete track" : "Delete " + v.track);
  delete_->set_enabled(v.running.empty() && !v.track.empty());
  rename_->set_label(v.track.empty() ? "Rename track" : "Rename " + v.track);
  rename_->set_enabled(v.running.empty() && !v.track.empty() && !v.rename.open);
}

PanelControl TrackSection::control_of(const ui::Widget* w) const {
  if (w == nullptr) return PanelControl::None;
  if (w == subject_) return PanelControl::TrackSubject;
  if (w == camera_) return PanelControl::TrackCamera;
  if (w == correct_) return PanelControl::TrackCorrect;
  if (w == anchor_) return PanelControl::TrackAnchor;
  if (w == delete_) return PanelControl::TrackDelete;
  if (w == rename_) return PanelControl::TrackRename;
  return PanelControl::None;
}

}  // namespace vdfx::app
