/// @file
/// @brief The in-headset editor (app/editor/editor.h) as a FrameClient of the windowed loop: `vdfx
/// edit`.
///
/// Per frame: update() steps the Editor with the frame's input at the display time and hands its
/// playhead to the loop; params() answers with the editor's interpolation, the trigger's live
/// preview included; quads() turns the editor's panels into quad layers in LOCAL space (the
/// panels' world is the input's LOCAL space; both face their local +z, like OpenXR quads).
///
/// Panel textures: a panel's CPU image (premultiplied RGBA8, row 0 at the top) is uploaded as it
/// is, only when the panel re-rendered, and then only its damaged rectangles: the compositor's
/// quads are premultiplied with their first row at the top (OpenXR's quad-layer convention).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "app/editor/editor.h"
#include "app/editor/editor_layers.h"
#include "app/editor/thumbnail_worker.h"
#include "app/window/frame_client.h"

namespace vdfx::app {

/// Where panel images go: GL textures in the window (create_gl_panel_textures), a recorder in
/// tests. Images are premultiplied RGBA8, first row at the top of the quad (the compositor's
/// quad convention, xr::QuadLayer).
class PanelTextures {
 public:
  virtual ~PanelTextures() = default;
  /// Uploads `regions` of `image` (its whole size when empty, which also (re)allocates) to the
  /// texture of `slot`; returns the texture's name (non-zero).
  virtual unsigned upload(std::size_t slot, const cv::Mat& image,
                          const std::vector<cv::Rect>& regions) = 0;
  /// Frees the textures (needs the context that made them current; the destructor frees nothing,
  /// since the window's context may already be gone by then).
  virtual void release() {}
};

/// GL textures with mipmaps (panels are seen much smaller than their pixel size). Needs a current
/// GL context at upload and release.
std::unique_ptr<PanelTextures> create_gl_panel_textures();

/// How the client draws the pointers and the placement reticle in the scene (quads composited
/// with the panels, never touched by the effects).
struct PointerDrawing {
  double dot_deg = 0.8;      //!< the cursor dot's angular diameter
  double reticle_deg = 1.6;  //!< the ring at the view centre (where keyframes are placed)
  double far_m = 3.0;        //!< where the dot sits when the ray meets no panel
  double ray_width_m = 0.004;
};

class EditorClient : public FrameClient {
 public:
  /// The editor stays owned by the caller; textures may be null (no quads: tests of the rest).
  /// follow_window: the Desktop layout follows the window's size (live); off for replays, whose
  /// panels stay where the recording had them.
  EditorClient(Editor& editor, std::unique_ptr<PanelTextures> textures, bool follow_window = false);

  /// Timeline thumbnails from a worker: shown on the strip once decoded.
  void set_thumbnails(std::unique_ptr<ThumbnailWorker> worker) { thumbnails_ = std::move(worker); }
  void on_desktop_event(const xr::DesktopEvent& event) override;
  void update(const xr::InputState& input, std::int64_t display_time_ns, FrameInfo& info) override;
  effects::StackParams params(const effects::Direction& direction,
                              std::int64_t video_frame) override;
  std::function<effects::StackParams(const effects::Direction&)> params_at(
      std::int64_t video_frame) override {
    return editor_.params_at(video_frame);
  }
  unsigned active_effects() const override { return active_; }
  std::uint64_t params_revision() const override { return revision_; }
  std::vector<xr::QuadLayer> quads() override;
  bool unaltered() const override { return editor_.unaltered(); }
  std::vector<effects::FlareLayout> flares(const xr::Pose& head_in_local, std::int64_t video_frame,
                                           const io::Picture* picture) override;
  std::vector<effects::GrainFrame> grains(const xr::Pose& head_in_local,
                                          std::int64_t display_time_ns,
                                          std::int64_t video_frame) override;
  std::string status_line() const override;

  Editor& editor() { return editor_; }
  /// Panel uploads so far (whole or partial).
  int uploads() const { return uploads_; }
  /// Frees the GL textures while the context is still current (see PanelTextures::release).
  void release_textures();

  /// The editor's controls, as text for --help and docs/editor.md.
  static std::string controls_text();
  /// The pointer quads of the last quads() call: cursor dots, rays, the reticle (tests).
  const std::vector<xr::QuadLayer>& pointer_quads() const { return pointer_quads_; }

 private:
  void add_pointer_quads(std::vector<xr::QuadLayer>& out);
  unsigned texture_of(std::size_t slot, const cv::Mat& premultiplied);

  struct Slot {
    const ui::Panel* panel = nullptr;
    int render_count = -1;  //!< the panel's render_count() at the last upload
    unsigned texture = 0;
    int width = 0, height = 0;  //!< the texture's size at the last upload
  };
  Editor& editor_;
  std::unique_ptr<PanelTextures> textures_;
  std::vector<Slot> slots_;
  unsigned active_ = 0;
  std::uint64_t revision_ = 0;
  /// What params() depends on; revision_ moves when it changes.
  struct AnswersKey {
    std::uint64_t document = ~0ull, solutions = 0, pending = 0;
    bool pending_exists = false, unaltered = false;
    bool operator==(const AnswersKey&) const = default;
  };
  AnswersKey answers_;
  int uploads_ = 0;
  bool follow_window_ = false;
  std::unique_ptr<ThumbnailWorker> thumbnails_;
  EditorLayers layers_;
  PointerDrawing drawing_;
  std::array<unsigned, 3> pointer_textures_{};  //!< dot, ring, ray
  std::vector<xr::QuadLayer> pointer_quads_;
  // Frame rate over the last second of display time, for the heads-up line.
  std::int64_t fps_t0_ = -1;
  int fps_frames_ = 0;
  double fps_ = 0.0;
};

}  // namespace vdfx::app
