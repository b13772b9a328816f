/// @file
/// @brief A clip whose camera turns, for the anchor measurements (`vdfx bench`'s
/// anchor.world_turn, the tests of anchors through render, eval and the headset): a real
/// panorama (Blender's CC0 interior.exr, the demo's hotel room) turned about the vertical axis
/// over the frames, the camera orientation a sidecar records for it (source "given"), and an
/// exposure keyframe on the room's window in the world frame.
#pragma once

#include <filesystem>
#include <opencv2/core.hpp>
#include <vector>

#include "effects/anchor.h"
#include "io/sidecar.h"

namespace vdfx::app::bench {

inline constexpr const char* kInteriorExr =
    "/usr/share/blender/datafiles/studiolights/world/interior.exr";
/// The room's window, a direction of the panorama (the world): where the demo sidecar
/// (app/demo/interior.vdfx.json) puts its exposure keyframe.
inline constexpr effects::Direction kRoomWindow{31.0, 5.0};
/// The window's exposure keyframe, and the one opposite it (0 stops: neutral).
inline constexpr double kWindowStops = -1.2;

/// q_f of a camera turned right by `deg` about the vertical: a direction of the video frame at
/// azimuth a is at azimuth a + deg in the world.
effects::Quat camera_yaw(double deg);
/// The camera of a turn of `turn_deg` over `frames` frames: frame f turned by turn_deg f / frames.
effects::CameraMotion turning_camera(int frames, double turn_deg);
/// The yaw of frame f of such a turn, degrees.
double turning_yaw_deg(int f, int frames, double turn_deg);
/// Where a world direction is in the video frame of a camera turned by `yaw_deg`.
effects::Direction video_direction(const effects::Direction& world, double yaw_deg);

/// interior.exr as vdfx reads it (tone-mapped, display-encoded CV_32FC3 RGB), area-resized to
/// width x width / 2. Throws io::InputError when the file is missing.
cv::Mat interior_panorama(int width);
/// The panorama as a camera turned by `yaw_deg` films it: each video column shows the world's
/// azimuth yaw_deg further right (columns blended linearly between their neighbours; a whole
/// number of columns is an exact shift).
cv::Mat turned_panorama(const cv::Mat& world, double yaw_deg);
/// Writes the turn as an H.264 clip (libx264, crf 16, 8 bits) of `frames` frames at `fps`.
void write_turning_clip(const std::filesystem::path& path, const cv::Mat& world, int frames,
                        double turn_deg, int fps);

/// The turning clip's sidecar: its camera (source "given") and an exposure of kWindowStops at
/// the window and 0 opposite it, both at frame 0 and fixed to `anchor` (world: the window;
/// video: today's behaviour, the keyframes fixed in the picture).
io::Sidecar turning_sidecar(const io::VideoInfo& video, const effects::CameraMotion& camera,
                            const effects::Anchor& anchor);

}  // namespace vdfx::app::bench
