/// @file
/// @brief resolve_video_layout: the command line over the stream's tags over the sidecar.
#include "io/video_layout.h"

#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/sidecar.h"

namespace vdfx::io {
namespace {

using effects::StereoMode;

std::string mode_text(StereoMode m) {
  return std::string(effects::stereo_mode_name(m));
}

/// The sidecar's record against the stream's tag: a contradiction is the user's to settle.
template <class T, class Name>
void check_agrees(const std::optional<T>& recorded, const std::optional<T>& tagged,
                  const char* field, const char* option, const std::filesystem::path& sidecar,
                  const VideoProperties& video, Name name) {
  if (!recorded || !tagged || *recorded == *tagged) return;
  throw InputError(sidecar.string() + ": /video/" + field + ": the sidecar says " +
                   name(*recorded) + " but " + video.path.string() + " is tagged " + name(*tagged) +
                   " (give " + option + " to say which is right)");
}

}  // namespace

effects::StereoLayout resolve_video_layout(const VideoProperties& video, const LayoutOverride& cli,
                                           const VideoInfo* sidecar,
                                           const std::filesystem::path& sidecar_path,
                                           std::string* hint) {
  const StereoTags& tags = video.stereo_tags;
  const auto cov_text = [](int c) { return std::to_string(c); };
  if (sidecar && !cli.mode)
    check_agrees(sidecar->layout, tags.mode, "layout", "--layout", sidecar_path, video, mode_text);
  if (sidecar && !cli.coverage_deg)
    check_agrees(sidecar->coverage_deg, tags.coverage_deg, "coverage", "--coverage", sidecar_path,
                 video, cov_text);
  effects::StereoLayout layout;
  const std::optional<StereoMode> recorded_mode = sidecar ? sidecar->layout : std::nullopt;
  const std::optional<int> recorded_cov = sidecar ? sidecar->coverage_deg : std::nullopt;
  layout.mode = cli.mode.value_or(tags.mode.value_or(recorded_mode.value_or(StereoMode::Mono)));
  layout.coverage_deg =
      cli.coverage_deg.value_or(tags.coverage_deg.value_or(recorded_cov.value_or(360)));
  if (const auto problem = effects::layout_problem(layout, video.width, video.height)) {
    const std::string from = cli.mode    ? "--layout"
                             : tags.mode ? "the stream's stereo tag"
                             : (sidecar && recorded_mode)
                                 ? sidecar_path.string() + ": /video/layout"
                                 : "the layout";
    throw InputError(video.path.string() + ": " + from + ": " + *problem);
  }
  const bool untagged = !cli.mode && !tags.mode && !recorded_mode;
  if (hint && untagged) *hint = effects::stereo_shape_hint(video.width, video.height);
  return layout;
}

void record_layout(VideoInfo& video, const effects::StereoLayout& layout) {
  if (layout == effects::StereoLayout{} && !video.layout && !video.coverage_deg) return;
  video.layout = layout.mode;
  video.coverage_deg = layout.coverage_deg;
}

}  // namespace vdfx::io
