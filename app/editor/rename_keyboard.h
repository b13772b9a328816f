/// @file
/// @brief RenameKeyboard: the on-screen keyboard that renames the shown subject track
/// (docs/editor.md, "Tracking"): a panel of its own, shown only while a rename is open, with the
/// name being typed, the keys a track name may hold (letters, digits, - and _), Shift, Back,
/// Cancel and Rename. Keys are pressed with the pointer (the mouse on the desktop, a
/// controller's ray in a headset: a headset has no keyboard, and the recordings replay the
/// presses like any other).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/editor/track_view.h"
#include "ui/button.h"
#include "ui/panel.h"

namespace vdfx::app {

enum class PanelControl;

inline constexpr const char* kRenamePanelId = "rename";

class RenameKeyboard {
 public:
  /// The panel's layout in pixels, and its size in metres (Hands; the Desktop layout sizes it to
  /// its screen rectangle).
  static constexpr int kWidth = 1500, kHeight = 600;

  explicit RenameKeyboard(std::shared_ptr<const ui::FontSet> fonts);
  ui::Panel& panel() { return *panel_; }
  const ui::Panel& panel() const { return *panel_; }
  /// Shows the view (the panel is hidden while no rename is open).
  void show(const RenameView& view);
  /// PanelControl::RenameKey for a key (key_of says which), RenameCancel, RenameCommit, or
  /// PanelControl::None when `w` is none of the keyboard's widgets.
  PanelControl control_of(const ui::Widget* w) const;
  /// A key's text: one character, or "Shift" or "Back"; "" for any other widget.
  std::string key_of(const ui::Widget* w) const;
  /// The key that types `c` (a letter of either case, a digit, - or _), or "Shift" / "Back";
  /// null when there is none.
  const ui::Button* key(const std::string& text) const;
  const ui::Button& commit_button() const { return *commit_; }
  const ui::Button& cancel_button() const { return *cancel_; }

 private:
  std::unique_ptr<ui::Panel> panel_;
  ui::Label* title_ = nullptr;
  ui::Label* text_ = nullptr;
  std::vector<ui::Button*> keys_;  //!< one per character: keys_[k] types chars_[k]
  std::string chars_;
  ui::Button* shift_ = nullptr;
  ui::Button* back_ = nullptr;
  ui::Button* cancel_ = nullptr;
  ui::Button* commit_ = nullptr;
};

}  // namespace vdfx::app
