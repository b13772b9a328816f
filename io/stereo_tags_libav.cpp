/// @file
/// @brief read_stereo_tags: AVStereo3D and AVSphericalMapping side data to io::StereoTags.
#include <cstdint>
#include <string>

extern "C" {
#include <libavformat/avformat.h>
#include <libavutil/spherical.h>
#include <libavutil/stereo3d.h>
}

#include "io/input_error.h"
#include "io/video_layout.h"

namespace vdfx::io {
namespace {

using effects::StereoMode;

void read_stereo3d(const AVStream* st, StereoTags& tags) {
  std::size_t size = 0;
  const auto* s =
      reinterpret_cast<const AVStereo3D*>(av_stream_get_side_data(st, AV_PKT_DATA_STEREO3D, &size));
  if (!s || size < sizeof(AVStereo3D)) return;
  const bool invert = (s->flags & AV_STEREO3D_FLAG_INVERT) != 0;
  switch (s->type) {
    case AV_STEREO3D_2D: tags.mode = StereoMode::Mono; break;
    // Inverted top-bottom (right eye on top) has no name in the contract: reported below.
    case AV_STEREO3D_TOPBOTTOM:
      if (!invert) tags.mode = StereoMode::TopBottom;
      break;
    case AV_STEREO3D_SIDEBYSIDE:
      tags.mode = invert ? StereoMode::RightLeft : StereoMode::LeftRight;
      break;
    default: break;
  }
  if (!tags.mode)
    tags.unsupported = std::string("stereo type '") + av_stereo3d_type_name(s->type) + "'" +
                       (invert ? " (inverted)" : "");
}

void read_spherical(const AVStream* st, const std::string& file, StereoTags& tags) {
  std::size_t size = 0;
  const auto* m = reinterpret_cast<const AVSphericalMapping*>(
      av_stream_get_side_data(st, AV_PKT_DATA_SPHERICAL, &size));
  if (!m || size < sizeof(AVSphericalMapping)) return;
  if (m->projection != AV_SPHERICAL_EQUIRECTANGULAR &&
      m->projection != AV_SPHERICAL_EQUIRECTANGULAR_TILE) {
    const std::string what = std::string("projection '") +
                             av_spherical_projection_name(m->projection) + "' (not equirect)";
    tags.unsupported += (tags.unsupported.empty() ? "" : ", ") + what;
    return;
  }
  // Bounds are 0.32 fixed point fractions of the full sphere's width and height.
  const std::uint64_t one = std::uint64_t{1} << 32;
  const std::uint64_t lr = std::uint64_t{m->bound_left} + m->bound_right;
  const std::uint64_t tb = std::uint64_t{m->bound_top} + m->bound_bottom;
  if (lr >= one || tb >= one)
    throw InputError(file + ": the spherical equirect bounds (left " +
                     std::to_string(m->bound_left) + ", right " + std::to_string(m->bound_right) +
                     ", top " + std::to_string(m->bound_top) + ", bottom " +
                     std::to_string(m->bound_bottom) + ", of 2^32) cover nothing");
  const std::uint32_t quarter = 0x40000000u;
  if (lr == 0 && tb == 0) {
    tags.coverage_deg = 360;
  } else if (m->bound_left == quarter && m->bound_right == quarter && tb == 0) {
    tags.coverage_deg = 180;
  } else {
    tags.unsupported += (tags.unsupported.empty() ? "" : ", ") +
                        std::string("equirect bounds other than 360 or a centred 180");
  }
}

}  // namespace

StereoTags read_stereo_tags(const AVStream* stream, const std::string& file) {
  StereoTags tags;
  read_stereo3d(stream, tags);
  read_spherical(stream, file, tags);
  return tags;
}

}  // namespace vdfx::io
