/// @file
/// @brief Video decoding with libavformat/libavcodec: threaded decoding, frame-exact seeking by
/// presentation timestamp, frames handed over in their native Y'CbCr layout without a copy.
///
/// Frame index: at open the demuxer reads every packet of the video stream once (no decoding)
/// and keeps their presentation timestamps, sorted: frame i is the i-th timestamp. That gives the
/// exact frame count of any container, the frame rate from the actual spacing (constant or not),
/// and a decoded frame's index from its own timestamp, whatever the B-frame reordering.
///
/// Seeking: av_seek_frame to the target's timestamp (AVSEEK_FLAG_BACKWARD: the key frame at or
/// before it), flush, decode forward and drop frames before the target. When the first frame the
/// decoder returns is already past the target (a demuxer that landed late, open-GOP leading
/// pictures), the seek is retried from further back, finally from the start. Files without
/// timestamps (raw elementary streams) are numbered by output order and seek by decoding from the
/// start.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
#include <libavutil/display.h>
#include <libswscale/swscale.h>
}

#include "io/frame_decoder.h"
#include "io/image_source.h"
#include "io/input_error.h"
#include "io/libav_util.h"
#include "io/ycbcr.h"

namespace vdfx::io {
namespace {

YcbcrMatrix matrix_of(AVColorSpace cs, int width, int height) {
  switch (cs) {
    case AVCOL_SPC_BT709: return YcbcrMatrix::Bt709;
    case AVCOL_SPC_BT470BG:
    case AVCOL_SPC_SMPTE170M:
    case AVCOL_SPC_FCC: return YcbcrMatrix::Bt601;
    case AVCOL_SPC_BT2020_NCL:
    case AVCOL_SPC_BT2020_CL: return YcbcrMatrix::Bt2020;
    default:
      // Untagged: what players assume (HD and larger BT.709, SD BT.601). docs/inputs.md.
      return (width >= 1280 || height > 576) ? YcbcrMatrix::Bt709 : YcbcrMatrix::Bt601;
  }
}

/// Luma position of chroma sample 0 for a chroma location (ITU-T H.273 chroma_sample_loc_type).
void siting_of(AVChromaLocation loc, int log2_w, int log2_h, double& x, double& y) {
  const double cx = log2_w ? 0.5 * ((1 << log2_w) - 1) : 0.0;  // centred between luma samples
  const double cy = log2_h ? 0.5 * ((1 << log2_h) - 1) : 0.0;
  const double ey = log2_h ? (1 << log2_h) - 1 : 0.0;  // on the last luma row of the pair
  switch (loc) {
    case AVCHROMA_LOC_CENTER:
      x = cx;
      y = cy;
      break;
    case AVCHROMA_LOC_TOPLEFT:
      x = 0.0;
      y = 0.0;
      break;
    case AVCHROMA_LOC_TOP:
      x = cx;
      y = 0.0;
      break;
    case AVCHROMA_LOC_BOTTOMLEFT:
      x = 0.0;
      y = ey;
      break;
    case AVCHROMA_LOC_BOTTOM:
      x = cx;
      y = ey;
      break;
    case AVCHROMA_LOC_LEFT:
    default:
      x = 0.0;
      y = cy;
      break;  // MPEG-2 / H.264 / HEVC default
  }
}

/// Planar Y'CbCr that can be handed over as is: three planes in order, no bit packing, native
/// (little-endian) samples of up to 16 bits.
bool is_plain_planar_ycbcr(const AVPixFmtDescriptor* d) {
  if (!d || (d->flags & (AV_PIX_FMT_FLAG_RGB | AV_PIX_FMT_FLAG_PAL | AV_PIX_FMT_FLAG_BITSTREAM |
                         AV_PIX_FMT_FLAG_HWACCEL | AV_PIX_FMT_FLAG_BE | AV_PIX_FMT_FLAG_FLOAT)))
    return false;
  if (!(d->flags & AV_PIX_FMT_FLAG_PLANAR) || d->nb_components < 3) return false;
  const int depth = d->comp[0].depth;
  if (depth > 16) return false;
  for (int i = 0; i < 3; ++i) {
    const AVComponentDescriptor& c = d->comp[i];
    if (c.plane != i || c.shift != 0 || c.offset != 0 || c.depth != depth ||
        c.step != (depth > 8 ? 2 : 1))
      return false;
  }
  return true;
}

bool is_jpeg_range_format(AVPixelFormat f) {
  return f == AV_PIX_FMT_YUVJ420P || f == AV_PIX_FMT_YUVJ422P || f == AV_PIX_FMT_YUVJ444P ||
         f == AV_PIX_FMT_YUVJ440P || f == AV_PIX_FMT_YUVJ411P;
}

/// Display rotation, clockwise degrees in {0, 90, 180, 270}, from the stream's display matrix.
int display_rotation(const AVStream* st) {
  size_t size = 0;
  const auto* m = reinterpret_cast<const std::int32_t*>(
      av_stream_get_side_data(st, AV_PKT_DATA_DISPLAYMATRIX, &size));
  if (!m || size < 9 * sizeof(std::int32_t)) return 0;
  const double ccw = av_display_rotation_get(m);  // the matrix rotates counter-clockwise
  if (std::isnan(ccw)) return 0;
  const long cw = std::lround(-ccw / 90.0) * 90;
  return static_cast<int>(((cw % 360) + 360) % 360);
}

/// Rotates a picture clockwise by 90/180/270 degrees (planes and chroma siting together).
void rotate_picture(Picture& p, int cw) {
  if (cw == 0) return;
  const int code = cw == 90    ? cv::ROTATE_90_CLOCKWISE
                   : cw == 180 ? cv::ROTATE_180
                               : cv::ROTATE_90_COUNTERCLOCKWISE;
  if (!p.is_ycbcr()) {
    cv::Mat r;
    cv::rotate(p.rgb, r, code);
    p.rgb = r;
    p.owner.reset();
    return;
  }
  YcbcrInfo& c = p.ycbcr;
  const int w = p.planes[0].cols, h = p.planes[0].rows;
  const int cw_n = p.planes[1].cols, ch_n = p.planes[1].rows;
  const double sx = 1 << c.log2_chroma_w, sy = 1 << c.log2_chroma_h;
  // Where chroma sample 0 lands after the turn (the chroma grid turns with the luma grid).
  const double flip_x = (w - 1) - sx * (cw_n - 1) - c.chroma_x;
  const double flip_y = (h - 1) - sy * (ch_n - 1) - c.chroma_y;
  YcbcrInfo n = c;
  if (cw == 180) {
    n.chroma_x = flip_x;
    n.chroma_y = flip_y;
  } else {
    std::swap(n.log2_chroma_w, n.log2_chroma_h);
    n.chroma_x = cw == 90 ? flip_y : c.chroma_y;
    n.chroma_y = cw == 90 ? c.chroma_x : flip_x;
  }
  for (cv::Mat& plane : p.planes) {
    cv::Mat r;
    cv::rotate(plane, r, code);
    plane = r;
  }
  c = n;
  p.owner.reset();  // the planes are copies now
}

class LibavDecoder final : public FrameDecoder {
 public:
  LibavDecoder(const std::filesystem::path& path, const DecoderOptions& options)
      : options_(options), name_(path.string()) {
    open_input_and_codec();
    build_index();
    open_input_and_codec();  // back to the start after the index scan
    const AVStream* st = fmt_->streams[stream_];
    props_.path = path;
    props_.backend = "libav";
    props_.codec = avcodec_get_name(st->codecpar->codec_id);
    props_.frames = static_cast<std::int64_t>(pts_.empty() ? packet_count_ : pts_.size());
    props_.declared_frames = st->nb_frames;
    props_.rotation_deg = display_rotation(st);
    props_.stereo_tags = read_stereo_tags(st, name_);
    props_.time_base = {st->time_base.num, st->time_base.den};
    if (st->codecpar->color_trc != AVCOL_TRC_UNSPECIFIED) {
      if (const char* name = av_color_transfer_name(st->codecpar->color_trc))
        props_.transfer = name;
    }
    if (props_.frames < 1)
      throw InputError(name_ +
                       ": the video stream holds no frames (empty or cut before the first)");
    set_frame_rate(st);
    // Fail now, with a clear message, rather than on the decode thread later.
    Picture first;
    if (read_picture(first) != DecodeStatus::Ok)
      throw InputError(name_ + ": cannot decode the first frame (corrupt or unsupported " +
                       props_.codec + " stream)");
    check_frame_size(name_, first.width(), first.height());
    if (first.is_ycbcr()) props_.bit_depth = first.ycbcr.bit_depth;
    props_.width = first.width();
    props_.height = first.height();
    held_ = std::move(first);
    held_index_ = 0;
    next_ = 0;
  }

  const VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return next_; }

  std::optional<std::int64_t> timestamp(std::int64_t index) const override {
    if (pts_.empty() || index < 0 || index >= static_cast<std::int64_t>(pts_.size()))
      return std::nullopt;
    return pts_[static_cast<std::size_t>(index)];
  }

  void seek(std::int64_t index) override {
    if (index < 0 || index >= props_.frames)
      throw std::out_of_range("frame " + std::to_string(index) + " is outside the video (0.." +
                              std::to_string(props_.frames - 1) + ")");
    if (index == next_) return;
    if (index > next_ && index - next_ <= options_.max_forward_grab) {
      next_ = index;  // read() decodes forward and drops what lies before
      return;
    }
    seek_file(index, 0);
  }

  DecodeStatus read(cv::Mat& out) override {
    Picture p;
    const DecodeStatus s = read_picture(p);
    if (s == DecodeStatus::Ok) out = to_rgb(p, options_.format);
    return s;
  }

  DecodeStatus read_picture(Picture& out) override {
    if (next_ >= props_.frames) return DecodeStatus::End;
    while (true) {
      if (held_index_ >= 0) {
        if (held_index_ == next_) {
          out = std::move(held_);
          held_ = Picture{};
          held_index_ = -1;
          ++next_;
          return DecodeStatus::Ok;
        }
        if (held_index_ > next_) {
          ++next_;  // frame next_ never came out of the decoder
          return DecodeStatus::Error;
        }
        held_ = Picture{};  // before the wanted frame: dropped
        held_index_ = -1;
      }
      const int r = avcodec_receive_frame(codec_.get(), frame_.get());
      if (r == 0) {
        const std::int64_t idx = index_of(frame_.get());
        if (seek_target_ >= 0 && idx >= 0) {
          if (idx > seek_target_ && !from_start_) {
            av_frame_unref(frame_.get());
            retry_seek();  // landed after the target: go further back
            continue;
          }
          seek_target_ = -1;
        }
        if (idx >= next_) {
          held_ = make_picture(frame_.get());
          held_index_ = idx;
        }  // else: pre-roll after a seek, a forward skip, or not a frame of the index
        av_frame_unref(frame_.get());
        continue;
      }
      if (r == AVERROR_EOF) {
        // Drained: nothing more comes. A file cut short ends here (VideoSource reports it).
        seek_target_ = -1;
        return DecodeStatus::End;
      }
      if (r != AVERROR(EAGAIN)) return fail_frame();
      if (eof_sent_) return DecodeStatus::End;  // flushed yet not at EOF: never spin
      feed_packet();
    }
  }

 private:
  void open_input_and_codec() {
    std::string error;
    fmt_ = av::open_input(name_, error);
    if (!fmt_)
      throw InputError(name_ + ": cannot open as a video (" + error +
                       "): corrupt, truncated or not a media file");
    const AVCodec* dec = nullptr;
    const int s = av_find_best_stream(fmt_.get(), AVMEDIA_TYPE_VIDEO, -1, -1, &dec, 0);
    if (s == AVERROR_STREAM_NOT_FOUND) throw InputError(name_ + ": has no video stream");
    if (s < 0 || !dec) {
      const AVCodecID id = s >= 0 ? fmt_->streams[s]->codecpar->codec_id : AV_CODEC_ID_NONE;
      throw InputError(name_ + ": no decoder for its video codec (" + avcodec_get_name(id) + ")");
    }
    stream_ = s;
    // The size limit (docs/reliability.md) before the decoder allocates anything for the frames.
    const AVCodecParameters* par = fmt_->streams[s]->codecpar;
    if (par->width > 0 && par->height > 0) check_frame_size(name_, par->width, par->height);
    for (unsigned i = 0; i < fmt_->nb_streams; ++i)
      if (static_cast<int>(i) != stream_) fmt_->streams[i]->discard = AVDISCARD_ALL;
    codec_.reset(avcodec_alloc_context3(dec));
    if (!codec_ || avcodec_parameters_to_context(codec_.get(), fmt_->streams[s]->codecpar) < 0)
      throw InputError(name_ + ": cannot set up the " + dec->name + " decoder");
    codec_->thread_count = options_.threads;  // 0: libavcodec picks one per core
    codec_->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
    codec_->pkt_timebase = fmt_->streams[s]->time_base;
    const int r = avcodec_open2(codec_.get(), dec, nullptr);
    if (r < 0)
      throw InputError(name_ + ": cannot open the " + dec->name + " decoder (" + av::error_text(r) +
                       ")");
    if (!frame_) frame_ = av::make_frame();
    if (!packet_) packet_ = av::make_packet();
    eof_sent_ = false;
    held_ = Picture{};
    held_index_ = -1;
    out_count_ = 0;
  }

  /// Reads every packet of the video stream once: timestamps (presentation order) and count.
  void build_index() {
    bool all_timed = true;
    while (true) {
      const int r = av_read_frame(fmt_.get(), packet_.get());
      if (r < 0) break;  // end of file, or a cut or damaged tail: the frames so far are the video
      if (packet_->stream_index == stream_ && !(packet_->flags & AV_PKT_FLAG_DISCARD)) {
        ++packet_count_;
        if (packet_->pts == AV_NOPTS_VALUE)
          all_timed = false;
        else
          pts_.push_back(packet_->pts);
      }
      av_packet_unref(packet_.get());
    }
    std::sort(pts_.begin(), pts_.end());
    const bool unique = std::adjacent_find(pts_.begin(), pts_.end()) == pts_.end();
    if (!all_timed || !unique) pts_.clear();  // numbered by output order instead
  }

  void set_frame_rate(const AVStream* st) {
    const AVRational tb = st->time_base;
    if (pts_.size() >= 2) {
      std::int64_t lo = INT64_MAX, hi = 0;
      for (std::size_t i = 1; i < pts_.size(); ++i) {
        const std::int64_t d = pts_[i] - pts_[i - 1];
        lo = std::min(lo, d);
        hi = std::max(hi, d);
      }
      // One tick of jitter is timestamp rounding (e.g. 30000/1001 in a 1/1000 time base).
      props_.variable_rate = hi - lo > 1;
      const std::int64_t span = pts_.back() - pts_.front();
      if (!props_.variable_rate && hi == lo) {
        props_.fps = reduce(tb.den, lo * tb.num);
        return;
      }
      if (span > 0) {
        const std::int64_t n = static_cast<std::int64_t>(pts_.size()) - 1;
        if (!props_.variable_rate && st->r_frame_rate.num > 0 && st->r_frame_rate.den > 0 &&
            std::abs(av_q2d(st->r_frame_rate) * av_q2d(tb) * static_cast<double>(span) / n - 1.0) <
                1e-3) {
          props_.fps = reduce(st->r_frame_rate.num, st->r_frame_rate.den);
          return;
        }
        props_.fps =
            fps_to_rational(static_cast<double>(n) / (static_cast<double>(span) * av_q2d(tb)));
        return;
      }
    }
    AVRational r = st->avg_frame_rate.num > 0 ? st->avg_frame_rate : st->r_frame_rate;
    if (r.num <= 0 || r.den <= 0)
      throw InputError(
          name_ + ": the video declares no frame rate and has too few timestamps to measure one");
    props_.fps = reduce(r.num, r.den);
  }

  static Rational reduce(std::int64_t num, std::int64_t den) {
    const std::int64_t g = std::gcd(num, den);
    return {num / g, den / g};
  }

  /// The frame's index: its timestamp's place in the index (-1: not a frame of it), or its
  /// output order since the start for files without timestamps.
  std::int64_t index_of(const AVFrame* f) {
    const std::int64_t n = out_count_++;
    if (pts_.empty()) return n;
    const std::int64_t t =
        f->best_effort_timestamp != AV_NOPTS_VALUE ? f->best_effort_timestamp : f->pts;
    const auto it = std::lower_bound(pts_.begin(), pts_.end(), t);
    if (t == AV_NOPTS_VALUE || it == pts_.end() || *it != t) return -1;
    return it - pts_.begin();
  }

  /// The frame as a Picture: the decoder's planes themselves when they are plain planar Y'CbCr
  /// (the Picture keeps a reference to the frame), else converted by swscale.
  Picture make_picture(const AVFrame* f) {
    Picture p;
    const auto fmt = static_cast<AVPixelFormat>(f->format);
    const AVPixFmtDescriptor* d = av_pix_fmt_desc_get(fmt);
    const bool positive = f->linesize[0] > 0 && f->linesize[1] > 0 && f->linesize[2] > 0;
    if (is_plain_planar_ycbcr(d) && positive) {
      AVFrame* ref = av_frame_clone(f);
      if (!ref) throw std::bad_alloc();
      p.owner = std::shared_ptr<const void>(ref, [](const void* q) {
        AVFrame* fr = const_cast<AVFrame*>(static_cast<const AVFrame*>(q));
        av_frame_free(&fr);
      });
      YcbcrInfo& c = p.ycbcr;
      c.bit_depth = d->comp[0].depth;
      c.log2_chroma_w = d->log2_chroma_w;
      c.log2_chroma_h = d->log2_chroma_h;
      c.full_range = f->color_range == AVCOL_RANGE_JPEG || is_jpeg_range_format(fmt);
      c.matrix = matrix_of(f->colorspace, f->width, f->height);
      AVChromaLocation loc = f->chroma_location;
      if (loc == AVCHROMA_LOC_UNSPECIFIED && is_jpeg_range_format(fmt)) loc = AVCHROMA_LOC_CENTER;
      siting_of(loc, c.log2_chroma_w, c.log2_chroma_h, c.chroma_x, c.chroma_y);
      const int type = c.bit_depth > 8 ? CV_16UC1 : CV_8UC1;
      for (int i = 0; i < 3; ++i) {
        const int w = i ? AV_CEIL_RSHIFT(f->width, c.log2_chroma_w) : f->width;
        const int h = i ? AV_CEIL_RSHIFT(f->height, c.log2_chroma_h) : f->height;
        p.planes[static_cast<std::size_t>(i)] =
            cv::Mat(h, w, type, ref->data[i], static_cast<std::size_t>(ref->linesize[i]));
      }
    } else {
      // RGB codecs, grey, palettes, packed or semi-planar Y'CbCr: one conversion to RGB24.
      sws_.reset(sws_getCachedContext(
          sws_.release(), f->width, f->height, fmt, f->width, f->height, AV_PIX_FMT_RGB24,
          SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr, nullptr));
      if (!sws_)
        throw std::runtime_error(std::string("no conversion from ") + (d ? d->name : "?") +
                                 " to RGB");
      const bool full = f->color_range == AVCOL_RANGE_JPEG || is_jpeg_range_format(fmt);
      const int cs = f->colorspace == AVCOL_SPC_UNSPECIFIED ? SWS_CS_DEFAULT : f->colorspace;
      sws_setColorspaceDetails(sws_.get(), sws_getCoefficients(cs), full,
                               sws_getCoefficients(SWS_CS_DEFAULT), 1, 0, 1 << 16, 1 << 16);
      p.rgb.create(f->height, f->width, CV_8UC3);
      std::uint8_t* dst[4] = {p.rgb.data, nullptr, nullptr, nullptr};
      int dst_stride[4] = {static_cast<int>(p.rgb.step), 0, 0, 0};
      sws_scale(sws_.get(), f->data, f->linesize, 0, f->height, dst, dst_stride);
    }
    rotate_picture(p, props_.rotation_deg);
    return p;
  }

  void feed_packet() {
    while (true) {
      const int r = av_read_frame(fmt_.get(), packet_.get());
      if (r < 0) {
        // End of file, or a read error in a cut file: drain the decoder and end there.
        avcodec_send_packet(codec_.get(), nullptr);
        eof_sent_ = true;
        return;
      }
      if (packet_->stream_index != stream_) {
        av_packet_unref(packet_.get());
        continue;
      }
      const int s = avcodec_send_packet(codec_.get(), packet_.get());
      av_packet_unref(packet_.get());
      // A damaged packet is dropped; its frame shows up as missing (read() reports Error).
      (void)s;
      return;
    }
  }

  /// The decoder failed outright on this frame: report it and move past it.
  DecodeStatus fail_frame() {
    ++next_;
    return DecodeStatus::Error;
  }

  void seek_file(std::int64_t index, std::int64_t back) {
    held_ = Picture{};
    held_index_ = -1;
    next_ = index;
    seek_target_ = index;
    seek_back_ = back;
    from_start_ = false;
    const std::int64_t at = std::max<std::int64_t>(0, index - back);
    if (pts_.empty() || at == 0) {
      rewind();
      return;
    }
    const int r = av_seek_frame(fmt_.get(), stream_, pts_[static_cast<std::size_t>(at)],
                                AVSEEK_FLAG_BACKWARD);
    if (r < 0) {
      rewind();
      return;
    }
    avcodec_flush_buffers(codec_.get());
    eof_sent_ = false;
    out_count_ = -1;  // unknown after a seek; only used without timestamps, which rewind
  }

  void retry_seek() {
    const std::int64_t back = seek_back_ == 0 ? 16 : seek_back_ * 4;
    seek_file(seek_target_, back);
  }

  /// Back to frame 0 exactly: reopened, so output-order numbering starts again too.
  void rewind() {
    open_input_and_codec();
    from_start_ = true;
  }

  DecoderOptions options_;
  std::string name_;
  VideoProperties props_;
  av::InputPtr fmt_;
  av::CodecPtr codec_;
  av::FramePtr frame_;
  av::PacketPtr packet_;
  struct SwsFree {
    void operator()(SwsContext* c) const { sws_freeContext(c); }
  };
  std::unique_ptr<SwsContext, SwsFree> sws_;
  int stream_ = -1;
  std::vector<std::int64_t> pts_;  //!< presentation timestamps, sorted: frame i is pts_[i]
  std::int64_t packet_count_ = 0;
  std::int64_t next_ = 0;
  std::int64_t out_count_ = 0;  //!< frames output since the (re)open
  Picture held_;                //!< a decoded frame not handed out yet
  std::int64_t held_index_ = -1;
  std::int64_t seek_target_ = -1;  //!< frame a seek is heading for (retries while undershot)
  std::int64_t seek_back_ = 0;
  bool from_start_ = false;
  bool eof_sent_ = false;
};

}  // namespace

std::unique_ptr<FrameDecoder> create_libav_decoder(const std::filesystem::path& path,
                                                   const DecoderOptions& options) {
  return std::make_unique<LibavDecoder>(path, options);
}

}  // namespace vdfx::io
