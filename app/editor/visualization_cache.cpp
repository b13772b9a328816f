/// @file
/// @brief VisualizationCache: track plot, minimap and markers, recomputed when what they show
/// changed.
#include "app/editor/visualization_cache.h"

#include <algorithm>

#include "app/editor/document.h"
#include "app/editor/editor_panels.h"
#include "app/editor/visualizations.h"

namespace vdfx::app {

namespace {
double angle_deg(const effects::Direction& a, const effects::Direction& b) {
  return effects::angle_between(effects::to_unit(a), effects::to_unit(b)) * effects::kRadToDeg;
}
}  // namespace

VisualizationCache::VisualizationCache(VisualizationOptions options, std::int64_t frame_count)
    : options_(options) {
  track_.frames = track_sample_frames(frame_count, options_.track_samples);
  if (options_.async) worker_ = std::make_unique<MinimapWorker>();
}

VisualizationCache::~VisualizationCache() = default;

void VisualizationCache::refresh_markers(const Document& doc, const VisualizationInput& in,
                                         EditorPanels& panels) {
  // Markers follow the view: recomputed when it moved by a degree, or the keyframes changed.
  const auto& ks = doc.keyframes(in.effect);
  const int eff = in.effect.index();
  const std::int64_t held_frame = in.held ? in.held->frame : -1;
  if (markers_.revision == doc.revision() && markers_.effect == eff &&
      angle_deg(markers_.view, in.view) <= 1.0 && markers_.held_frame == held_frame)
    return;
  markers_.near = keyframes_near_view(ks, in.view, options_.marker_cone_deg);
  std::vector<int> frames, highlighted;
  for (std::size_t i = 0; i < ks.size(); ++i)
    frames.push_back(static_cast<int>(in.held && i == *in.selected ? in.held->frame : ks[i].frame));
  for (const auto i : markers_.near) highlighted.push_back(static_cast<int>(ks[i].frame));
  if (in.held) highlighted.push_back(static_cast<int>(in.held->frame));
  panels.strip->set_keyframes(frames);
  panels.strip->set_highlighted(highlighted);
  markers_.revision = doc.revision();
  markers_.effect = eff;
  markers_.view = in.view;
  markers_.held_frame = held_frame;
}

void VisualizationCache::refresh(const Document& doc, const VisualizationInput& in,
                                 EditorPanels& panels) {
  const auto& ks = doc.keyframes(in.effect);
  const int eff = in.effect.index();
  refresh_markers(doc, in, panels);
  // While a keyframe is placed, or held away from its place, the track and the field are the
  // pending edit's interpolant (the one the view shows); each new place is a new version.
  const PendingEdit* pending = doc.pending();
  const bool shows_pending =
      pending && pending->target() == in.effect && pending->changes_interpolant();
  std::shared_ptr<const effects::RbfInterpolator> rbf;
  auto interpolant = [&] {
    if (!rbf) rbf = shows_pending ? pending->interpolant() : doc.keyframe_set(in.effect).solution();
    return rbf;
  };
  const MinimapKey base{doc.revision(), doc.keyframe_set(in.effect).solution_version(), eff, -1,
                        shows_pending ? pending->version() : 0};
  const auto [lo, hi] = display_range(in.effect);
  if (!(track_.key == base) || angle_deg(track_.view, in.view) > 1.0) {
    track_.values = effect_track(interpolant().get(), in.effect, in.view, track_.frames);
    panels.plot->set_values(track_.values);
    panels.plot->set_range(lo, hi);
    // Keyframe marks: the held keyframe where it is held, a placed one at the playhead.
    std::vector<std::int64_t> key_frames;
    for (std::size_t i = 0; i < ks.size(); ++i)
      key_frames.push_back(in.held && i == *in.selected ? in.held->frame : ks[i].frame);
    if (in.previewing) key_frames.push_back(in.frame);
    std::vector<int> marks;  // keyframe frames as sample indices
    for (const auto f : key_frames) {
      const auto it = std::lower_bound(track_.frames.begin(), track_.frames.end(), f);
      if (it != track_.frames.end()) marks.push_back(static_cast<int>(it - track_.frames.begin()));
    }
    panels.plot->set_keyframes(marks);
    track_.key = base;
    track_.view = in.view;
  }
  {
    const auto it = std::lower_bound(track_.frames.begin(), track_.frames.end(), in.frame);
    panels.plot->set_playhead(static_cast<int>(std::min<std::ptrdiff_t>(
        it - track_.frames.begin(), static_cast<std::ptrdiff_t>(track_.frames.size()) - 1)));
  }
  MinimapKey mk = base;
  mk.frame = in.frame;
  if (!(minimap_.requested == mk)) {
    const auto s = doc.interpolation(in.effect);
    minimap_.nearest = nearest_keyframe(ks, in.view, in.frame, s.time_scale, doc.video().fps);
    minimap_.requested = mk;
    if (worker_)
      worker_->request({mk, interpolant(), in.effect, in.frame, options_.minimap_width,
                        options_.minimap_height});
    else
      show_minimap(mk,
                   effect_minimap(interpolant().get(), in.effect, in.frame, options_.minimap_width,
                                  options_.minimap_height),
                   in.effect, panels);
  }
  // A field finished for an earlier frame or edit is shown until the current one is ready (a
  // frame or two while playing large sets); one for another effect is dropped.
  if (worker_)
    if (auto r = worker_->take(); r && r->key.effect == eff)
      show_minimap(r->key, std::move(r->field), in.effect, panels);
  {
    // Keyframe dots: the selected one ringed (and carried along while held). Setters compare,
    // so an unchanged set costs no redraw.
    std::vector<effects::Direction> dirs;
    for (std::size_t i = 0; i < ks.size(); ++i)
      dirs.push_back(in.held && i == *in.selected ? in.held->direction : ks[i].direction);
    panels.minimap->set_keyframes(std::move(dirs),
                                  minimap_.nearest ? static_cast<int>(*minimap_.nearest) : -1,
                                  in.selected ? static_cast<int>(*in.selected) : -1);
  }
  panels.minimap->set_view(in.view, in.view_hfov_deg, in.view_vfov_deg);
}

void VisualizationCache::show_minimap(const MinimapKey& key, cv::Mat field, EditTarget effect,
                                      EditorPanels& panels) {
  const auto [lo, hi] = display_range(effect);
  minimap_.field = std::move(field);
  panels.minimap->set_field(minimap_.field, lo, hi);
  minimap_.shown = key;
  ++minimap_.computations;
}

bool VisualizationCache::wait(std::chrono::milliseconds timeout, EditTarget effect,
                              EditorPanels& panels) {
  if (worker_ && worker_->wait_idle(timeout))
    if (auto r = worker_->take(); r && r->key.effect == effect.index())
      show_minimap(r->key, std::move(r->field), effect, panels);
  return minimap_current();
}

}  // namespace vdfx::app
