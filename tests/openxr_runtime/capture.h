/// @file
/// @brief The read-back folder (VDFX_TEST_RUNTIME_OUTPUT_DIR): what the app submitted, for tests
/// to check. Chosen frames as PNGs with a JSON of the layers (poses, FOVs, sizes), and at the end
/// of the session session.json (states, lifecycle calls, interaction profile, haptics, frame
/// counts). Layout and
/// fields: docs/openxr.md, "Testing without a headset".
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tests/openxr_runtime/runtime.h"

namespace vdfx::test_runtime {

/// One submitted image region, as the headset would show it: 8-bit RGBA, top row first.
struct CapturedImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;
  /// "stored": the bytes of an sRGB swapchain as they are; "linear-to-srgb": a linear format's
  /// values (what the compositor takes as linear light) encoded to sRGB for display.
  std::string encoding;
};

struct CapturedView {
  XrPosef pose{};                     //!< as submitted, in the layer's space
  std::optional<Pose> pose_in_local;  //!< the same at the frame's display time, if located
  std::optional<XrFovf> fov;          //!< projection views
  std::string format;                 //!< the swapchain's format name
  std::uint32_t swapchain_width = 0, swapchain_height = 0;
  XrRect2Di rect{};
  std::uint32_t array_index = 0;
  std::uint32_t image_index = 0;  //!< which swapchain image it was
  CapturedImage image;
  /// VDFX_TEST_RUNTIME_CAPTURE=last: a GPU copy of the region, read into `image` only when the
  /// session ends (reading every frame back would cost a generic90 frame about 50 ms on
  /// llvmpipe); 0 once read.
  GLuint pending_copy = 0;
  bool format_srgb = false;
};

struct CapturedLayer {
  std::string type;  //!< "projection" or "quad"
  XrCompositionLayerFlags flags = 0;
  std::string space;                //!< "VIEW", "LOCAL", "STAGE" or "action:NAME"
  std::vector<CapturedView> views;  //!< projection: one per eye; quad: one
  std::string eye_visibility;       //!< quad: "both", "left" or "right"
  XrExtent2Df size{};               //!< quad: metres
};

struct CapturedFrame {
  std::int64_t frame = 0;   //!< index of its xrWaitFrame in the session
  XrTime display_time = 0;  //!< XrFrameEndInfo::displayTime
  XrTime predicted_display_time = 0;
  std::vector<CapturedLayer> layers;
};

struct HapticRecord {
  XrTime time = 0;         //!< the session's time (latest predicted display time)
  std::int64_t frame = 0;  //!< frames waited so far
  std::string action;
  std::string subaction;             //!< "" when applied to every subaction path
  std::vector<std::string> outputs;  //!< the bound output paths that vibrated
  bool stop = false;                 //!< xrStopHapticFeedback
  std::int64_t duration_ns = 0;
  float frequency = 0.0f;
  float amplitude = 0.0f;
};

class Recorder {
 public:
  /// Creates the folder (throws naming it when that fails).
  explicit Recorder(const Instance& inst);

  /// Whether frame `frame`'s layers are to be read back.
  bool wants(std::int64_t frame) const { return spec_.wants(frame); }
  void state(XrSessionState state, XrTime time);
  void interaction_profile(const std::string& path, XrTime time);
  void haptic(HapticRecord record);
  /// A lifecycle call the app made (xrBeginSession, xrRequestExitSession, xrEndSession,
  /// xrDestroySession), in order, with the frames waited by then: session.json's
  /// "lifecycle_calls".
  void call(const char* function, std::int64_t frames_waited);
  /// Writes the frame's files now, or (VDFX_TEST_RUNTIME_CAPTURE=last) keeps it for finish() when
  /// it has layers; returns the frame it no longer keeps, whose GPU copies the caller drops.
  std::optional<CapturedFrame> frame(CapturedFrame frame);
  /// Whether frames are kept (last) rather than written at once.
  bool keeps_last() const { return spec_.mode == CaptureSpec::Mode::Last; }
  /// The kept frame, whose GPU copies are read before finish().
  std::optional<CapturedFrame>& kept() { return last_; }
  /// Writes the last frame (when kept) and session.json; again later, it does nothing.
  void finish(std::int64_t frames_waited, std::int64_t frames_ended);

 private:
  void write_frame(const CapturedFrame& frame);

  std::filesystem::path dir_;
  CaptureSpec spec_;
  std::string hmd_name_;
  std::string script_;
  std::int64_t period_ns_ = 0;
  std::optional<CapturedFrame> last_;
  std::vector<std::pair<XrSessionState, XrTime>> states_;
  std::vector<std::pair<std::string, XrTime>> profiles_;
  std::vector<HapticRecord> haptics_;
  std::vector<std::pair<std::string, std::int64_t>> calls_;
  std::vector<std::int64_t> written_;
  bool finished_ = false;
};

}  // namespace vdfx::test_runtime
