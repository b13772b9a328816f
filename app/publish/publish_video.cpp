/// @file
/// @brief publish_video: copy or transcode.
#include "app/publish/publish_video.h"

#include <algorithm>
#include <cctype>

#include "app/export/export_request.h"
#include "app/publish/publish_assets.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"

namespace vdfx::app {
namespace {

namespace fs = std::filesystem;

/// The export of the whole video with no effects into `out` (an .mp4).
void transcode(const PublishRequest& r, const io::Sidecar& sidecar, const fs::path& dir,
               const fs::path& out) {
  io::Sidecar none = sidecar;
  none.effects.clear();
  none.flares.clear();
  none.grains.clear();
  const fs::path no_effects = dir / ".transcode.vdfx.json";
  io::write_sidecar(no_effects, none);
  ExportRequest e;
  e.video = r.video;
  e.sidecar = no_effects;
  e.baked_out = out;
  e.layout = r.layout;  // the baked export keeps a stereo layout and tags it (docs/export.md)
  if (r.transcode == Transcode::Vp9) {
    // Constant quality (b = 0 makes crf the only target); "good" at cpu-used 4 with row
    // threading: a few times faster than the default at a small cost in size.
    e.encoder = "libvpx-vp9";
    e.crf = 24;
    e.preset.clear();
    e.encoder_options = {{"b", "0"}, {"deadline", "good"}, {"cpu-used", "4"}, {"row-mt", "1"}};
  } else {
    e.crf = 18;
    e.preset = "fast";
  }
  run_export(e);
  fs::remove(no_effects);
}

}  // namespace

PublishedVideo publish_video(const PublishRequest& r, const io::Sidecar& sidecar,
                             const fs::path& dir) {
  PublishedVideo v;
  if (r.transcode == Transcode::None) {
    // The extension is one of the containers browsers play (run_publish checked it).
    std::string ext = r.video.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    v.file = kPublishedVideoStem + ext;
    copy_file_checked(r.video, dir / v.file);
  } else {
    v.file = std::string(kPublishedVideoStem) + ".mp4";
    transcode(r, sidecar, dir, dir / v.file);
  }
  const auto decoder = io::open_frame_decoder(dir / v.file, {});
  const io::VideoProperties p = decoder->properties();
  io::Picture first;
  if (decoder->read_picture(first) == io::DecodeStatus::Ok && first.is_ycbcr())
    v.ycbcr = first.ycbcr;
  v.codec = p.codec;
  v.fps = p.fps.value();
  v.frames = p.frames;
  v.width = p.width;
  v.height = p.height;
  return v;
}

}  // namespace vdfx::app
