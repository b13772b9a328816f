/// @file
/// @brief What the headset tests that run the editor in the frame loop share: the editor as they
/// drive it (Hands panels; solves and visualizations synchronous, so runs repeat exactly) and the
/// loop's options for the simulated OpenXR runtime (generic90 at a tenth of its size, no visible
/// window).
#pragma once

#include <memory>

#include "app/editor/editor.h"
#include "app/window/frame_loop.h"
#include "xr/headset/hmd_profile.h"
#include "xr/openxr/gl/openxr_runtime.h"

namespace vdfx::app::testing {

inline std::unique_ptr<Editor> headset_test_editor(const io::Sidecar& sidecar) {
  DocumentOptions dopts;
  dopts.keyframes.async = false;
  EditorOptions eo;
  eo.layout = PanelLayout::Hands;
  eo.visuals.async = false;
  return std::make_unique<Editor>(sidecar, dopts, eo);
}

inline FrameLoopOptions openxr_loop_options() {
  FrameLoopOptions o;
  o.profile = xr::load_hmd_profile("generic90");
  o.visible = false;
  o.eye_scale = 0.1;
  o.openxr = xr::OpenXrRuntime::create();
  return o;
}

}  // namespace vdfx::app::testing
