/// @file
/// @brief EditorLayers: the edited document's flares and grain as FlareSet and GrainSet.
#include "app/editor/editor_layers.h"

#include "app/editor/editor.h"
#include "io/sidecar_sets.h"

namespace vdfx::app {

EditorLayers::EditorLayers() : flares_({}, effects::InterpolationSettings{}, 30.0) {}

void EditorLayers::update(const Editor& editor) {
  const Document& doc = editor.document();
  const PendingEdit* p = doc.pending();
  const bool pending_flare = p && p->target().is_flare(),
             pending_grain = p && p->target().is_grain();
  if (doc.revision() != revision_ || pending_flare != pending_flare_ ||
      pending_grain != pending_grain_) {
    revision_ = doc.revision();
    pending_flare_ = pending_flare;
    pending_grain_ = pending_grain;
    io::Sidecar s = doc.sidecar();
    // The document writes its edited flare first, and writes the others only after one; while
    // the first keyframe of a new flare is being placed the sidecar has none yet: show it.
    if (s.flares.empty() && pending_flare) {
      s.flares.push_back(doc.flare());
      s.flares.back().anchor = doc.anchor(EditTarget::flare());
    }
    if (s.grains.empty() && pending_grain) {
      s.grains.push_back(doc.grain());
      s.grains.back().anchor = doc.anchor(EditTarget::grain());
    }
    edited_flare_ = !s.flares.empty();
    edited_grain_ = !s.grains.empty();
    const effects::AnchorSources anchors = io::anchor_sources(s);
    flares_.replace_flares(std::move(s.flares), s.interpolation, s.video.fps, anchors);
    grains_ = effects::GrainSet(std::move(s.grains), s.interpolation, s.video.fps, anchors);
  }
  // The editor's interpolants: the pending edit's while there is one, else the solutions.
  if (edited_flare_)
    if (auto rbf = editor.interpolant(EditTarget::flare()); rbf && !rbf->empty())
      flares_.set_intensity(0, rbf);
  if (edited_grain_)
    if (auto rbf = editor.interpolant(EditTarget::grain()); rbf && !rbf->empty())
      grains_.set_interpolant(0, rbf);
}

}  // namespace vdfx::app
