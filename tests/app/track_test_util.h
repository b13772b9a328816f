/// @file
/// @brief Clips with a known truth for the `vdfx track` tests: a real panorama seen along a known
/// camera path, a patch moved along a known subject path (app/bench/track_clips.h), encoded with
/// x264 into the test's folder; and the angle between directions and orientations.
#pragma once

#include <Eigen/Geometry>
#include <filesystem>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "app/bench/media.h"
#include "app/bench/track_clips.h"
#include "effects/coords.h"

namespace vdfx::app::testing {

struct CameraClip {
  std::filesystem::path path;
  std::vector<Eigen::Quaterniond> truth;  //!< per frame
};

/// The forest panorama seen along `path` as a w x w/2 H.264 clip (coverage 360) at 30 fps.
inline CameraClip write_camera_clip(const std::filesystem::path& file, bench::CameraPath path,
                                    int frames, int w) {
  CameraClip c{file, bench::camera_path(path, frames, 30.0)};
  const cv::Mat world = bench::world_panorama("forest", 2 * w);
  bench::encode_clip(file, w, w / 2, frames, 30,
                     [&](int i) { return bench::camera_view(world, c.truth[i], w, w / 2); });
  return c;
}

struct SubjectClip {
  std::filesystem::path path;
  std::vector<bench::SubjectPose> truth;  //!< per frame
};

/// The patch moving as `motion` says over the courtyard panorama (a still camera), w x w/2 H.264.
inline SubjectClip write_subject_clip(const std::filesystem::path& file,
                                      bench::SubjectMotion motion, int frames, int w) {
  SubjectClip c{file, bench::subject_path(motion, frames)};
  const cv::Mat world = bench::world_panorama("courtyard", w);
  const cv::Mat texture = bench::subject_texture();
  bench::encode_clip(file, w, w / 2, frames, 30,
                     [&](int i) { return bench::draw_subject(world, c.truth[i], texture); });
  return c;
}

}  // namespace vdfx::app::testing
