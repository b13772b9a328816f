/// @file
/// @brief Video sources: properties, frame-exact seeks, loop, pause, decode errors, truncated and
/// missing files. Videos are generated at runtime with FFmpeg's libraries (tests/media_clips.h;
/// H.264 with B-frames unless said otherwise); each frame carries its index as 8 black/white
/// stripes, so a test can read back which frame it got.
#include "io/video_source.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <set>
#include <thread>

#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/ycbcr.h"
#include "io_test_util.h"
#include "tests/media_clips.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr int kW = 128, kH = 64;

using test_media::coded_frame;
using testing::temp_dir;

/// The stripes of a decoded picture (converted on the CPU, the reference path).
int frame_code(const Picture& p) {
  return test_media::frame_code(to_rgb(p, PixelFormat::Rgb8));
}

/// An H.264 MP4 (B-frames, key frame every `gop`, 0: x264's default of 250).
fs::path write_video(const fs::path& dir, const std::string& name, int frames,
                     io::Rational fps = {24, 1}, int gop = 12) {
  test_media::ClipSpec c;
  c.frames = frames;
  c.fps = fps;
  c.gop = gop;
  return test_media::write_clip(dir / name, c);
}

/// An MJPEG AVI written by OpenCV's videoio: a file another tool made.
fs::path write_opencv_mjpeg(const fs::path& dir, const std::string& name, int frames) {
  const fs::path p = dir / name;
  cv::VideoWriter w(p.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 24.0,
                    cv::Size(kW, kH));
  if (!w.isOpened()) ADD_FAILURE() << "cannot write " << p << " with this OpenCV";
  cv::Mat bgr;
  for (int i = 0; i < frames; ++i) {
    cv::cvtColor(coded_frame(i), bgr, cv::COLOR_RGB2BGR);
    w.write(bgr);
  }
  w.release();
  return p;
}

/// Warnings arrive on the decode thread: collected under a lock.
std::mutex warnings_mutex;

VideoSourceOptions quiet(std::vector<std::string>* warnings = nullptr) {
  VideoSourceOptions o;
  o.on_warning = [warnings](const std::string& w) {
    std::lock_guard lock(warnings_mutex);
    if (warnings) warnings->push_back(w);
  };
  return o;
}

TEST(VideoSource, PropertiesAndSequentialFrames) {
  const auto dir = temp_dir("video_seq");
  const auto p = write_video(dir, "a.mp4", 30, {25, 1});
  auto src = VideoSource::open(p, quiet());
  const VideoProperties& pr = src->properties();
  EXPECT_EQ(pr.frames, 30);
  EXPECT_EQ(pr.width, kW);
  EXPECT_EQ(pr.height, kH);
  EXPECT_FALSE(pr.is_still);
  EXPECT_EQ(pr.fps, (Rational{25, 1}));
  for (int i = 0; i < 30; ++i) {
    const auto f = src->frame_at(i, 5s);
    ASSERT_TRUE(f) << i;
    EXPECT_EQ(f->index, i);
    EXPECT_EQ(frame_code(f->picture), i);
    // Handed over as decoded: Y'CbCr planes in the decoder's own buffers, nothing converted.
    ASSERT_TRUE(f->picture.is_ycbcr());
    EXPECT_EQ(f->picture.planes[0].type(), CV_8UC1);
    EXPECT_EQ(f->picture.planes[1].size(), cv::Size(kW / 2, kH / 2));
    EXPECT_TRUE(f->picture.owner);
  }
  EXPECT_EQ(src->stats().decode_errors, 0);
}

/// Seeks in an order that jumps back, forward far, forward near, and repeats.
const std::int64_t kSeekOrder[] = {40, 3, 3, 47, 0, 25, 24, 26, 10, 46, 1, 33};

TEST(VideoSource, FrameAtAfterJumpsIsExact) {
  const auto dir = temp_dir("video_seek");
  // B-frames with a short and a long GOP (one key frame: every seek decodes from frame 0), and a
  // file another tool wrote.
  const fs::path files[] = {write_video(dir, "gop12.mp4", 48, {24, 1}, 12),
                            write_video(dir, "gop300.mp4", 48, {24, 1}, 300),
                            write_opencv_mjpeg(dir, "opencv.avi", 48)};
  for (const fs::path& p : files) {
    auto src = VideoSource::open(p, quiet());
    for (const std::int64_t k : kSeekOrder) {
      const auto f = src->frame_at(k, 5s);
      ASSERT_TRUE(f) << p << " " << k;
      EXPECT_EQ(f->index, k);
      EXPECT_EQ(frame_code(f->picture), k) << p;
    }
    // An explicit seek, then the frame.
    src->seek(17);
    const auto f = src->frame_at(17, 5s);
    ASSERT_TRUE(f);
    EXPECT_EQ(frame_code(f->picture), 17);
  }
}

TEST(VideoSource, LoopWrapsWithoutASeekAndEndClampsWithout) {
  const auto dir = temp_dir("video_loop");
  const auto p = write_video(dir, "a.mp4", 12);
  {
    VideoSourceOptions o = quiet();
    o.loop = true;
    auto src = VideoSource::open(p, o);
    ASSERT_TRUE(src->frame_at(9, 5s));
    const std::int64_t seeks = src->stats().seeks;
    for (const std::int64_t k : {10, 11, 0, 1, 2, 3, 4}) {
      const auto f = src->frame_at(k, 5s);
      ASSERT_TRUE(f) << k;
      EXPECT_EQ(f->index, k);
      EXPECT_EQ(frame_code(f->picture), k);
    }
    // The wrap came from the decoder looping, not from a seek the consumer forced.
    EXPECT_EQ(src->stats().seeks, seeks);
  }
  {
    auto src = VideoSource::open(p, quiet());
    ASSERT_TRUE(src->frame_at(11, 5s));
    const auto f = src->frame_at(100, 5s);  // past the end: the newest frame <= 100
    ASSERT_TRUE(f);
    EXPECT_EQ(f->index, 11);
    EXPECT_FALSE(src->stats().ended_early);
  }
}

TEST(VideoSource, PausedDecodesOnlyWhatIsAskedFor) {
  const auto dir = temp_dir("video_pause");
  const auto p = write_video(dir, "a.mp4", 40);
  auto src = VideoSource::open(p, quiet());
  src->set_paused(true);
  EXPECT_TRUE(src->paused());
  const auto f = src->frame_at(20, 5s);
  ASSERT_TRUE(f);
  EXPECT_EQ(frame_code(f->picture), 20);
  const std::int64_t decoded = src->stats().decoded;
  std::this_thread::sleep_for(50ms);
  EXPECT_EQ(src->stats().decoded, decoded);  // nothing decoded ahead while paused
  src->set_paused(false);
  const auto g = src->frame_at(21, 5s);
  ASSERT_TRUE(g);
  EXPECT_EQ(frame_code(g->picture), 21);
}

/// A decoder that fails on chosen frames, and decodes frame i only once `*allowed` > i: the
/// worker's error and timeout paths without relying on timing.
class FakeDecoder final : public FrameDecoder {
 public:
  FakeDecoder(std::int64_t frames, std::set<std::int64_t> bad,
              std::shared_ptr<std::atomic<std::int64_t>> allowed = nullptr)
      : bad_(std::move(bad)), allowed_(std::move(allowed)) {
    props_.path = "fake.mp4";
    props_.fps = {25, 1};
    props_.frames = frames;
    props_.width = kW;
    props_.height = kH;
    props_.backend = "fake";
  }
  const VideoProperties& properties() const override { return props_; }
  std::int64_t next_index() const override { return next_; }
  void seek(std::int64_t index) override {
    if (index < 0 || index >= props_.frames) throw std::out_of_range("fake seek");
    next_ = index;
  }
  DecodeStatus read(cv::Mat& out) override {
    while (allowed_ && *allowed_ <= next_) std::this_thread::sleep_for(1ms);
    if (next_ >= props_.frames) return DecodeStatus::End;
    const std::int64_t i = next_++;
    if (bad_.count(i)) return DecodeStatus::Error;
    out = coded_frame(static_cast<int>(i));
    return DecodeStatus::Ok;
  }

 private:
  VideoProperties props_;
  std::set<std::int64_t> bad_;
  std::shared_ptr<std::atomic<std::int64_t>> allowed_;
  std::int64_t next_ = 0;
};

TEST(VideoSource, MidStreamDecodeErrorIsSkippedWithAWarning) {
  std::vector<std::string> warnings;
  VideoSource src(std::make_unique<FakeDecoder>(20, std::set<std::int64_t>{5}), quiet(&warnings));
  for (int i = 0; i < 5; ++i) ASSERT_TRUE(src.frame_at(i, 5s));
  const auto f5 = src.frame_at(5, 2s);  // frame 5 never comes: the newest before it
  ASSERT_TRUE(f5);
  EXPECT_EQ(f5->index, 4);
  const auto f6 = src.frame_at(6, 5s);
  ASSERT_TRUE(f6);
  EXPECT_EQ(frame_code(f6->picture), 6);
  EXPECT_GE(src.stats().decode_errors, 1);
  std::lock_guard lock(warnings_mutex);
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings[0].find("frame 5 could not be decoded"), std::string::npos) << warnings[0];
  EXPECT_FALSE(src.stats().ended_early);
}

TEST(VideoSource, RunOfErrorsEndsTheStreamThere) {
  std::set<std::int64_t> bad;
  for (std::int64_t i = 20; i < 60; ++i) bad.insert(i);
  VideoSource src(std::make_unique<FakeDecoder>(60, bad), quiet());
  ASSERT_TRUE(src.frame_at(19, 5s));
  const auto f = src.frame_at(20, 5s);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->index, 19);
  // frame_at may return as soon as frame 20 failed; the worker decides the end a little later.
  for (int i = 0; i < 500 && !src.stats().ended_early; ++i) std::this_thread::sleep_for(10ms);
  const VideoStats s = src.stats();
  EXPECT_TRUE(s.ended_early);
  EXPECT_EQ(s.end, 20);
}

TEST(VideoSource, SlowDecodeTimesOutInsteadOfBlocking) {
  auto allowed = std::make_shared<std::atomic<std::int64_t>>(0);
  VideoSource src(std::make_unique<FakeDecoder>(10, std::set<std::int64_t>{}, allowed), quiet());
  EXPECT_FALSE(src.frame_at(0, 20ms).has_value());  // not decoded yet: no frame, no hang
  *allowed = 1;
  const auto f = src.frame_at(0, 10s);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->index, 0);
  // Frame 1 is still "decoding": a zero timeout gives the newest frame <= 1 at once.
  const auto g = src.frame_at(1, 0ms);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->index, 0);
  const auto h = src.frame_at(1, 20ms);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->index, 0);
  *allowed = 100;  // let the worker finish so the source can stop
  const auto k = src.frame_at(1, 10s);
  ASSERT_TRUE(k);
  EXPECT_EQ(k->index, 1);
}

TEST(VideoSource, StillImageIsAOneFrameVideo) {
  const auto dir = temp_dir("video_still");
  cv::Mat bgr;
  cv::cvtColor(coded_frame(77), bgr, cv::COLOR_RGB2BGR);
  ASSERT_TRUE(cv::imwrite((dir / "s.png").string(), bgr));
  auto src = VideoSource::open(dir / "s.png", quiet());
  EXPECT_TRUE(src->properties().is_still);
  EXPECT_EQ(src->properties().frames, 1);
  EXPECT_EQ(src->properties().width, kW);
  const auto f = src->frame_at(0, 5s);
  ASSERT_TRUE(f);
  EXPECT_EQ(frame_code(f->picture), 77);
  const auto g = src->frame_at(250, 5s);
  ASSERT_TRUE(g);
  EXPECT_EQ(g->index, 0);
}

TEST(VideoSource, MissingAndGarbageFilesAreInputErrors) {
  const auto dir = temp_dir("video_errors");
  std::ofstream(dir / "junk.mp4") << std::string(5000, 'j');
  const struct {
    fs::path path;
    const char* reason;
  } cases[] = {
      {dir / "missing.mp4", "no such file"}, {dir / "junk.mp4", "cannot"}, {dir, "is a folder"}};
  for (const auto& c : cases) {
    try {
      VideoSource::open(c.path, quiet());
      ADD_FAILURE() << c.path << ": opened";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(c.path.string()), std::string::npos) << what;
      EXPECT_NE(what.find(c.reason), std::string::npos) << what;
    }
  }
}

/// Opens a cut file: refused naming the file (false), or opened (true) and then the frames handed
/// out are the right ones, except that the one frame the cut went through may decode with
/// damaged content (the decoder cannot tell); asking past the cut returns rather than hangs.
bool plays_up_to_the_cut(const fs::path& cut) {
  std::unique_ptr<VideoSource> src;
  std::vector<std::string> warnings;
  try {
    src = VideoSource::open(cut, quiet(&warnings));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
    return false;
  }
  std::int64_t last = -1;
  std::set<std::int64_t> wrong;
  for (std::int64_t i = 0; i < 60; ++i) {
    const auto f = src->frame_at(i, 5s);
    if (!f) continue;
    EXPECT_LE(f->index, i);
    if (frame_code(f->picture) != f->index) wrong.insert(f->index);
    last = f->index;
  }
  EXPECT_LE(wrong.size(), 1u) << cut;
  EXPECT_GE(last, 0) << cut;
  EXPECT_LT(last, 59) << cut;  // the cut is never papered over with frames that are not there
  // Fewer frames than the container promised is said, not silent.
  const VideoProperties& pr = src->properties();
  EXPECT_TRUE(pr.frames < 60 || src->stats().ended_early || src->stats().decode_errors > 0) << cut;
  if (pr.declared_frames > pr.frames) {
    std::lock_guard lock(warnings_mutex);
    const std::string first = warnings.empty() ? std::string() : warnings[0];
    EXPECT_NE(first.find("cut short"), std::string::npos) << cut << ": " << first;
  }
  return true;
}

TEST(VideoSource, TruncatedFileFailsClearlyOrEndsGracefully) {
  const auto dir = temp_dir("video_truncated");
  // MP4 with its index in front (cut: the index promises frames the file no longer has),
  // Matroska, and OpenCV's MJPEG AVI (the MP4 with its index at the end: the next test).
  test_media::ClipSpec c;
  c.frames = 60;
  c.gop = 12;
  c.frame = [](int i) {  // noise below the stripes: the frames, not the headers, fill the file
    cv::Mat m = coded_frame(i);
    cv::RNG rng(static_cast<std::uint64_t>(i) + 1);
    cv::Mat noise(kH / 4, kW, CV_8UC3);
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    noise.copyTo(m(cv::Rect(0, kH - kH / 4, kW, kH / 4)));
    return m;
  };
  const fs::path front = test_media::write_clip(dir / "front.mp4", c);
  const fs::path mkv = test_media::write_clip(dir / "full.mkv", c);
  const fs::path avi = write_opencv_mjpeg(dir, "full.avi", 60);
  int opened = 0;
  for (const fs::path& full : {front, mkv, avi}) {
    const auto size = fs::file_size(full);
    for (const double keep : {0.5, 0.02}) {
      const auto cut = dir / ("cut" + std::to_string(static_cast<int>(keep * 100)) + "_" +
                              full.filename().string());
      fs::copy_file(full, cut, fs::copy_options::overwrite_existing);
      fs::resize_file(cut, static_cast<std::uintmax_t>(static_cast<double>(size) * keep));
      opened += plays_up_to_the_cut(cut);
    }
  }
  EXPECT_GE(opened, 3);  // cut in half, each of the three plays up to the cut
}

TEST(VideoSource, AnMp4CutWithItsIndexAtTheEndIsRefusedNamingIt) {
  // Cut anywhere, an MP4 whose index is at its end has no index.
  const fs::path tail = temp_dir("video_truncated_tail") / "tail.mp4";
  {
    io::EncoderSettings s;
    s.width = kW;
    s.height = kH;
    s.preset = "superfast";
    s.faststart = false;
    auto enc = io::VideoEncoder::create(tail, s);
    for (int i = 0; i < 24; ++i) enc->write(rgb_to_ycbcr(coded_frame(i), s.ycbcr), i);
    enc->finish();
  }
  fs::resize_file(tail, fs::file_size(tail) / 2);
  try {
    VideoSource::open(tail, quiet());
    ADD_FAILURE() << "a cut MP4 without its index opened";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(tail.string()), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vdfx::io
