/// @file
/// @brief read_camm_track: the 'camm' data stream's packets parsed into records (camm_track.h).
#include "io/camm_track.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "io/input_error.h"
#include "io/libav_util.h"

namespace vdfx::io {
namespace {

/// Payload bytes of each record type of the specification (after the 4-byte header).
int payload_size(unsigned type) {
  switch (type) {
    case 0: return 12;  // angle_axis float[3]
    case 1: return 8;   // pixel exposure time, rolling shutter skew time: int32 each
    case 2: return 12;  // gyro float[3]
    case 3: return 12;  // acceleration float[3]
    case 4: return 12;  // position float[3]
    case 5: return 24;  // latitude, longitude, altitude: double each
    case 6: return 56;  // GPS time, fix type, position, accuracies, velocities
    case 7: return 12;  // magnetic field float[3]
    default: return -1;
  }
}

unsigned u16_le(const std::uint8_t* p) {
  return p[0] | (static_cast<unsigned>(p[1]) << 8);
}

float f32_le(const std::uint8_t* p) {
  const std::uint32_t bits = p[0] | (static_cast<std::uint32_t>(p[1]) << 8) |
                             (static_cast<std::uint32_t>(p[2]) << 16) |
                             (static_cast<std::uint32_t>(p[3]) << 24);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

/// Parses one packet's records into `out`.
void parse_packet(const AVPacket& pkt, double time_s, const std::string& where, CammTrack& out) {
  const std::uint8_t* p = pkt.data;
  int left = pkt.size;
  while (left >= 4) {
    const unsigned type = u16_le(p + 2);
    const int size = payload_size(type);
    if (size < 0) {  // a type after this reader's time: one type a packet, so skip the rest
      ++out.other_records;
      return;
    }
    if (left < 4 + size)
      throw InputError(where + ": a type " + std::to_string(type) + " record is cut short (" +
                       std::to_string(left - 4) + " of " + std::to_string(size) + " bytes)");
    if (type == 0 || type == 2) {
      CammRecord r{time_s, {f32_le(p + 4), f32_le(p + 8), f32_le(p + 12)}};
      for (const double v : r.value)
        if (!std::isfinite(v)) throw InputError(where + ": a value is not a finite number");
      (type == 0 ? out.angle_axis : out.gyro).push_back(r);
    } else {
      ++out.other_records;
    }
    p += 4 + size;
    left -= 4 + size;
  }
}

}  // namespace

std::optional<CammTrack> read_camm_track(const std::filesystem::path& video) {
  std::string error;
  const av::InputPtr in = av::open_input(video.string(), error);
  if (!in) return std::nullopt;
  int stream = -1;
  for (unsigned i = 0; i < in->nb_streams; ++i)
    if (in->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_DATA &&
        in->streams[i]->codecpar->codec_tag == MKTAG('c', 'a', 'm', 'm'))
      stream = static_cast<int>(i);
  if (stream < 0) return std::nullopt;
  const AVRational tb = in->streams[stream]->time_base;
  CammTrack out;
  av::PacketPtr pkt = av::make_packet();
  for (std::int64_t n = 0; av_read_frame(in.get(), pkt.get()) >= 0; av_packet_unref(pkt.get())) {
    if (pkt->stream_index != stream) continue;
    const std::int64_t pts = pkt->pts != AV_NOPTS_VALUE ? pkt->pts : pkt->dts;
    const std::string where = video.string() + ": CAMM track, packet " + std::to_string(n++);
    if (pts == AV_NOPTS_VALUE) throw InputError(where + ": has no timestamp");
    parse_packet(*pkt, static_cast<double>(pts) * av_q2d(tb), where, out);
  }
  const auto by_time = [](const CammRecord& a, const CammRecord& b) { return a.time_s < b.time_s; };
  std::stable_sort(out.angle_axis.begin(), out.angle_axis.end(), by_time);
  std::stable_sort(out.gyro.begin(), out.gyro.end(), by_time);
  return out;
}

}  // namespace vdfx::io
