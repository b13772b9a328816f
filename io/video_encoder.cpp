/// @file
/// @brief VideoEncoder on libavcodec/libavformat.
///
/// Spherical metadata: libavformat's MOV/MP4 muxer writes the Spherical Video V2 boxes (sv3d with
/// an equirectangular projection, st3d) from the stream's AV_PKT_DATA_SPHERICAL and
/// AV_PKT_DATA_STEREO3D side data, but only when the format context's strictness allows
/// "unofficial" extensions; Matroska writes its Projection element from the same side data.
/// Audio: packets are copied as they are, interleaved with the video by time (each audio packet
/// is written once the video has reached its time), so the muxer never holds the whole track.
#include "io/video_encoder.h"

#include <cerrno>
#include <cstring>
#include <stdexcept>

extern "C" {
#include <libavutil/display.h>
#include <libavutil/opt.h>
#include <libavutil/spherical.h>
#include <libavutil/stereo3d.h>
}

#include "io/input_error.h"
#include "io/libav_util.h"

namespace vdfx::io {
namespace {

/// Equirect projection, no yaw/pitch/roll; VR180: left and right bounds a quarter of the width
/// each (0.32 fixed point), which libavformat writes as the equi box's bounds.
void set_equirect(AVSphericalMapping& m, int coverage_deg) {
  m.projection = AV_SPHERICAL_EQUIRECTANGULAR;
  if (coverage_deg == 180) {
    m.projection = AV_SPHERICAL_EQUIRECTANGULAR_TILE;
    m.bound_left = m.bound_right = 0x40000000u;
  }
}

void set_stereo_mode(AVStereo3D& st3d, effects::StereoMode mode) {
  switch (mode) {
    case effects::StereoMode::Mono: st3d.type = AV_STEREO3D_2D; break;
    case effects::StereoMode::TopBottom: st3d.type = AV_STEREO3D_TOPBOTTOM; break;
    case effects::StereoMode::LeftRight: st3d.type = AV_STEREO3D_SIDEBYSIDE; break;
    case effects::StereoMode::RightLeft:
      st3d.type = AV_STEREO3D_SIDEBYSIDE;
      st3d.flags = AV_STEREO3D_FLAG_INVERT;
      break;
  }
}

/// A failure of the disk or file system under the output (full, over quota, read-only, an I/O
/// error): the user's OUT cannot be written there, which is exit 1, not a fault of vdfx.
bool is_storage_error(int r) {
  for (const int e : {ENOSPC, EDQUOT, EFBIG, EIO, EROFS, EACCES, EPERM, EPIPE, ENXIO, ESTALE})
    if (r == AVERROR(e)) return true;
  return false;
}

/// `out` is the name the user gave (the file written may be a temporary one beside it).
[[noreturn]] void write_failed(const std::string& out, const std::string& what, int r) {
  if (is_storage_error(r))
    throw InputError(out + ": cannot write the " + what + " (" + av::error_text(r) + ")");
  throw std::runtime_error("VideoEncoder: writing " + what + " failed: " + av::error_text(r));
}

AVRational q(Rational r) {
  return {static_cast<int>(r.num), static_cast<int>(r.den)};
}

AVPixelFormat pixel_format(const YcbcrInfo& y) {
  if (y.bit_depth != 8 && y.bit_depth != 10)
    throw std::invalid_argument("VideoEncoder: 8- or 10-bit pictures only");
  const bool deep = y.bit_depth == 10;
  if (y.log2_chroma_w == 1 && y.log2_chroma_h == 1)
    return deep ? AV_PIX_FMT_YUV420P10 : AV_PIX_FMT_YUV420P;
  if (y.log2_chroma_w == 1 && y.log2_chroma_h == 0)
    return deep ? AV_PIX_FMT_YUV422P10 : AV_PIX_FMT_YUV422P;
  if (y.log2_chroma_w == 0 && y.log2_chroma_h == 0)
    return deep ? AV_PIX_FMT_YUV444P10 : AV_PIX_FMT_YUV444P;
  throw std::invalid_argument("VideoEncoder: chroma subsampling must be 4:2:0, 4:2:2 or 4:4:4");
}

void tag_colour(AVCodecContext* c, const YcbcrInfo& y) {
  c->color_range = y.full_range ? AVCOL_RANGE_JPEG : AVCOL_RANGE_MPEG;
  switch (y.matrix) {
    case YcbcrMatrix::Bt601:
      c->colorspace = AVCOL_SPC_SMPTE170M;
      c->color_primaries = AVCOL_PRI_SMPTE170M;
      c->color_trc = AVCOL_TRC_SMPTE170M;
      break;
    case YcbcrMatrix::Bt709:
      c->colorspace = AVCOL_SPC_BT709;
      c->color_primaries = AVCOL_PRI_BT709;
      c->color_trc = AVCOL_TRC_BT709;
      break;
    case YcbcrMatrix::Bt2020:
      c->colorspace = AVCOL_SPC_BT2020_NCL;
      c->color_primaries = AVCOL_PRI_BT2020;
      c->color_trc = AVCOL_TRC_BT2020_10;
      break;
  }
  if (y.log2_chroma_h == 1)
    c->chroma_sample_location = y.chroma_y == 0.0 ? AVCHROMA_LOC_TOPLEFT : AVCHROMA_LOC_LEFT;
  else if (y.log2_chroma_w == 1)
    c->chroma_sample_location = AVCHROMA_LOC_LEFT;
}

void add_side_data(AVStream* st, AVPacketSideDataType type, void* data, std::size_t size) {
  if (!data) throw std::bad_alloc();
  if (av_stream_add_side_data(st, type, static_cast<std::uint8_t*>(data), size) < 0) {
    av_free(data);
    throw std::runtime_error("VideoEncoder: cannot attach stream side data");
  }
}

struct OutputCloser {
  void operator()(AVFormatContext* c) const {
    if (!c) return;
    if (c->pb && !(c->oformat->flags & AVFMT_NOFILE)) avio_closep(&c->pb);
    avformat_free_context(c);
  }
};

/// The audio streams of another file, copied packet by packet in time order.
class AudioCopier {
 public:
  AudioCopier(const std::filesystem::path& from, AVFormatContext* out,
              std::optional<AudioWindow> window)
      : window_(window) {
    std::string error;
    in_ = av::open_input(from.string(), error);
    if (!in_) throw InputError(from.string() + ": cannot read its audio (" + error + ")");
    map_.assign(in_->nb_streams, -1);
    for (unsigned i = 0; i < in_->nb_streams; ++i) {
      AVStream* s = in_->streams[i];
      if (s->codecpar->codec_type != AVMEDIA_TYPE_AUDIO) {
        s->discard = AVDISCARD_ALL;
        continue;
      }
      if (avformat_query_codec(out->oformat, s->codecpar->codec_id, FF_COMPLIANCE_NORMAL) != 1)
        throw InputError(from.string() + ": its " + avcodec_get_name(s->codecpar->codec_id) +
                         " audio cannot be copied into a " + out->oformat->name +
                         " file (choose an output name ending .mkv or .mov)");
      AVStream* o = avformat_new_stream(out, nullptr);
      if (!o || avcodec_parameters_copy(o->codecpar, s->codecpar) < 0)
        throw std::runtime_error("VideoEncoder: cannot add an audio stream");
      o->codecpar->codec_tag = 0;  // let the muxer choose its own tag for the codec
      o->time_base = s->time_base;
      o->disposition = s->disposition;
      av_dict_copy(&o->metadata, s->metadata, 0);
      map_[i] = o->index;
    }
    packet_ = av::make_packet();
  }

  bool has_streams() const {
    for (int m : map_)
      if (m >= 0) return true;
    return false;
  }

  /// Writes every audio packet whose time is at or before `until_seconds` (all: +infinity).
  /// `out_name`: the output's name for messages.
  void write_until(AVFormatContext* out, double until_seconds, const std::string& out_name) {
    while (!done_) {
      if (!pending_) {
        const int r = av_read_frame(in_.get(), packet_.get());
        if (r < 0) {
          done_ = true;
          return;
        }
        if (map_[static_cast<std::size_t>(packet_->stream_index)] < 0) {
          av_packet_unref(packet_.get());
          continue;
        }
        pending_ = true;
      }
      const AVStream* s = in_->streams[packet_->stream_index];
      const std::int64_t ts = packet_->pts != AV_NOPTS_VALUE ? packet_->pts : packet_->dts;
      const double t = ts == AV_NOPTS_VALUE ? 0.0 : static_cast<double>(ts) * av_q2d(s->time_base);
      if (t > until_seconds) return;
      pending_ = false;
      if (!keep(ts, s->time_base)) {
        av_packet_unref(packet_.get());
        continue;
      }
      AVStream* o = out->streams[map_[static_cast<std::size_t>(packet_->stream_index)]];
      if (window_) {
        const std::int64_t shift =
            av_rescale_q(window_->start, q(window_->time_base), s->time_base);
        if (packet_->pts != AV_NOPTS_VALUE) packet_->pts -= shift;
        if (packet_->dts != AV_NOPTS_VALUE) packet_->dts -= shift;
      }
      av_packet_rescale_ts(packet_.get(), s->time_base, o->time_base);
      packet_->stream_index = o->index;
      packet_->pos = -1;
      const int r = av_interleaved_write_frame(out, packet_.get());
      if (r < 0) write_failed(out_name, "audio", r);
    }
  }

 private:
  bool keep(std::int64_t ts, AVRational tb) const {
    if (!window_ || ts == AV_NOPTS_VALUE) return true;
    const AVRational wtb = q(window_->time_base);
    return av_compare_ts(ts, tb, window_->start, wtb) >= 0 &&
           (window_->end == INT64_MAX || av_compare_ts(ts, tb, window_->end, wtb) < 0);
  }

  std::optional<AudioWindow> window_;
  av::InputPtr in_;
  av::PacketPtr packet_;
  std::vector<int> map_;  //!< input stream -> output stream (-1: not copied)
  bool pending_ = false;
  bool done_ = false;
};

class LibavEncoder final : public VideoEncoder {
 public:
  LibavEncoder(const std::filesystem::path& path, const EncoderSettings& s)
      : settings_(s), report_name_((s.format_from.empty() ? path : s.format_from).string()) {
    av::limit_logs();
    if (s.width <= 0 || s.height <= 0) throw std::invalid_argument("VideoEncoder: no picture size");
    const std::string name = path.string();
    open_container(name);
    open_codec();
    add_video_stream();
    if (!s.copy_audio_from.empty()) {
      audio_ = std::make_unique<AudioCopier>(s.copy_audio_from, out_.get(), s.audio_window);
      if (!audio_->has_streams()) audio_.reset();
    }
    write_header(name);
    frame_ = av::make_frame();
    packet_ = av::make_packet();
    frame_->format = codec_->pix_fmt;
    frame_->width = codec_->width;
    frame_->height = codec_->height;
  }

  void write(const Picture& p, std::int64_t pts) override {
    if (finished_) throw std::logic_error("VideoEncoder::write after finish");
    if (!p.is_ycbcr() || p.width() != settings_.width || p.height() != settings_.height ||
        p.ycbcr.log2_chroma_w != settings_.ycbcr.log2_chroma_w ||
        p.ycbcr.log2_chroma_h != settings_.ycbcr.log2_chroma_h ||
        p.planes[0].depth() != (settings_.ycbcr.bit_depth > 8 ? CV_16U : CV_8U))
      throw std::invalid_argument(
          "VideoEncoder::write: picture does not match the encoder settings");
    // The encoder may still hold the previous buffer: a fresh one per frame.
    av_frame_unref(frame_.get());
    frame_->format = codec_->pix_fmt;
    frame_->width = codec_->width;
    frame_->height = codec_->height;
    if (av_frame_get_buffer(frame_.get(), 0) < 0) throw std::bad_alloc();
    for (int i = 0; i < 3; ++i) {
      const cv::Mat& plane = p.planes[static_cast<std::size_t>(i)];
      for (int y = 0; y < plane.rows; ++y)
        std::memcpy(frame_->data[i] + static_cast<std::ptrdiff_t>(y) * frame_->linesize[i],
                    plane.ptr(y), static_cast<std::size_t>(plane.cols) * plane.elemSize());
    }
    frame_->pts = pts;
    frame_->color_range = codec_->color_range;
    frame_->colorspace = codec_->colorspace;
    frame_->color_primaries = codec_->color_primaries;
    frame_->color_trc = codec_->color_trc;
    frame_->chroma_location = codec_->chroma_sample_location;
    send(frame_.get());
  }

  void finish() override {
    if (finished_) return;
    send(nullptr);
    if (audio_) audio_->write_until(out_.get(), 1e300, report_name_);
    int r = av_write_trailer(out_.get());
    finished_ = true;
    if (r < 0) write_failed(report_name_, "end of the video (its index)", r);
    // The last buffered bytes reach the file only here: a full disk may first show now.
    if (out_->pb && !(out_->oformat->flags & AVFMT_NOFILE)) {
      avio_flush(out_->pb);
      r = out_->pb->error;
      const int closed = avio_closep(&out_->pb);
      if (r >= 0) r = closed;
      if (r < 0) write_failed(report_name_, "video", r);
    }
  }

  Rational stream_time_base() const override {
    return {stream_->time_base.num, stream_->time_base.den};
  }

 private:
  /// The output's format context, its format from format_from's name (else the file's), the
  /// context named after the file really written: MP4's faststart pass reopens that name.
  void open_container(const std::string& name) {
    const std::string& format_name = report_name_;
    const AVOutputFormat* oformat = av_guess_format(nullptr, format_name.c_str(), nullptr);
    if (!oformat)
      throw InputError(format_name +
                       ": no container format for this file name (use .mp4, .mov or .mkv)");
    AVFormatContext* raw = nullptr;
    if (avformat_alloc_output_context2(&raw, oformat, nullptr, name.c_str()) < 0 || !raw)
      throw std::runtime_error("VideoEncoder: cannot set up a " + std::string(oformat->name) +
                               " file");
    out_.reset(raw);
    // Spherical Video V2 is an "unofficial" extension of ISO BMFF to libavformat.
    out_->strict_std_compliance = FF_COMPLIANCE_UNOFFICIAL;
  }

  /// The encoder, set up and opened with the settings' options; an option it does not know is
  /// an error, not ignored.
  void open_codec() {
    const EncoderSettings& s = settings_;
    const AVCodec* codec = avcodec_find_encoder_by_name(s.codec.c_str());
    if (!codec) throw InputError("no video encoder named '" + s.codec + "' in this FFmpeg");
    codec_.reset(avcodec_alloc_context3(codec));
    AVCodecContext* c = codec_.get();
    c->width = s.width;
    c->height = s.height;
    c->pix_fmt = pixel_format(s.ycbcr);
    c->framerate = q(s.frame_rate);
    c->time_base =
        s.time_base.num > 0 ? q(s.time_base) : AVRational{c->framerate.den, c->framerate.num};
    c->sample_aspect_ratio = {1, 1};
    c->thread_count = s.threads;
    if (s.gop > 0) c->gop_size = s.gop;
    if (s.max_b_frames >= 0) c->max_b_frames = s.max_b_frames;
    tag_colour(c, s.ycbcr);
    if (out_->oformat->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    AVDictionary* opts = nullptr;
    if (s.crf >= 0) av_dict_set(&opts, "crf", std::to_string(s.crf).c_str(), 0);
    if (!s.preset.empty()) av_dict_set(&opts, "preset", s.preset.c_str(), 0);
    for (const auto& [k, v] : s.codec_options) av_dict_set(&opts, k.c_str(), v.c_str(), 0);
    const int r = avcodec_open2(c, codec, &opts);
    std::string unused;
    for (const AVDictionaryEntry* e = nullptr;
         (e = av_dict_get(opts, "", e, AV_DICT_IGNORE_SUFFIX));)
      unused += std::string(unused.empty() ? "" : ", ") + e->key;
    av_dict_free(&opts);
    if (r < 0)
      throw InputError("cannot open the " + s.codec + " encoder for " + std::to_string(s.width) +
                       "x" + std::to_string(s.height) + " (" + av::error_text(r) + ")");
    if (!unused.empty())
      throw std::invalid_argument("VideoEncoder: " + s.codec + " does not know " + unused);
  }

  /// The video stream as the encoder describes it, with its spherical, stereo and display
  /// rotation side data.
  void add_video_stream() {
    const EncoderSettings& s = settings_;
    stream_ = avformat_new_stream(out_.get(), nullptr);
    if (!stream_) throw std::runtime_error("VideoEncoder: cannot add the video stream");
    stream_->time_base = codec_->time_base;
    stream_->avg_frame_rate = codec_->framerate;
    if (avcodec_parameters_from_context(stream_->codecpar, codec_.get()) < 0)
      throw std::runtime_error("VideoEncoder: cannot describe the video stream");
    if (s.spherical_equirect) {
      std::size_t size = 0;
      AVSphericalMapping* m = av_spherical_alloc(&size);
      if (m) set_equirect(*m, s.stereo.coverage_deg);
      add_side_data(stream_, AV_PKT_DATA_SPHERICAL, m, size);
    }
    // The stereo mode: beside the projection, or alone for a flat 3D video.
    if (s.spherical_equirect || s.stereo.stereo()) {
      AVStereo3D* st3d = av_stereo3d_alloc();
      if (st3d) set_stereo_mode(*st3d, s.stereo.mode);
      add_side_data(stream_, AV_PKT_DATA_STEREO3D, st3d, sizeof(AVStereo3D));
    }
    if (s.display_rotation_deg % 360 != 0) {
      auto* m = static_cast<std::int32_t*>(av_malloc(9 * sizeof(std::int32_t)));
      // av_display_rotation_get(av_display_rotation_set(a)) is -a, and players (the ffmpeg
      // command line among them) turn the picture clockwise by -get: so set(a) displays a turn of
      // a degrees clockwise.
      if (m) av_display_rotation_set(m, static_cast<double>(s.display_rotation_deg));
      add_side_data(stream_, AV_PKT_DATA_DISPLAYMATRIX, m, 9 * sizeof(std::int32_t));
    }
  }

  /// Opens the file (unless the format writes none) and writes the container's header.
  void write_header(const std::string& name) {
    int r = 0;
    if (!(out_->oformat->flags & AVFMT_NOFILE)) {
      r = avio_open(&out_->pb, name.c_str(), AVIO_FLAG_WRITE);
      if (r < 0)
        throw InputError(report_name_ + ": cannot open for writing (" + av::error_text(r) + ")");
    }
    AVDictionary* mux = nullptr;
    if (settings_.faststart) av_dict_set(&mux, "movflags", "+faststart", 0);
    r = avformat_write_header(out_.get(), &mux);
    av_dict_free(&mux);
    if (r < 0)
      throw InputError(report_name_ + ": cannot write the header (" + av::error_text(r) + ")");
  }

  void send(const AVFrame* f) {
    int r = avcodec_send_frame(codec_.get(), f);
    if (r < 0) throw std::runtime_error("VideoEncoder: encoding failed: " + av::error_text(r));
    while ((r = avcodec_receive_packet(codec_.get(), packet_.get())) == 0) {
      av_packet_rescale_ts(packet_.get(), codec_->time_base, stream_->time_base);
      packet_->stream_index = stream_->index;
      if (audio_) {
        const std::int64_t t = packet_->dts != AV_NOPTS_VALUE ? packet_->dts : packet_->pts;
        audio_->write_until(out_.get(), static_cast<double>(t) * av_q2d(stream_->time_base),
                            report_name_);
      }
      r = av_interleaved_write_frame(out_.get(), packet_.get());
      if (r < 0) write_failed(report_name_, "video", r);
    }
    if (r != AVERROR(EAGAIN) && r != AVERROR_EOF)
      throw std::runtime_error("VideoEncoder: encoding failed: " + av::error_text(r));
  }

  EncoderSettings settings_;
  std::string report_name_;  //!< the output as the user named it (format_from, else the path)
  std::unique_ptr<AVFormatContext, OutputCloser> out_;
  av::CodecPtr codec_;
  AVStream* stream_ = nullptr;
  av::FramePtr frame_;
  av::PacketPtr packet_;
  std::unique_ptr<AudioCopier> audio_;
  bool finished_ = false;
};

}  // namespace

std::unique_ptr<VideoEncoder> VideoEncoder::create(const std::filesystem::path& path,
                                                   const EncoderSettings& settings) {
  return std::make_unique<LibavEncoder>(path, settings);
}

std::vector<std::string> audio_copy_notes(const std::filesystem::path& from) {
  std::vector<std::string> notes;
  std::string error;
  const auto in = av::open_input(from.string(), error);
  if (!in) return notes;  // the copy itself reports an unreadable file
  for (unsigned i = 0; i < in->nb_streams; ++i) {
    const AVCodecParameters* par = in->streams[i]->codecpar;
    if (par->codec_type != AVMEDIA_TYPE_AUDIO) continue;
    const bool ambisonic = par->ch_layout.order == AV_CHANNEL_ORDER_AMBISONIC;
    if (!ambisonic && par->ch_layout.nb_channels != 4) continue;
    notes.push_back(from.string() + ": audio stream " + std::to_string(i) + " (" +
                    std::to_string(par->ch_layout.nb_channels) + " channels" +
                    (ambisonic ? ", ambisonic" : "") +
                    ") is copied with its channel layout, but this FFmpeg (libavformat " +
                    AV_STRINGIFY(LIBAVFORMAT_VERSION_MAJOR) + "." +
                    AV_STRINGIFY(LIBAVFORMAT_VERSION_MINOR) +
                    ") writes no spatial audio box (SA3D): a 360 player may play it as plain "
                    "4-channel audio");
  }
  return notes;
}

}  // namespace vdfx::io
