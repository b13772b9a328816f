/// @file
/// @brief Clips with a known truth for `vdfx track` (docs/anchors.md, "Measured"): a real
/// panorama (Blender's CC0 studio lights, package blender-data) seen by a camera turning along a
/// known path, and a textured patch moving over it along a known path (across the seam, over a
/// pole, growing as it comes closer, hidden for a while). Frames are rendered here and encoded with
/// x264 (encode_clip) so that the tracker sees real compression noise. Shared by `vdfx bench` and
/// the tests.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace vdfx::app::bench {

/// Blender's studio-light panorama NAME ("forest", "courtyard", "city", ...).
std::filesystem::path studio_light(const std::string& name);

/// The panorama NAME tone-mapped (io::load_image) to RGB 8-bit, area-averaged to width x width/2.
cv::Mat world_panorama(const std::string& name, int width);

/// What a camera at orientation q (its video frame's directions into the world) records of
/// `world` (RGB 8-bit equirect) as a w x h equirect spanning `coverage_deg` of azimuth: the pixel
/// of direction n shows the world at q n. Bilinear, the world's columns wrapped.
cv::Mat camera_view(const cv::Mat& world, const Eigen::Quaterniond& q, int w, int h,
                    int coverage_deg = 360);

enum class CameraPath {
  Turn,   //!< a full turn of yaw in 10 s, the horizon tilting gently (up to 8 degrees)
  Shake,  //!< a hand-held shake: three axes, 3 to 6 Hz, several degrees a frame at 30 fps
  Pan,    //!< a slow pan: a third of a turn over the clip, with a slow tilt
};
/// The true orientation at each of `frames` frames at `fps` (frame 0: identity).
std::vector<Eigen::Quaterniond> camera_path(CameraPath path, int frames, double fps);

/// The angle of the rotation between two orientations, degrees.
double rotation_error_deg(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

/// Estimated orientations against the truth, degrees: RMS and largest over the frames, and the
/// error at the last frame (the drift).
struct OrientationErrors {
  double rms = 0.0, max = 0.0, last = 0.0;
};
OrientationErrors orientation_errors(const std::vector<Eigen::Quaterniond>& estimated,
                                     const std::vector<Eigen::Quaterniond>& truth);

enum class SubjectMotion {
  Seam,      //!< along altitude 10 from azimuth 150 to -150, across the seam; 10 degrees wide
  Pole,      //!< over the north pole on a great circle (altitude 55 up, down at azimuth 180)
  Approach,  //!< nearly straight on, growing from 6 to 20 degrees, hidden for a fifth of the clip
  Turn,      //!< along the horizon from azimuth -30 to 30, turning 90 degrees in its own plane:
             //!< its look changes every frame, as a subject turning round does
};

/// Where the patch is at a frame: its centre direction and the patch's axes (columns: right, up,
/// towards the viewer), its width, and whether it is drawn.
struct SubjectPose {
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  double size_deg = 10.0;
  bool visible = true;
  Eigen::Vector3d centre() const { return -axes.col(2); }
};
std::vector<SubjectPose> subject_path(SubjectMotion motion, int frames);

/// A subject track against the truth: the angle between tracked and true centre over the frames
/// where the patch is drawn (degrees), hidden frames the tracker said it saw, drawn frames it said
/// it did not.
struct SubjectErrors {
  double rms = 0.0, max = 0.0;
  int visible = 0;
  std::vector<std::int64_t> hidden_seen;
  std::vector<std::int64_t> visible_lost;
};
/// `directions[f]` and `seen[f]`: the tracker's result at frame f.
SubjectErrors subject_errors(const std::vector<Eigen::Vector3d>& directions,
                             const std::vector<bool>& seen, const std::vector<SubjectPose>& truth);

/// The patch's texture: coloured blocks and fine noise, RGB 8-bit (a fixed seed).
cv::Mat subject_texture();

/// `background` (RGB 8-bit equirect, 360) with the textured square drawn where `pose` puts it
/// (seen from the centre: a flat square, side size_deg at its centre).
cv::Mat draw_subject(const cv::Mat& background, const SubjectPose& pose, const cv::Mat& texture);

}  // namespace vdfx::app::bench
