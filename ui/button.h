/// @file
/// @brief Button (click), Toggle (on/off) and Label (static text).
#pragma once

#include <string>

#include "ui/canvas.h"
#include "ui/colour.h"
#include "ui/widget.h"

namespace vdfx::ui {

/// Shapes drawn instead of glyphs where fonts lack a clear symbol.
enum class Icon { None, Play, Pause };

class Button : public Widget {
 public:
  Button(std::string id, std::string label, Icon icon = Icon::None)
      : Widget(std::move(id)), label_(std::move(label)), icon_(icon) {}
  const std::string& label() const { return label_; }
  void set_label(std::string s) { set(label_, s); }
  Icon icon() const { return icon_; }
  void set_icon(Icon i) { set(icon_, i); }
  bool focusable() const override { return true; }
  void draw(DrawContext& ctx) const override;

 private:
  std::string label_;
  Icon icon_;
};

class Toggle : public Widget {
 public:
  Toggle(std::string id, std::string label, bool on = false)
      : Widget(std::move(id)), label_(std::move(label)), on_(on) {}
  bool on() const { return on_; }
  void set_on(bool v) { set(on_, v); }
  glm::dvec2 value() const override { return {on_ ? 1.0 : 0.0, 0.0}; }
  bool focusable() const override { return true; }
  void click(glm::dvec2) override { set_on(!on_); }
  void draw(DrawContext& ctx) const override;

 private:
  std::string label_;
  bool on_;
};

class Label : public Widget {
 public:
  enum class Role { Title, Body, Small };
  Label(std::string id, std::string text, Role role = Role::Body, Align align = Align::Left,
        bool muted = false)
      : Widget(std::move(id)), text_(std::move(text)), role_(role), align_(align), muted_(muted) {}
  const std::string& text() const { return text_; }
  void set_text(std::string s) { set(text_, s); }
  bool interactive() const override { return false; }
  void draw(DrawContext& ctx) const override;

 private:
  std::string text_;
  Role role_;
  Align align_;
  bool muted_;
};

}  // namespace vdfx::ui
