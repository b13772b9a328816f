/// @file
/// @brief VisualizationCache: track plot, minimap and markers, recomputed when what they show
/// changed.
#include "app/editor/visualization_cache.h"

#include <algorithm>

#include "app/editor/document.h"
#include "app/editor/visualizations.h"
#include "effects/direction_angle.h"

namespace vdfx::app {

namespace {
/// The index of the first sampled frame at or after `frame` (frames.size() when none).
std::ptrdiff_t sample_at(std::span<const std::int64_t> frames, std::int64_t frame) {
  return std::lower_bound(frames.begin(), frames.end(), frame) - frames.begin();
}
}  // namespace

VisualizationCache::VisualizationCache(VisualizationOptions options, std::int64_t frame_count)
    : options_(options) {
  track_.frames = track_sample_frames(frame_count, options_.track_samples);
  if (options_.async) worker_ = std::make_unique<MinimapWorker>();
}

VisualizationCache::~VisualizationCache() = default;

void VisualizationCache::refresh_markers(const Document& doc, const VisualizationInput& in) {
  // Markers follow the view: recomputed when it moved by a degree, the keyframes changed, or an
  // anchored effect's rotation did (the playhead moved).
  const auto& ks = doc.keyframes(in.effect);
  const int eff = in.effect.index();
  const std::int64_t held_frame = in.held ? in.held->frame : -1;
  const effects::AnchorFrames& anchor = doc.anchor_frames(in.effect);
  const std::int64_t anchor_frame = anchor.identity() ? 0 : in.frame;
  if (markers_.revision == doc.revision() && markers_.effect == eff &&
      effects::angle_between_deg(markers_.view, in.view) <= 1.0 &&
      markers_.held_frame == held_frame && markers_.anchor_frame == anchor_frame)
    return;
  markers_.near =
      keyframes_near_view(ks, anchor.apply(in.view, in.frame), options_.marker_cone_deg);
  out_.marker_frames.clear();
  out_.highlighted_frames.clear();
  for (std::size_t i = 0; i < ks.size(); ++i)
    out_.marker_frames.push_back(static_cast<int>(in.shown(ks, i).frame));
  for (const auto i : markers_.near)
    out_.highlighted_frames.push_back(static_cast<int>(ks[i].frame));
  if (in.held) out_.highlighted_frames.push_back(static_cast<int>(in.held->frame));
  ++out_.markers_version;
  markers_.revision = doc.revision();
  markers_.effect = eff;
  markers_.view = in.view;
  markers_.held_frame = held_frame;
  markers_.anchor_frame = anchor_frame;
}

void VisualizationCache::refresh_track(const VisualizationInput& in,
                                       std::span<const effects::Keyframe> ks, const MinimapKey& key,
                                       const effects::RbfInterpolator* rbf,
                                       const effects::AnchorFrames& anchor) {
  out_.track = effect_track(rbf, in.effect, in.view, track_.frames, anchor);
  std::tie(out_.track_lo, out_.track_hi) = display_range(in.effect);
  // Keyframe marks: the held keyframe where it is held, a placed one at the playhead.
  std::vector<std::int64_t> key_frames;
  for (std::size_t i = 0; i < ks.size(); ++i) key_frames.push_back(in.shown(ks, i).frame);
  if (in.previewing) key_frames.push_back(in.frame);
  out_.track_marks.clear();
  for (const auto f : key_frames)
    if (const auto i = sample_at(track_.frames, f);
        i < static_cast<std::ptrdiff_t>(track_.frames.size()))
      out_.track_marks.push_back(static_cast<int>(i));
  ++out_.track_version;
  track_.key = key;
  track_.view = in.view;
}

void VisualizationCache::refresh_minimap(
    const Document& doc, const VisualizationInput& in, const MinimapKey& key,
    const std::function<std::shared_ptr<const effects::RbfInterpolator>()>& rbf) {
  const auto& ks = doc.keyframes(in.effect);
  const effects::AnchorFrames& anchor = doc.anchor_frames(in.effect);
  if (!(minimap_.requested == key)) {
    const auto s = doc.interpolation(in.effect);
    minimap_.nearest = nearest_keyframe(ks, anchor.apply(in.view, in.frame), in.frame, s.time_scale,
                                        doc.video().fps);
    minimap_.requested = key;
    if (worker_)
      worker_->request({key, rbf(), in.effect, in.frame, options_.minimap_width,
                        options_.minimap_height, anchor});
    else
      take_field(key,
                 effect_minimap(rbf().get(), in.effect, in.frame, options_.minimap_width,
                                options_.minimap_height, nullptr, anchor),
                 in.effect);
  }
  // A field finished for an earlier frame or edit is shown until the current one is ready (a
  // frame or two while playing large sets); one for another effect is dropped.
  if (worker_)
    if (auto r = worker_->take(); r && r->key.effect == in.effect.index())
      take_field(r->key, std::move(r->field), in.effect);
  // Keyframe dots where the keyframes are at the playhead (turned back from the anchor's
  // frame): the selected one ringed (and carried along while held).
  out_.dots.clear();
  for (std::size_t i = 0; i < ks.size(); ++i)
    out_.dots.push_back(anchor.unapply(in.shown(ks, i).direction, in.frame));
  out_.nearest = minimap_.nearest ? static_cast<int>(*minimap_.nearest) : -1;
  out_.selected = in.selected ? static_cast<int>(*in.selected) : -1;
  out_.view = in.view;
  out_.view_hfov_deg = in.view_hfov_deg;
  out_.view_vfov_deg = in.view_vfov_deg;
}

const Visualizations& VisualizationCache::refresh(const Document& doc,
                                                  const VisualizationInput& in) {
  refresh_markers(doc, in);
  // While a keyframe is placed, or held away from its place, the track and the field are the
  // pending edit's interpolant (the one the view shows); each new place is a new version.
  const PendingEdit* pending = doc.pending();
  const bool shows_pending =
      pending && pending->target() == in.effect && pending->changes_interpolant();
  std::shared_ptr<const effects::RbfInterpolator> rbf;
  const auto interpolant = [&] {
    if (!rbf) rbf = shows_pending ? pending->interpolant() : doc.keyframe_set(in.effect).solution();
    return rbf;
  };
  const MinimapKey base{doc.revision(), doc.keyframe_set(in.effect).solution_version(),
                        in.effect.index(), -1, shows_pending ? pending->version() : 0};
  if (!(track_.key == base) || effects::angle_between_deg(track_.view, in.view) > 1.0)
    refresh_track(in, doc.keyframes(in.effect), base, interpolant().get(),
                  doc.anchor_frames(in.effect));
  out_.track_playhead = static_cast<int>(std::min(
      sample_at(track_.frames, in.frame), static_cast<std::ptrdiff_t>(track_.frames.size()) - 1));
  MinimapKey key = base;
  key.frame = in.frame;
  refresh_minimap(doc, in, key, interpolant);
  return out_;
}

void VisualizationCache::take_field(const MinimapKey& key, cv::Mat field, EditTarget effect) {
  std::tie(out_.field_lo, out_.field_hi) = display_range(effect);
  out_.field = std::move(field);
  ++out_.field_version;
  minimap_.shown = key;
  ++minimap_.computations;
}

bool VisualizationCache::wait(std::chrono::milliseconds timeout, EditTarget effect) {
  if (worker_ && worker_->wait_idle(timeout))
    if (auto r = worker_->take(); r && r->key.effect == effect.index())
      take_field(r->key, std::move(r->field), effect);
  return minimap_current();
}

}  // namespace vdfx::app
