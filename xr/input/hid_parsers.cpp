/// @file
/// @brief Report parsers for DualShock 4, DualSense, SpaceMouse and descriptor-driven gamepads.
#include "xr/input/hid_parsers.h"

#include <algorithm>
#include <charconv>

namespace vdfx::xr {

namespace {

// Sony sticks: 0..255 with rest at 128 (0x80); mapped so the rest value is exactly 0.
double sony_axis(std::uint8_t v) {
  return std::clamp((static_cast<double>(v) - 128.0) / 127.0, -1.0, 1.0);
}
double sony_trigger(std::uint8_t v) {
  return static_cast<double>(v) / 255.0;
}

// Hat switch positions 0..7 clockwise from north; anything else is "released".
void set_hat8(GamepadState& s, int position) {
  const bool valid = position >= 0 && position <= 7;
  s.set(PadButton::DpadUp, valid && (position == 7 || position == 0 || position == 1));
  s.set(PadButton::DpadRight, valid && position >= 1 && position <= 3);
  s.set(PadButton::DpadDown, valid && position >= 3 && position <= 5);
  s.set(PadButton::DpadLeft, valid && position >= 5 && position <= 7);
}

// The Sony button block shared by DS4 (bytes 5-7) and DualSense (bytes 8-10): low nibble hat,
// then square, cross, circle, triangle; L1, R1, L2, R2, share/create, options, L3, R3; PS, pad.
GamepadState sony_common(std::span<const std::uint8_t> r, std::size_t sticks, std::size_t triggers,
                         std::size_t buttons) {
  GamepadState s;
  s.left_stick = {sony_axis(r[sticks]), -sony_axis(r[sticks + 1])};
  s.right_stick = {sony_axis(r[sticks + 2]), -sony_axis(r[sticks + 3])};
  s.left_trigger = sony_trigger(r[triggers]);
  s.right_trigger = sony_trigger(r[triggers + 1]);
  const std::uint8_t b0 = r[buttons], b1 = r[buttons + 1], b2 = r[buttons + 2];
  set_hat8(s, b0 & 0x0F);
  s.set(PadButton::West, b0 & 0x10);
  s.set(PadButton::South, b0 & 0x20);
  s.set(PadButton::East, b0 & 0x40);
  s.set(PadButton::North, b0 & 0x80);
  s.set(PadButton::L1, b1 & 0x01);
  s.set(PadButton::R1, b1 & 0x02);
  s.set(PadButton::L2, b1 & 0x04);
  s.set(PadButton::R2, b1 & 0x08);
  s.set(PadButton::Select, b1 & 0x10);
  s.set(PadButton::Start, b1 & 0x20);
  s.set(PadButton::L3, b1 & 0x40);
  s.set(PadButton::R3, b1 & 0x80);
  s.set(PadButton::Home, b2 & 0x01);
  s.set(PadButton::Touchpad, b2 & 0x02);
  return s;
}

double spacemouse_axis(const std::uint8_t* p) {
  const auto raw = static_cast<std::int16_t>(static_cast<std::uint16_t>(p[0] | (p[1] << 8)));
  return std::clamp(raw / kSpaceMouseFullScale, -1.0, 1.0);
}

double normalize_axis(std::int32_t v, const HidField& f) {
  if (f.logical_max <= f.logical_min) return 0.0;
  const double t = (static_cast<double>(v) - f.logical_min) /
                   (static_cast<double>(f.logical_max) - f.logical_min);
  return std::clamp(2.0 * t - 1.0, -1.0, 1.0);
}

double normalize_trigger(std::int32_t v, const HidField& f) {
  if (f.logical_max <= f.logical_min) return 0.0;
  return std::clamp((static_cast<double>(v) - f.logical_min) /
                        (static_cast<double>(f.logical_max) - f.logical_min),
                    0.0, 1.0);
}

constexpr std::uint16_t kGenericDesktop = 0x01;
constexpr std::uint16_t kSimulation = 0x02;
constexpr std::uint16_t kButtonPage = 0x09;

}  // namespace

std::string_view device_kind_name(HidDeviceKind kind) {
  switch (kind) {
    case HidDeviceKind::DualShock4: return "DualShock 4";
    case HidDeviceKind::DualSense: return "DualSense";
    case HidDeviceKind::SpaceMouse: return "SpaceMouse";
    case HidDeviceKind::GenericGamepad: return "generic gamepad";
    default: return "unsupported";
  }
}

HidDeviceKind known_device_kind(std::uint16_t vid, std::uint16_t pid) {
  if (vid == 0x054c) {
    if (pid == 0x05c4 || pid == 0x09cc || pid == 0x0ba0) return HidDeviceKind::DualShock4;
    if (pid == 0x0ce6 || pid == 0x0df2) return HidDeviceKind::DualSense;
  }
  if (vid == 0x046d) {  // Logitech-era 3Dconnexion devices
    for (std::uint16_t p :
         {0xc603, 0xc605, 0xc606, 0xc621, 0xc623, 0xc625, 0xc626, 0xc627, 0xc628, 0xc629, 0xc62b}) {
      if (pid == p) return HidDeviceKind::SpaceMouse;
    }
  }
  if (vid == 0x256f) return HidDeviceKind::SpaceMouse;  // 3Dconnexion's own vendor id
  return HidDeviceKind::Unknown;
}

HidDeviceKind classify_device(std::uint16_t vid, std::uint16_t pid, std::uint16_t usage_page,
                              std::uint16_t usage) {
  const HidDeviceKind known = known_device_kind(vid, pid);
  if (known != HidDeviceKind::Unknown) return known;
  if (usage_page == kGenericDesktop && (usage == 0x04 || usage == 0x05))
    return HidDeviceKind::GenericGamepad;
  return HidDeviceKind::Unknown;
}

std::optional<std::pair<std::uint16_t, std::uint16_t>> parse_device_id(std::string_view id) {
  const auto hash = id.find('#');
  if (hash != std::string_view::npos) id = id.substr(0, hash);
  if (id.size() != 9 || id[4] != ':') return std::nullopt;
  std::uint16_t v = 0, p = 0;
  auto r1 = std::from_chars(id.data(), id.data() + 4, v, 16);
  auto r2 = std::from_chars(id.data() + 5, id.data() + 9, p, 16);
  if (r1.ec != std::errc() || r1.ptr != id.data() + 4 || r2.ec != std::errc() ||
      r2.ptr != id.data() + 9) {
    return std::nullopt;
  }
  return std::make_pair(v, p);
}

std::optional<GamepadState> parse_ds4_usb_report(std::span<const std::uint8_t> r) {
  // Byte 0 report ID 0x01; 1-4 LX LY RX RY; 5-7 buttons; 8 L2; 9 R2 (then counters, IMU, touch).
  if (r.size() < 10 || r[0] != 0x01) return std::nullopt;
  return sony_common(r, 1, 8, 5);
}

std::optional<GamepadState> parse_dualsense_usb_report(std::span<const std::uint8_t> r) {
  // Byte 0 report ID 0x01; 1-4 LX LY RX RY; 5 L2; 6 R2; 7 sequence; 8-10 buttons.
  if (r.size() < 11 || r[0] != 0x01) return std::nullopt;
  return sony_common(r, 1, 5, 8);
}

bool apply_spacemouse_report(SpaceMouseState& s, std::span<const std::uint8_t> r) {
  if (r.empty()) return false;
  switch (r[0]) {
    case 1:
      if (r.size() < 7) return false;
      for (int i = 0; i < 3; ++i) s.translation[i] = spacemouse_axis(&r[1 + 2 * i]);
      if (r.size() >= 13) {  // newer devices: all six axes in report 1
        for (int i = 0; i < 3; ++i) s.rotation[i] = spacemouse_axis(&r[7 + 2 * i]);
      }
      return true;
    case 2:
      if (r.size() < 7) return false;
      for (int i = 0; i < 3; ++i) s.rotation[i] = spacemouse_axis(&r[1 + 2 * i]);
      return true;
    case 3: {
      std::uint32_t b = 0;
      for (std::size_t i = 1; i < r.size() && i <= 4; ++i)
        b |= static_cast<std::uint32_t>(r[i]) << (8 * (i - 1));
      s.buttons = b;
      return true;
    }
    default: return false;
  }
}

const std::vector<PadButton>& generic_button_order() {
  static const std::vector<PadButton> order = {
      PadButton::South, PadButton::East, PadButton::West, PadButton::North,  PadButton::L1,
      PadButton::R1,    PadButton::L2,   PadButton::R2,   PadButton::Select, PadButton::Start,
      PadButton::L3,    PadButton::R3,   PadButton::Home};
  return order;
}

GenericGamepadDecoder::GenericGamepadDecoder(HidReportDescriptor d) : descriptor_(std::move(d)) {
  auto has = [&](std::uint16_t usage) {
    return std::any_of(descriptor_.inputs.begin(), descriptor_.inputs.end(),
                       [&](const HidField& f) {
                         return f.usage_page == kGenericDesktop && !f.is_array && f.usage == usage;
                       });
  };
  // Rx/Ry present: they are the right stick and Z/Rz the analog triggers (Xbox-style HID);
  // otherwise Z/Rz is the right stick, the common layout of DirectInput pads.
  const bool rx_ry_stick = has(0x33) && has(0x34);
  for (const HidField& f : descriptor_.inputs) {
    std::optional<Role> role;
    if (f.usage_page == kGenericDesktop && !f.is_array) {
      switch (f.usage) {
        case 0x30: role = Role::LeftX; break;
        case 0x31: role = Role::LeftY; break;
        case 0x32: role = rx_ry_stick ? Role::LeftTrigger : Role::RightX; break;
        case 0x35: role = rx_ry_stick ? Role::RightTrigger : Role::RightY; break;
        case 0x33: role = Role::RightX; break;
        case 0x34: role = Role::RightY; break;
        case 0x39: role = Role::Hat; break;
        default: break;
      }
    } else if (f.usage_page == kSimulation && !f.is_array) {
      if (f.usage == 0xC5) role = Role::LeftTrigger;   // Brake
      if (f.usage == 0xC4) role = Role::RightTrigger;  // Accelerator
    } else if (f.usage_page == kButtonPage) {
      role = Role::Button;
    }
    if (role) bindings_.push_back({f, *role});
  }
}

bool GenericGamepadDecoder::apply(GamepadState& s, std::span<const std::uint8_t> report) const {
  bool any = false;
  bool cleared_array_buttons = false;
  const auto& order = generic_button_order();
  for (const Binding& b : bindings_) {
    std::int32_t v = 0;
    if (!read_field(b.field, descriptor_.uses_report_ids, report, v)) continue;
    any = true;
    switch (b.role) {
      case Role::LeftX: s.left_stick[0] = normalize_axis(v, b.field); break;
      case Role::LeftY: s.left_stick[1] = -normalize_axis(v, b.field); break;  // HID Y grows down
      case Role::RightX: s.right_stick[0] = normalize_axis(v, b.field); break;
      case Role::RightY: s.right_stick[1] = -normalize_axis(v, b.field); break;
      case Role::LeftTrigger: s.left_trigger = normalize_trigger(v, b.field); break;
      case Role::RightTrigger: s.right_trigger = normalize_trigger(v, b.field); break;
      case Role::Hat: {
        // In 64 bits: a descriptor's range can span all of int32 (found by fuzzing: the
        // difference overflowed).
        const std::int64_t span = std::int64_t{b.field.logical_max} - b.field.logical_min + 1;
        std::int64_t pos = std::int64_t{v} - b.field.logical_min;
        if (pos < 0 || pos >= span)
          pos = -1;  // the null state: released
        else if (span == 4)
          pos *= 2;  // 4-way hats: N, E, S, W
        set_hat8(s, pos > 7 ? -1 : static_cast<int>(pos));
        break;
      }
      case Role::Button: {
        if (b.field.is_array) {
          if (!cleared_array_buttons) {  // an array lists the pressed buttons: start from none
            for (PadButton pb : order) s.set(pb, false);
            cleared_array_buttons = true;
          }
          if (v < b.field.logical_min || v > b.field.logical_max) break;
          const std::int64_t usage = b.field.usage + (std::int64_t{v} - b.field.logical_min);
          if (usage >= 1 && usage <= static_cast<std::int64_t>(order.size()))
            s.set(order[static_cast<std::size_t>(usage - 1)], true);
        } else if (b.field.usage >= 1 && b.field.usage <= order.size()) {
          s.set(order[b.field.usage - 1], v != 0);
        }
        break;
      }
    }
  }
  return any;
}

HidReportParser::HidReportParser(HidDeviceKind kind, std::span<const std::uint8_t> descriptor)
    : kind_(kind) {
  if (kind == HidDeviceKind::GenericGamepad) {
    generic_.emplace(parse_report_descriptor(descriptor));
  }
}

bool HidReportParser::apply(std::span<const std::uint8_t> report) {
  switch (kind_) {
    case HidDeviceKind::DualShock4: {
      auto s = parse_ds4_usb_report(report);
      if (s) gamepad_ = *s;
      return s.has_value();
    }
    case HidDeviceKind::DualSense: {
      auto s = parse_dualsense_usb_report(report);
      if (s) gamepad_ = *s;
      return s.has_value();
    }
    case HidDeviceKind::SpaceMouse: return apply_spacemouse_report(spacemouse_, report);
    case HidDeviceKind::GenericGamepad: return generic_->apply(gamepad_, report);
    default: return false;
  }
}

void HidReportParser::reset() {
  gamepad_ = {};
  spacemouse_ = {};
}

}  // namespace vdfx::xr
