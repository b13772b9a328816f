/// @file
/// @brief Video sources: properties, frame-exact seeks, loop, pause, decode errors, truncated and
/// missing files. Videos are generated at runtime with cv::VideoWriter; each frame carries its
/// index as 8 black/white stripes, so a test can read back which frame it got.
#include "io_test_util.h"
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <mutex>
#include <set>
#include <thread>

#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/video_source.h"

namespace vdfx::io {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr int kW = 128, kH = 64;

using testing::temp_dir;

cv::Mat coded_frame(int index) {
  cv::Mat m(kH, kW, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int b = 0; b < 8; ++b)
    if (index & (1 << b)) m(cv::Rect(b * 16, 0, 16, kH)).setTo(cv::Scalar(255, 255, 255));
  return m;
}

/// Reads the stripes back from an RGB frame (8-bit or float).
int frame_code(const cv::Mat& rgb) {
  cv::Mat m8;
  if (rgb.depth() == CV_32F) rgb.convertTo(m8, CV_8UC3, 255.0);
  else m8 = rgb;
  int code = 0;
  for (int b = 0; b < 8; ++b)
    if (m8.at<cv::Vec3b>(kH / 2, b * 16 + 8)[1] > 127) code |= 1 << b;
  return code;
}

fs::path write_video(const fs::path& dir, const std::string& name, int fourcc, int frames,
                     double fps = 24.0) {
  const fs::path p = dir / name;
  cv::VideoWriter w(p.string(), fourcc, fps, cv::Size(kW, kH));
  if (!w.isOpened()) ADD_FAILURE() << "cannot write " << p << " with this OpenCV";
  for (int i = 0; i < frames; ++i) w.write(coded_frame(i));
  w.release();
  return p;
}

const int kMjpg = cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
const int kMp4v = cv::VideoWriter::fourcc('m', 'p', '4', 'v');

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
  const auto p = write_video(dir, "a.avi", kMjpg, 30, 25.0);
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
    EXPECT_EQ(frame_code(f->image), i);
    EXPECT_EQ(f->image.type(), CV_8UC3);
  }
  EXPECT_EQ(src->stats().decode_errors, 0);
}

/// Seeks in an order that jumps back, forward far, forward near, and repeats.
const std::int64_t kSeekOrder[] = {40, 3, 3, 47, 0, 25, 24, 26, 10, 46, 1, 33};

struct CodecCase {
  const char* file;
  int fourcc;
};
const CodecCase kCodecs[] = {{"mjpg.avi", kMjpg}, {"mp4v.mp4", kMp4v}};

TEST(FrameDecoder, SeekIsFrameExact) {
  const auto dir = temp_dir("decoder_seek");
  for (const CodecCase& c : kCodecs) {
    // mp4v has inter frames: a seek must decode from the key frame before the target.
    const auto p = write_video(dir, c.file, c.fourcc, 48);
    auto d = open_frame_decoder(p);
    ASSERT_EQ(d->properties().frames, 48) << c.file;
    for (const std::int64_t k : kSeekOrder) {
      d->seek(k);
      EXPECT_EQ(d->next_index(), k);
      cv::Mat img;
      ASSERT_EQ(d->read(img), DecodeStatus::Ok) << c.file << " frame " << k;
      EXPECT_EQ(frame_code(img), k) << c.file;
      EXPECT_EQ(d->next_index(), k + 1);
    }
    EXPECT_THROW(d->seek(48), std::out_of_range);
    EXPECT_THROW(d->seek(-1), std::out_of_range);
  }
}

TEST(VideoSource, FrameAtAfterJumpsIsExact) {
  const auto dir = temp_dir("video_seek");
  for (const CodecCase& c : kCodecs) {
    const auto p = write_video(dir, c.file, c.fourcc, 48);
    VideoSourceOptions o = quiet();
    o.decoder.format = PixelFormat::RgbF32;
    auto src = VideoSource::open(p, o);
    for (const std::int64_t k : kSeekOrder) {
      const auto f = src->frame_at(k, 5s);
      ASSERT_TRUE(f) << c.file << " " << k;
      EXPECT_EQ(f->index, k);
      EXPECT_EQ(frame_code(f->image), k) << c.file;
      EXPECT_EQ(f->image.type(), CV_32FC3);
    }
    // An explicit seek, then the frame.
    src->seek(17);
    const auto f = src->frame_at(17, 5s);
    ASSERT_TRUE(f);
    EXPECT_EQ(frame_code(f->image), 17);
  }
}

TEST(VideoSource, LoopWrapsWithoutASeekAndEndClampsWithout) {
  const auto dir = temp_dir("video_loop");
  const auto p = write_video(dir, "a.avi", kMjpg, 12);
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
      EXPECT_EQ(frame_code(f->image), k);
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
  const auto p = write_video(dir, "a.avi", kMjpg, 40);
  auto src = VideoSource::open(p, quiet());
  src->set_paused(true);
  EXPECT_TRUE(src->paused());
  const auto f = src->frame_at(20, 5s);
  ASSERT_TRUE(f);
  EXPECT_EQ(frame_code(f->image), 20);
  const std::int64_t decoded = src->stats().decoded;
  std::this_thread::sleep_for(50ms);
  EXPECT_EQ(src->stats().decoded, decoded);  // nothing decoded ahead while paused
  src->set_paused(false);
  const auto g = src->frame_at(21, 5s);
  ASSERT_TRUE(g);
  EXPECT_EQ(frame_code(g->image), 21);
}

/// A decoder that fails on chosen frames, and decodes frame i only once `*allowed` > i: the
/// worker's error and timeout paths without relying on timing.
class FakeDecoder final : public FrameDecoder {
 public:
  FakeDecoder(std::int64_t frames, std::set<std::int64_t> bad,
              std::shared_ptr<std::atomic<std::int64_t>> allowed = nullptr)
      : bad_(std::move(bad)), allowed_(std::move(allowed)) {
    props_ = {"fake.mp4", {25, 1}, frames, kW, kH, false, "fake"};
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
    cv::cvtColor(coded_frame(static_cast<int>(i)), out, cv::COLOR_BGR2RGB);
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
  EXPECT_EQ(frame_code(f6->image), 6);
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
  ASSERT_TRUE(cv::imwrite((dir / "s.png").string(), coded_frame(77)));
  auto src = VideoSource::open(dir / "s.png", quiet());
  EXPECT_TRUE(src->properties().is_still);
  EXPECT_EQ(src->properties().frames, 1);
  EXPECT_EQ(src->properties().width, kW);
  const auto f = src->frame_at(0, 5s);
  ASSERT_TRUE(f);
  EXPECT_EQ(frame_code(f->image), 77);
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
  } cases[] = {{dir / "missing.mp4", "no such file"},
               {dir / "junk.mp4", "cannot"},
               {dir, "is a folder"}};
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

TEST(VideoSource, TruncatedFileFailsClearlyOrEndsGracefully) {
  const auto dir = temp_dir("video_truncated");
  const auto full = write_video(dir, "full.avi", kMjpg, 60);
  const auto size = fs::file_size(full);
  for (const double keep : {0.5, 0.02}) {
    const auto cut = dir / ("cut" + std::to_string(static_cast<int>(keep * 100)) + ".avi");
    fs::copy_file(full, cut, fs::copy_options::overwrite_existing);
    fs::resize_file(cut, static_cast<std::uintmax_t>(static_cast<double>(size) * keep));
    std::unique_ptr<VideoSource> src;
    try {
      src = VideoSource::open(cut, quiet());
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(cut.string()), std::string::npos) << e.what();
      continue;
    }
    // Opened: frames handed out are the right ones, except that the one frame the cut went
    // through may decode with damaged content (the decoder cannot tell); asking past the cut
    // returns rather than hangs.
    std::int64_t last = -1;
    std::set<std::int64_t> wrong;
    for (std::int64_t i = 0; i < src->properties().frames; ++i) {
      const auto f = src->frame_at(i, 5s);
      if (!f) continue;
      EXPECT_LE(f->index, i);
      if (frame_code(f->image) != f->index) wrong.insert(f->index);
      last = f->index;
    }
    EXPECT_LE(wrong.size(), 1u);
    EXPECT_GE(last, 0);
    EXPECT_LT(last, 60);
    // Fewer frames than declared must be visible in the stats, not silent.
    if (last < src->properties().frames - 1) {
      EXPECT_TRUE(src->stats().ended_early || src->stats().decode_errors > 0);
    }
  }
}

}  // namespace
}  // namespace vdfx::io
