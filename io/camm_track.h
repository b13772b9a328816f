/// @file
/// @brief The records of a video's Camera Motion Metadata track (CAMM: Google's Street View
/// specification, an MP4 data track whose sample entry is 'camm'), read with libavformat, where
/// the track shows as a data stream tagged 'camm'. Each packet holds records of one type: a
/// little-endian uint16 reserved (0) and uint16 type, then the type's payload. Kept: type 0,
/// angle-axis orientation (float[3], radians: the rotation taking the camera's directions into the
/// device's world, M X), and type 2, gyroscope (float[3], rad/s about the camera's axes); the
/// other types (exposure, accelerometer, position, GPS, magnetic field) are counted and skipped.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace vdfx::io {

struct CammRecord {
  double time_s = 0.0;            //!< the packet's presentation time, seconds
  std::array<double, 3> value{};  //!< angle-axis (radians) or angular velocity (rad/s)
};

struct CammTrack {
  std::vector<CammRecord> angle_axis;  //!< type 0, in time order
  std::vector<CammRecord> gyro;        //!< type 2, in time order
  std::int64_t other_records = 0;      //!< records of the other types
};

/// The CAMM track of `video`, or nothing when the file has none (or is not a container libavformat
/// reads). A packet of a type this reader does not know is counted and skipped (the specification
/// puts one type in each packet). Throws io::InputError naming the file and the packet for a
/// record cut short or not finite.
std::optional<CammTrack> read_camm_track(const std::filesystem::path& video);

}  // namespace vdfx::io
