/// @file
/// @brief The flare and grain layers of the document being edited, ready to lay out per frame:
/// effects::FlareSet and effects::GrainSet rebuilt when the document changes, with the edited
/// flare's and grain's interpolants taken from the editor each frame (so a keyframe being
/// placed or held shows live, as the stack effects' do).
#pragma once

#include <cstdint>

#include "effects/flare_set.h"
#include "effects/grain_layout.h"

namespace vdfx::app {

class Editor;

class EditorLayers {
 public:
  EditorLayers();
  /// Brings both sets up to date with the editor's document and pending edit (frame thread).
  void update(const Editor& editor);
  effects::FlareSet& flares() { return flares_; }
  effects::GrainSet& grains() { return grains_; }

 private:
  effects::FlareSet flares_;
  effects::GrainSet grains_;
  std::uint64_t revision_ = ~0ull;
  bool pending_flare_ = false,
       pending_grain_ = false;                        //!< the pending edit's target at the rebuild
  bool edited_flare_ = false, edited_grain_ = false;  //!< entry 0 of the set is the edited one
};

}  // namespace vdfx::app
