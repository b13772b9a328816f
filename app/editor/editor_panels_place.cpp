/// @file
/// @brief EditorPanels: where the panels are (their anchors, placed once a frame), which of them
/// each hand's ray reaches, and finding one by id.
#include "app/editor/editor_panels.h"

namespace vdfx::app {

xr::Pose anchor_pose(Anchor anchor, const xr::InputState& input) {
  switch (anchor) {
    case Anchor::LeftHand: return input.left.grip;
    case Anchor::RightHand: return input.right.grip;
    case Anchor::Head: return input.head;
    case Anchor::World: break;
  }
  return {};
}

std::vector<ui::Panel*> EditorPanels::all() {
  // Drawn in this order: the track's marker belongs to the scene, under the panels.
  std::vector<ui::Panel*> out{&marker_->panel(), effect_.get(), timeline_.get()};
  if (views_) out.push_back(views_.get());
  if (hud_) out.push_back(hud_.get());
  out.push_back(&keyboard_->panel());  // over the others
  return out;
}

ui::Panel* EditorPanels::panel(std::string_view id) {
  for (ui::Panel* p : all())
    if (p->id() == id) return p;
  return nullptr;
}

const ui::Panel* EditorPanels::panel(std::string_view id) const {
  return const_cast<EditorPanels*>(this)->panel(id);
}

const PanelPlacement& EditorPanels::placement(std::string_view id) const {
  if (id == kTimelinePanelId) return timeline_place_;
  if (id == kViewsPanelId) return views_place_;
  if (id == kHudPanelId) return hud_place_;
  if (id == kRenamePanelId) return keyboard_place_;
  return effect_place_;
}

void EditorPanels::place(const xr::InputState& input) {
  const auto put = [&](ui::Panel* p, const PanelPlacement& place) {
    if (p && place.anchor != Anchor::World)
      p->set_world_pose(anchor_pose(place.anchor, input) * place.offset);
  };
  put(effect_.get(), effect_place_);
  put(timeline_.get(), timeline_place_);
  put(views_.get(), views_place_);
  put(hud_.get(), hud_place_);
  if (layout_ == PanelLayout::Hands) {
    if (!keyboard_->panel().visible()) {
      keyboard_place_ = {Anchor::Head, keyboard_offset_};  // for the next opening
    } else if (keyboard_place_.anchor == Anchor::Head) {
      keyboard_place_ = {Anchor::World, anchor_pose(Anchor::Head, input) * keyboard_offset_};
      keyboard_->panel().set_world_pose(keyboard_place_.offset);
    }
  }
  put(&keyboard_->panel(), keyboard_place_);
  marker_->set_head(input.head);
}

std::vector<ui::Panel*> EditorPanels::reachable_by(xr::Hand hand) {
  // On the desktop the mouse is the right hand's ray; the sim's left hand only has buttons.
  if (layout_ == PanelLayout::Desktop && hand == xr::Hand::Left) return {};
  const Anchor own = hand == xr::Hand::Left ? Anchor::LeftHand : Anchor::RightHand;
  std::vector<ui::Panel*> out;
  if (effect_place_.anchor != own) out.push_back(effect_.get());
  if (timeline_place_.anchor != own) out.push_back(timeline_.get());
  if (views_) out.push_back(views_.get());  // the HUD takes no input
  out.push_back(&keyboard_->panel());       // either hand (hidden: no input)
  return out;
}

}  // namespace vdfx::app
