/// @file
/// @brief RenameKeyboard: the rename panel's keys and what they show.
#include "app/editor/rename_keyboard.h"

#include <cctype>

#include "app/editor/editor_panels.h"

namespace vdfx::app {

namespace {

/// Rows of keys, as a keyboard has them (lower case shown; Shift shows upper case).
constexpr const char* kRows[] = {"1234567890-", "qwertyuiop_", "asdfghjkl", "zxcvbnm"};
constexpr int kColumns = 11;
constexpr double kWidthM = 0.5;

std::string shown(char c, bool upper) {
  return std::string(1, upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c);
}

}  // namespace

RenameKeyboard::RenameKeyboard(std::shared_ptr<const ui::FontSet> fonts)
    : panel_(std::make_unique<ui::Panel>(kRenamePanelId, kWidth, kHeight,
                                         glm::dvec2(kWidthM, kWidthM * kHeight / kWidth),
                                         std::move(fonts))) {
  using namespace ui;
  Panel& p = *panel_;
  const Theme& t = p.theme();
  Stack col(Rect{0, 0, kWidth, kHeight}.inset(32.0), t.gap);
  // Columns `first` to `first + n - 1` of a row of kColumns.
  const auto cells = [&](const Rect& row, int first, int n) {
    const Rect a = split_cols(row, kColumns, first, t.gap);
    const Rect b = split_cols(row, kColumns, first + n - 1, t.gap);
    return Rect{a.x, a.y, b.x + b.w - a.x, a.h};
  };
  const Rect head = col.next(t.row_height);
  title_ = &p.add<Label>("rename_title", "Rename track", Label::Role::Body);
  title_->set_rect(cells(head, 0, 4));
  text_ = &p.add<Label>("rename_text", "", Label::Role::Title);
  text_->set_rect(cells(head, 4, 3));
  cancel_ = &p.add<Button>("rename_cancel", "Cancel");
  cancel_->set_rect(cells(head, 7, 2));
  commit_ = &p.add<Button>("rename_commit", "Rename");
  commit_->set_rect(cells(head, 9, 2));
  const double key_h = (col.rest().h - 3.0 * t.gap) / 4.0;
  for (int r = 0; r < 4; ++r) {
    const Rect row = col.next(key_h);
    const int first = r == 3 ? 2 : 0;  // Shift before "z", two keys wide
    const std::string chars = kRows[r];
    for (std::size_t i = 0; i < chars.size(); ++i) {
      Button& b =
          p.add<Button>("rename_key_" + std::to_string(keys_.size()), shown(chars[i], false));
      b.set_rect(split_cols(row, kColumns, first + static_cast<int>(i), t.gap));
      keys_.push_back(&b);
      chars_ += chars[i];
    }
    if (r == 2) {  // after "l"
      back_ = &p.add<Button>("rename_back", "Back");
      back_->set_rect(cells(row, 9, 2));
    }
    if (r == 3) {
      shift_ = &p.add<Button>("rename_shift", "Shift");
      shift_->set_rect(cells(row, 0, 2));
    }
  }
  panel_->set_visible(false);
}

void RenameKeyboard::show(const RenameView& v) {
  panel_->set_visible(v.open);
  if (!v.open) return;
  title_->set_text("Rename " + v.from + " to");
  text_->set_text(v.text + "_");
  for (std::size_t k = 0; k < keys_.size(); ++k) keys_[k]->set_label(shown(chars_[k], v.upper));
  shift_->set_label(v.upper ? "SHIFT" : "Shift");
  commit_->set_enabled(v.can_commit);
}

PanelControl RenameKeyboard::control_of(const ui::Widget* w) const {
  if (w == nullptr) return PanelControl::None;
  if (w == cancel_) return PanelControl::RenameCancel;
  if (w == commit_) return PanelControl::RenameCommit;
  return key_of(w).empty() ? PanelControl::None : PanelControl::RenameKey;
}

std::string RenameKeyboard::key_of(const ui::Widget* w) const {
  if (w == shift_) return "Shift";
  if (w == back_) return "Back";
  for (std::size_t k = 0; k < keys_.size(); ++k)
    if (keys_[k] == w) return std::string(1, chars_[k]);
  return {};
}

const ui::Button* RenameKeyboard::key(const std::string& text) const {
  if (text == "Shift") return shift_;
  if (text == "Back") return back_;
  if (text.size() != 1) return nullptr;
  const std::size_t k =
      chars_.find(static_cast<char>(std::tolower(static_cast<unsigned char>(text[0]))));
  return k == std::string::npos ? nullptr : keys_[k];
}

}  // namespace vdfx::app
