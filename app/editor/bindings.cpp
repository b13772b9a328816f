/// @file
/// @brief The help text of the editor's controls, generated from the binding table.
#include "app/editor/bindings.h"

#include <sstream>
#include <vector>

#include "xr/input/input_backend.h"

namespace vdfx::app {

namespace {

/// The control as OpenXR's simple and touch profiles name it ("right a", "left squeeze").
std::string control_name(xr::Hand hand, xr::Control c) {
  const bool left = hand == xr::Hand::Left;
  const std::string side = left ? "left " : "right ";
  switch (c) {
    case xr::Control::Trigger: return side + "trigger";
    case xr::Control::Squeeze: return side + "squeeze";
    case xr::Control::Primary: return side + (left ? "x" : "a");
    case xr::Control::Secondary: return side + (left ? "y" : "b");
    case xr::Control::Menu: return side + "menu";
    case xr::Control::StickClick: return side + "thumbstick click";
    case xr::Control::StickUp:
    case xr::Control::StickDown:
    case xr::Control::StickLeft:
    case xr::Control::StickRight: return side + "thumbstick";
  }
  return side;
}

/// "right squeeze [G]": the control and what presses it in the sim (the whole stick for a stick
/// direction); `pointing`: only what presses it through the cursor (a panel's pointer use).
std::string control_column(xr::Hand hand, xr::Control c, bool pointing = false) {
  const bool stick = c == xr::Control::StickUp || c == xr::Control::StickDown ||
                     c == xr::Control::StickLeft || c == xr::Control::StickRight;
  std::vector<std::string> inputs;
  for (const xr::Control each :
       stick ? std::vector<xr::Control>{xr::Control::StickUp, xr::Control::StickDown,
                                        xr::Control::StickLeft, xr::Control::StickRight}
             : std::vector<xr::Control>{c})
    for (std::string& s : xr::sim_inputs_of(hand, each, xr::SimConfig{}, pointing))
      inputs.push_back(std::move(s));
  std::string out = control_name(hand, c);
  for (std::size_t i = 0; i < inputs.size(); ++i) out += (i ? ", " : " [") + inputs[i];
  return inputs.empty() ? out : out + "]";
}

/// Two columns, the second word-wrapped; a control repeated on the next row is not named again.
class Table {
 public:
  void row(const std::string& control, std::string_view does) {
    std::string left = control == last_ ? std::string() : control;
    last_ = control;
    if (left.size() + 2 > kColumn) {  // a long control column gets a line of its own
      out_ << "  " << left << "\n";
      left.clear();
    }
    left.resize(kColumn - 2, ' ');
    std::string line = "  " + left;
    std::istringstream words{std::string(does)};
    std::string word;
    bool first = true;
    while (words >> word) {
      if (!first && line.size() + 1 + word.size() > kWidth) {
        out_ << line << "\n";
        line = std::string(kColumn, ' ');
        first = true;
      }
      line += (first ? "" : " ") + word;
      first = false;
    }
    out_ << line << "\n";
  }
  std::string str() const { return out_.str(); }

 private:
  static constexpr std::size_t kColumn = 46, kWidth = 100;
  std::ostringstream out_;
  std::string last_;
};

}  // namespace

std::string bindings_help_text() {
  Table t;
  for (const Binding& b : kBindings) t.row(control_column(b.hand, b.control), b.does);
  for (const PointerUse& u : kPointerUses)
    t.row(control_column(u.hand, u.control, /*pointing=*/true), u.does);
  for (const DesktopUse& d : kDesktopUses) t.row(std::string(d.input), d.does);
  return t.str();
}

}  // namespace vdfx::app
