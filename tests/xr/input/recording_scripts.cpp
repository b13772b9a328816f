/// @file
/// @brief Scripted sessions behind recordings/ (see recordings/README.md for what each does).
#include "recording_scripts.h"

#include <cmath>

#include "hid_test_data.h"
#include "io/recording.h"
#include "xr/input/hid_mapping.h"
#include "xr/input/input_backend.h"
#include "xr/input/input_state_io.h"

namespace vdfx::xr::scripts {

namespace {

io::RecordingHeader header(const std::string& note) {
  return {"sim", std::nullopt, note};
}

void sim_look_and_place(const std::filesystem::path& file) {
  SimConfig cfg;
  cfg.hfov_deg = 90.0;  // the view this session was first recorded in (recordings/README.md)
  cfg.look = LookMode::Mouselook;  // recorded before drag became the default
  cfg.look_deg_per_px = 0.2;       // and before the drag followed the cursor
  auto rec = create_recording_backend(create_sim_backend(cfg), file,
                                      header("sim: look right 90 deg, up 10 deg, move the cursor, "
                                             "pull the trigger twice, push the left stick"));
  double mx = 640, my = 360;
  for (int f = 0; f < 180; ++f) {
    if (f == 10) rec->push_event(MouseButtonEvent{MouseButton::Right, true});
    if (f >= 11 && f <= 40) rec->push_event(MouseMoveEvent{mx += 15, my});
    if (f == 41) rec->push_event(MouseButtonEvent{MouseButton::Right, false});
    if (f == 50) rec->push_event(MouseButtonEvent{MouseButton::Right, true});
    if (f >= 51 && f <= 60) rec->push_event(MouseMoveEvent{mx, my -= 5});
    if (f == 61) rec->push_event(MouseButtonEvent{MouseButton::Right, false});
    if (f >= 70 && f < 90) {  // glide to (960, 200)
      const double a = (f - 69) / 20.0;
      rec->push_event(MouseMoveEvent{1090 + (960 - 1090) * a, 310 + (200 - 310) * a});
    }
    if (f == 100) rec->push_event(KeyEvent{Key::Space, true});
    if (f == 110) rec->push_event(KeyEvent{Key::Space, false});
    if (f == 120) rec->push_event(MouseButtonEvent{MouseButton::Left, true});
    if (f == 130) rec->push_event(MouseButtonEvent{MouseButton::Left, false});
    if (f == 140) rec->push_event(KeyEvent{Key::W, true});
    if (f == 170) rec->push_event(KeyEvent{Key::W, false});
    rec->poll(f * kFrameNs);
  }
}

void sim_buttons_tour(const std::filesystem::path& file) {
  auto rec = create_recording_backend(create_sim_backend({}), file,
                                      header("sim: every key binding in turn, 6 frames each"));
  const auto& tour = buttons_tour();
  const int frames = static_cast<int>(tour.size()) * 9 + 3;
  for (int f = 0; f < frames; ++f) {
    const int k = f / 9, phase = f % 9;
    if (k < static_cast<int>(tour.size())) {
      if (phase == 3) rec->push_event(KeyEvent{static_cast<Key>(tour[k].key), true});
    }
    if (phase == 0 && k > 0) rec->push_event(KeyEvent{static_cast<Key>(tour[k - 1].key), false});
    rec->poll(f * kFrameNs);
  }
}

// A HID stream: reports every 20 ms from `report(t)`, plus a sample line every 100 ms holding
// what the mapper makes of them (what a replay must reproduce).
void hid_stream(const std::filesystem::path& file, const std::string& note,
                const std::string& device, const std::vector<std::uint8_t>& descriptor,
                double seconds,
                const std::function<std::vector<std::vector<std::uint8_t>>(double)>& reports) {
  io::RecordingWriter w(file, header(note));
  HidInputMapper mapper;
  if (!descriptor.empty()) {
    w.write(io::RecordedHid{0, device, descriptor, true});
    mapper.on_descriptor(device, descriptor);
  }
  const std::int64_t end = static_cast<std::int64_t>(std::llround(seconds * 1e9));
  for (std::int64_t t = 0; t <= end; t += kReportNs) {
    for (const auto& r : reports(static_cast<double>(t) * 1e-9)) {
      w.write(io::RecordedHid{t, device, r, false});
      mapper.on_report(t, device, r);
    }
    if (t % kHidSampleNs == 0) w.write(to_recorded_sample(mapper.state(t)));
  }
}

std::uint8_t level(double x) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0));
}

void hid_ds4(const std::filesystem::path& file) {
  hid_stream(file, "DualShock 4 (USB): left stick right 1 s, R2 ramp and cross, then options",
             "054c:05c4", {}, 3.0, [](double t) -> std::vector<std::vector<std::uint8_t>> {
               std::uint8_t lx = 0x80, r2 = 0, b5 = 0x08, b6 = 0;
               if (t < 1.0 - 1e-9) lx = 0xFF;
               if (t >= 1.0 - 1e-9 && t < 2.0 - 1e-9) r2 = level(t - 1.0);
               if (t >= 1.5 - 1e-9 && t < 2.0 - 1e-9) b5 = 0x28;  // cross
               if (t >= 2.5 - 1e-9) b6 = 0x20;                    // options
               if (r2 > 0) b6 |= 0x08;  // R2's digital bit goes with the analog value
               return {test_data::ds4_report({{1, lx}, {9, r2}, {5, b5}, {6, b6}})};
             });
}

void hid_dualsense(const std::filesystem::path& file) {
  hid_stream(file, "DualSense (USB): look up 0.5 s, L2 and triangle, R1 and right stick left",
             "054c:0ce6", {}, 3.0, [](double t) -> std::vector<std::vector<std::uint8_t>> {
               std::uint8_t ly = 0x80, l2 = 0, rx = 0x80, b8 = 0x08, b9 = 0;
               if (t < 0.5 - 1e-9) ly = 0x00;
               if (t >= 0.5 - 1e-9 && t < 1.5 - 1e-9) {
                 l2 = 0xFF;
                 b8 = 0x88;
                 b9 = 0x04;
               }
               if (t >= 1.5 - 1e-9 && t < 2.5 - 1e-9) {
                 rx = 0x00;
                 b9 = 0x02;
               }
               const auto seq = static_cast<std::uint8_t>(std::lround(t * 50.0));
               return {test_data::dualsense_report(
                   {{2, ly}, {3, rx}, {5, l2}, {7, seq}, {8, b8}, {9, b9}})};
             });
}

void hid_generic(const std::filesystem::path& file) {
  hid_stream(file,
             "generic USB gamepad (descriptor-driven): right stick right, hat up, button 1 and "
             "left stick left",
             "0079:0006", test_data::kGenericGamepadDescriptor, 3.0,
             [](double t) -> std::vector<std::vector<std::uint8_t>> {
               std::uint8_t x = 0x80, z = 0x80, hat = 0x0F;
               std::uint16_t buttons = 0;
               if (t < 1.0 - 1e-9) z = 0xFF;
               if (t >= 1.0 - 1e-9 && t < 2.0 - 1e-9) hat = 0;
               if (t >= 2.0 - 1e-9 && t < 3.0 - 1e-9) {
                 buttons = 0x001;
                 x = 0x00;
               }
               return {test_data::generic_report(x, 0x80, z, 0x80, hat, buttons)};
             });
}

void hid_spacemouse(const std::filesystem::path& file) {
  hid_stream(file, "SpaceMouse (046d:c626): twist right 1 s, button 1, tilt up 0.5 s", "046d:c626",
             {}, 3.0,
             [last_buttons = -1](double t) mutable -> std::vector<std::vector<std::uint8_t>> {
               int rx = 0, rz = 0;
               std::uint8_t buttons = 0;
               if (t < 1.0 - 1e-9) rz = 350;
               if (t >= 2.0 - 1e-9 && t < 2.5 - 1e-9) buttons = 0x01;
               if (t >= 2.5 - 1e-9 && t < 3.0 - 1e-9) rx = 350;
               // Translation (1), rotation (2) and buttons (3) come as separate reports; like the
               // device, send buttons only when they change.
               std::vector<std::vector<std::uint8_t>> out;
               if (t == 0.0) out.push_back(test_data::spacemouse_report(1, 0, 0, 0));
               out.push_back(test_data::spacemouse_report(2, rx, 0, rz));
               if (buttons != last_buttons) out.push_back({0x03, buttons, 0x00});
               last_buttons = buttons;
               return out;
             });
}

}  // namespace

const std::vector<TourStep>& buttons_tour() {
  static const std::vector<TourStep> tour = {
      {static_cast<int>(Key::Space), "/user/hand/right/input/trigger/value", 1.0},
      {static_cast<int>(Key::G), "/user/hand/right/input/squeeze/value", 1.0},
      {static_cast<int>(Key::J), "/user/hand/right/input/a/click", 1.0},
      {static_cast<int>(Key::K), "/user/hand/right/input/b/click", 1.0},
      {static_cast<int>(Key::L), "/user/hand/right/input/thumbstick/click", 1.0},
      {static_cast<int>(Key::Up), "/user/hand/right/input/thumbstick/y", 1.0},
      {static_cast<int>(Key::Left), "/user/hand/right/input/thumbstick/x", -1.0},
      {static_cast<int>(Key::E), "/user/hand/left/input/trigger/value", 1.0},
      {static_cast<int>(Key::Q), "/user/hand/left/input/squeeze/value", 1.0},
      {static_cast<int>(Key::X), "/user/hand/left/input/x/click", 1.0},
      {static_cast<int>(Key::Y), "/user/hand/left/input/y/click", 1.0},
      {static_cast<int>(Key::C), "/user/hand/left/input/thumbstick/click", 1.0},
      {static_cast<int>(Key::S), "/user/hand/left/input/thumbstick/y", -1.0},
      {static_cast<int>(Key::D), "/user/hand/left/input/thumbstick/x", 1.0},
      {static_cast<int>(Key::M), "/user/hand/left/input/menu/click", 1.0},
  };
  return tour;
}

const std::vector<Script>& all() {
  static const std::vector<Script> scripts = {
      {"sim_look_and_place.vdrec.jsonl", sim_look_and_place},
      {"sim_buttons_tour.vdrec.jsonl", sim_buttons_tour},
      {"hid_ds4.vdrec.jsonl", hid_ds4},
      {"hid_dualsense.vdrec.jsonl", hid_dualsense},
      {"hid_generic_gamepad.vdrec.jsonl", hid_generic},
      {"hid_spacemouse.vdrec.jsonl", hid_spacemouse},
  };
  return scripts;
}

}  // namespace vdfx::xr::scripts
