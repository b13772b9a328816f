/// @file
/// @brief An MP4 with a Camera Motion Metadata track, for the CAMM reader's tests: a clip's video
/// stream copied with libavformat beside a data stream of CAMM packets.
///
/// FFmpeg 5.1's MP4 muxer writes no 'camm' sample entry (a data stream tagged 'camm' is refused in
/// MP4, and MOV mode writes an empty sample description for it). It does write one for GoPro's
/// 'gpmd' metadata (AV_CODEC_ID_BIN_DATA): a plain SampleEntry, which is all CAMM's sample entry
/// is, in a 'meta' handler track, as CAMM asks. So the track is written as 'gpmd' and the two
/// four-character codes the muxer writes for it inside the 'moov' box (the sample entry and the
/// media header's box) are then renamed 'camm' in place: same length, no offset changes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io/libav_util.h"

namespace vdfx::test_media {

struct CammPacket {
  double time_s = 0.0;
  unsigned type = 0;  //!< 0: angle-axis, 2: gyroscope; others are written as zeros of their size
  std::array<float, 3> value{};
  int bytes = -1;  //!< payload bytes written (-1: the type's own size): a short one is damaged
};

inline std::vector<std::uint8_t> camm_bytes(const CammPacket& p) {
  const int sizes[] = {12, 8, 12, 12, 12, 24, 56, 12};
  const int size = p.bytes >= 0 ? p.bytes : (p.type < 8 ? sizes[p.type] : 12);
  std::vector<std::uint8_t> out(4 + static_cast<std::size_t>(size), 0);
  out[2] = static_cast<std::uint8_t>(p.type & 0xff);
  out[3] = static_cast<std::uint8_t>(p.type >> 8);
  if (p.type == 0 || p.type == 2)
    std::memcpy(out.data() + 4, p.value.data(), std::min<std::size_t>(12, out.size() - 4));
  return out;  // little-endian floats: this is an x86-64 build (docs/architecture.md)
}

/// Renames the muxer's 'gpmd' four-character codes inside the top-level 'moov' box to 'camm'.
inline void rename_gpmd_to_camm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::vector<char> d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  std::size_t at = 0, renamed = 0;
  while (at + 8 <= d.size()) {
    const auto b = [&](std::size_t i) {
      return static_cast<std::uint32_t>(static_cast<unsigned char>(d[at + i]));
    };
    const std::size_t size = (b(0) << 24) | (b(1) << 16) | (b(2) << 8) | b(3);
    if (size < 8 || at + size > d.size()) break;
    if (std::memcmp(&d[at + 4], "moov", 4) == 0)
      for (std::size_t i = at; i + 4 <= at + size; ++i)
        if (std::memcmp(&d[i], "gpmd", 4) == 0) {
          std::memcpy(&d[i], "camm", 4);
          ++renamed;
        }
    at += size;
  }
  EXPECT_EQ(renamed, 2u) << "the muxer's gpmd boxes in " << file;
  std::ofstream(file, std::ios::binary).write(d.data(), static_cast<std::streamsize>(d.size()));
}

/// `video`'s video stream copied into `out` (.mp4) with a CAMM track of `packets`.
inline void write_camm_clip(const std::filesystem::path& video, const std::filesystem::path& out,
                            const std::vector<CammPacket>& packets) {
  using namespace vdfx::io::av;
  std::string error;
  const InputPtr in = open_input(video.string(), error);
  ASSERT_TRUE(in) << error;
  AVFormatContext* raw = nullptr;
  ASSERT_GE(avformat_alloc_output_context2(&raw, nullptr, "mp4", out.string().c_str()), 0);
  std::unique_ptr<AVFormatContext, void (*)(AVFormatContext*)> oc(
      raw, [](AVFormatContext* c) { avformat_free_context(c); });
  AVStream* vin = in->streams[0];
  AVStream* vs = avformat_new_stream(raw, nullptr);
  avcodec_parameters_copy(vs->codecpar, vin->codecpar);
  vs->codecpar->codec_tag = 0;
  vs->time_base = vin->time_base;
  AVStream* ds = avformat_new_stream(raw, nullptr);
  ds->codecpar->codec_type = AVMEDIA_TYPE_DATA;
  ds->codecpar->codec_id = AV_CODEC_ID_BIN_DATA;
  ds->codecpar->codec_tag = MKTAG('g', 'p', 'm', 'd');
  ds->time_base = {1, 10000};
  ASSERT_GE(avio_open(&raw->pb, out.string().c_str(), AVIO_FLAG_WRITE), 0);
  ASSERT_GE(avformat_write_header(raw, nullptr), 0);
  PacketPtr pkt = make_packet();
  while (av_read_frame(in.get(), pkt.get()) >= 0) {
    if (pkt->stream_index == 0) {
      av_packet_rescale_ts(pkt.get(), vin->time_base, vs->time_base);
      pkt->stream_index = vs->index;
      ASSERT_GE(av_interleaved_write_frame(raw, pkt.get()), 0);
    }
    av_packet_unref(pkt.get());
  }
  for (std::size_t i = 0; i < packets.size(); ++i) {
    const CammPacket& p = packets[i];
    const std::vector<std::uint8_t> bytes = camm_bytes(p);
    ASSERT_GE(av_new_packet(pkt.get(), static_cast<int>(bytes.size())), 0);
    std::memcpy(pkt->data, bytes.data(), bytes.size());
    pkt->pts = pkt->dts = std::llround(p.time_s * 10000.0);
    // Each sample lasts until the next (the last 10 ms): the muxer's edit list ends the track at
    // the last sample's end, and a last sample of no duration would fall outside it.
    const double next = i + 1 < packets.size() ? packets[i + 1].time_s : p.time_s + 0.01;
    pkt->duration = std::max<std::int64_t>(1, std::llround((next - p.time_s) * 10000.0));
    pkt->stream_index = ds->index;
    ASSERT_GE(av_interleaved_write_frame(raw, pkt.get()), 0);
  }
  ASSERT_GE(av_write_trailer(raw), 0);
  avio_closep(&raw->pb);
  oc.reset();
  rename_gpmd_to_camm(out);
}

}  // namespace vdfx::test_media
