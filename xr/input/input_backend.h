/// @file
/// @brief The input backend interface and its factory by name: "sim", "hid[:SEL,...]",
/// "replay:FILE" (style: hello_xr's platform plugin + factory). Backends hide their classes.
///
/// Time is passed in to poll(), never read inside, so replay and tests are deterministic.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "io/hid_device.h"
#include "io/hid_reader.h"
#include "io/recording.h"
#include "xr/input/actions.h"
#include "xr/input/hid_mapping.h"
#include "xr/input/input_events.h"

namespace vdfx::xr {

class InputBackend {
 public:
  virtual ~InputBackend() = default;
  /// The actions at time t_ns (the frame's predicted display time), with the edges since the
  /// previous poll (InputState::edges). Backends that queue input (sim, hid) never let a control
  /// go down and up again within one poll: a tap between two frames is down in exactly one.
  InputState poll(std::int64_t t_ns) { return sync_.sync(poll_state(t_ns)); }
  /// Desktop events from the window glue, applied at the next poll; ignored by backends that do
  /// not use them. Call from the thread that polls.
  virtual void push_event(const DesktopEvent& event) { (void)event; }
  /// A one-line status for the UI (e.g. "054c:05c4: lost (...) (retrying every 1000 ms)").
  virtual std::string status() const { return {}; }
  /// Recorded sample times (replay only; empty for live backends): `vdfx replay` steps these.
  virtual std::vector<std::int64_t> timeline() const { return {}; }
  /// Raw HID lines handled by the last poll (descriptors, reports, losses), for recording.
  virtual std::vector<io::RecordedHid> drain_raw_reports() { return {}; }

 protected:
  /// The backend's state at t_ns (what poll() returns, before the edges).
  virtual InputState poll_state(std::int64_t t_ns) = 0;

 private:
  ActionSync sync_;
};

/// Desktop stand-in: mouse and keyboard drive head and hands (docs/input.md lists bindings).
/// Which way a right-button drag turns the view.
enum class LookMode {
  Drag,       //!< the image follows the mouse, as in desktop 360 players (YouTube, Facebook 360):
              //!< dragging left turns the view right, dragging down looks up
  Mouselook,  //!< a first-person game's camera: dragging left turns left, down looks down
};
/// "drag" / "mouselook", and back (nullopt for another name).
std::string_view look_mode_name(LookMode mode);
std::optional<LookMode> parse_look_mode(std::string_view name);

struct SimConfig {
  int window_width = 1280;  //!< pixels; updated by ViewGeometryEvent
  int window_height = 720;
  double hfov_deg = 100.0;  //!< horizontal field of view of the desktop view (its default)
  /// Head turn per pixel of right-button drag; 0 (the default): the drag follows the cursor,
  /// the turn that moves the view's centre by one pixel (look_deg_per_px_of).
  double look_deg_per_px = 0.0;
  LookMode look = LookMode::Drag;  //!< which way a drag turns; the key I switches it
  bool left_handed = false;        //!< mouse and the main keys drive the left hand instead
  glm::dvec3 head_position{0.0, kDefaultEyeHeight, 0.0};
};

/// The turn of one pixel of drag: config.look_deg_per_px where set, else the angle one pixel
/// spans at the centre of a pinhole of hfov_deg over window_width pixels (at 1280 pixels and 100
/// degrees, 0.107 degrees: the image under the cursor moves with it).
double look_deg_per_px_of(const SimConfig& config);

struct InputBackendOptions {
  SimConfig sim;
  HidMappingConfig hid_mapping;
  io::HidSystem hid_system;  //!< empty functions: the OS's (hidapi)
  io::HidReaderOptions hid_reader;
};

/// "sim", "hid" (every supported device found), "hid:SEL[,SEL...]" with SEL a vendor:product
/// ("054c:05c4") or a device path ("/dev/hidraw3"), "replay:FILE". Throws io::InputError for an
/// unknown name, a bad selector or a bad recording (message names the file and line).
std::unique_ptr<InputBackend> create_input_backend(std::string_view spec,
                                                   const InputBackendOptions& options = {});

std::unique_ptr<InputBackend> create_sim_backend(const SimConfig& config);
std::unique_ptr<InputBackend> create_hid_backend(const std::vector<std::string>& selectors,
                                                 const InputBackendOptions& options);
std::unique_ptr<InputBackend> create_replay_backend(io::Recording recording,
                                                    const InputBackendOptions& options);
std::unique_ptr<InputBackend> create_replay_backend(const std::filesystem::path& file,
                                                    const InputBackendOptions& options);

/// The RecordingInputBackend decorator: polls `inner` and writes what it returns (and its raw
/// HID lines) to `file`, one flushed line per poll; everything else passes through.
std::unique_ptr<InputBackend> create_recording_backend(std::unique_ptr<InputBackend> inner,
                                                       const std::filesystem::path& file,
                                                       const io::RecordingHeader& header);

/// The sim bindings as a two-column text table (for --help and docs/input.md).
std::string sim_bindings_text(const SimConfig& config);
/// What presses one control in the sim, as sim_bindings_text names it ("Space", "left mouse
/// button"); empty when nothing does. For help texts that name the sim's keys. `pointing`: only
/// the inputs that press it with the aim through the cursor (not Space, aimed at the centre).
std::vector<std::string> sim_inputs_of(Hand hand, Control control, const SimConfig& config,
                                       bool pointing = false);

}  // namespace vdfx::xr
