/// @file
/// @brief The committed recordings/: they match the generator, and replaying each produces what
/// recordings/README.md says it must.
#include <gtest/gtest.h>

#include <cstdlib>

#include "input_test_util.h"
#include "io/recording.h"
#include "recording_scripts.h"
#include "tests/support/test_paths.h"
#include "tests/test_files.h"
#include "xr/input/input_backend.h"
#include "xr/input/input_state_io.h"

namespace vdfx::xr {
namespace {

using test_util::altitude_deg;
using test_util::azimuth_deg;

const std::filesystem::path kDir = test_files::recordings_dir();

std::unique_ptr<InputBackend> replay(const std::string& name) {
  return create_input_backend("replay:" + (kDir / name).string());
}

TEST(Recordings, CommittedFilesMatchTheGenerator) {
  const bool regenerate = std::getenv("VDFX_REGENERATE_RECORDINGS") != nullptr;
  const std::filesystem::path out = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "recordings";
  std::filesystem::create_directories(out);
  for (const auto& s : scripts::all()) {
    SCOPED_TRACE(s.file_name);
    if (regenerate) s.write(kDir / s.file_name);
    s.write(out / s.file_name);
    const io::Recording fresh = io::read_recording(out / s.file_name);
    const io::Recording committed = io::read_recording(kDir / s.file_name);
    EXPECT_LE(committed.lines.size(), 400u);  // small fixtures
    ASSERT_EQ(fresh.lines.size(), committed.lines.size());
    EXPECT_EQ(fresh.header.note, committed.header.note);
    for (std::size_t i = 0; i < fresh.lines.size(); ++i) {
      const auto& a = fresh.lines[i].value;
      const auto& b = committed.lines[i].value;
      ASSERT_EQ(a.index(), b.index()) << "line " << committed.lines[i].line_number;
      if (const auto* ha = std::get_if<io::RecordedHid>(&a)) {
        const auto& hb = std::get<io::RecordedHid>(b);
        EXPECT_EQ(ha->t_ns, hb.t_ns);
        EXPECT_EQ(ha->bytes, hb.bytes) << "line " << committed.lines[i].line_number;
      } else {
        const auto& sa = std::get<io::RecordedSample>(a);
        const auto& sb = std::get<io::RecordedSample>(b);
        EXPECT_EQ(sa.t_ns, sb.t_ns);
        // Trigonometry may differ in the last bits between platforms; nothing more.
        test_util::expect_state_eq(from_recorded_sample(sa), from_recorded_sample(sb), 1e-9);
      }
    }
  }
}

TEST(Recordings, SimLookAndPlace) {
  auto r = replay("sim_look_and_place.vdrec.jsonl");
  const auto times = r->timeline();
  ASSERT_EQ(times.size(), 180u);
  auto at = [&](int frame) { return r->poll(frame * scripts::kFrameNs); };
  EXPECT_NEAR(azimuth_deg(at(5).head), 0.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(at(41).head), 90.0, 1e-9);
  EXPECT_NEAR(altitude_deg(at(45).head), 0.0, 1e-9);
  EXPECT_NEAR(altitude_deg(at(61).head), 10.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(at(179).head), 90.0, 1e-9);
  // The cursor ends at (960, 200): right of and above the view centre.
  const InputState s = at(95);
  const glm::dvec3 d = glm::inverse(s.head.orientation) * forward(s.right.aim);
  EXPECT_NEAR(std::atan2(d.x, -d.z), std::atan((960.0 / 640.0 - 1.0)), 1e-9);
  for (int f : {99, 110, 119, 130}) EXPECT_EQ(at(f).right.trigger, 0.0) << f;
  for (int f : {100, 109, 120, 129}) EXPECT_EQ(at(f).right.trigger, 1.0) << f;
  EXPECT_EQ(at(139).left.thumbstick.y, 0.0);
  EXPECT_EQ(at(140).left.thumbstick.y, 1.0);
  EXPECT_EQ(at(170).left.thumbstick.y, 0.0);
}

TEST(Recordings, SimButtonsTour) {
  auto r = replay("sim_buttons_tour.vdrec.jsonl");
  const auto& tour = scripts::buttons_tour();
  for (std::size_t k = 0; k < tour.size(); ++k) {
    const int pressed = static_cast<int>(9 * k + 3), released = static_cast<int>(9 * k + 9);
    auto value = [&](int frame) {
      const auto v = *get_action(r->poll(frame * scripts::kFrameNs), tour[k].path);
      if (const bool* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
      return std::get<double>(v);
    };
    EXPECT_EQ(value(pressed - 1), 0.0) << tour[k].path;
    EXPECT_EQ(value(pressed), tour[k].value) << tour[k].path;
    EXPECT_EQ(value(released - 1), tour[k].value) << tour[k].path;
    EXPECT_EQ(value(released), 0.0) << tour[k].path;
  }
}

constexpr std::int64_t kMs = 1'000'000;

TEST(Recordings, HidDs4) {
  auto r = replay("hid_ds4.vdrec.jsonl");
  EXPECT_NEAR(azimuth_deg(r->poll(500 * kMs).head), 45.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(r->poll(1000 * kMs).head), 90.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(r->poll(3000 * kMs).head), 90.0, 1e-9);
  EXPECT_NEAR(r->poll(1500 * kMs).right.trigger, 128.0 / 255.0, 1e-12);
  EXPECT_TRUE(r->poll(1600 * kMs).right.primary);
  EXPECT_FALSE(r->poll(2000 * kMs).right.primary);
  EXPECT_FALSE(r->poll(2400 * kMs).left.menu);
  EXPECT_TRUE(r->poll(2500 * kMs).left.menu);
}

TEST(Recordings, HidDualSense) {
  auto r = replay("hid_dualsense.vdrec.jsonl");
  EXPECT_NEAR(altitude_deg(r->poll(500 * kMs).head), 45.0, 1e-9);
  const InputState a = r->poll(1000 * kMs);
  EXPECT_EQ(a.left.trigger, 1.0);
  EXPECT_TRUE(a.left.secondary);  // triangle: y
  const InputState b = r->poll(2000 * kMs);
  EXPECT_EQ(b.left.trigger, 0.0);
  EXPECT_EQ(b.right.squeeze, 1.0);  // R1
  EXPECT_NEAR(b.right.thumbstick.x, -1.0, 1e-12);
  EXPECT_EQ(r->poll(2600 * kMs).right.squeeze, 0.0);
}

TEST(Recordings, HidGenericGamepad) {
  auto r = replay("hid_generic_gamepad.vdrec.jsonl");
  EXPECT_NEAR(r->poll(500 * kMs).right.thumbstick.x, 1.0, 1e-4);
  EXPECT_EQ(r->poll(1500 * kMs).left.thumbstick.y, 1.0);            // hat up -> d-pad -> left stick
  EXPECT_TRUE(r->poll(2500 * kMs).right.primary);                   // button 1 -> a
  EXPECT_NEAR(azimuth_deg(r->poll(3000 * kMs).head), -90.0, 0.01);  // left stick left 1 s
}

TEST(Recordings, HidSpaceMouse) {
  auto r = replay("hid_spacemouse.vdrec.jsonl");
  EXPECT_NEAR(azimuth_deg(r->poll(1000 * kMs).head), 120.0, 1e-9);
  EXPECT_EQ(r->poll(2200 * kMs).right.trigger, 1.0);
  EXPECT_EQ(r->poll(2500 * kMs).right.trigger, 0.0);
  const InputState end = r->poll(3000 * kMs);
  EXPECT_NEAR(altitude_deg(end.head), 60.0, 1e-9);
  EXPECT_NEAR(azimuth_deg(end.head), 120.0, 1e-9);
}

TEST(Recordings, HidReplayReproducesItsSampleLines) {
  for (const char* name : {"hid_ds4.vdrec.jsonl", "hid_dualsense.vdrec.jsonl",
                           "hid_generic_gamepad.vdrec.jsonl", "hid_spacemouse.vdrec.jsonl"}) {
    SCOPED_TRACE(name);
    const io::Recording rec = io::read_recording(kDir / name);
    auto r = create_replay_backend(rec, {});
    int samples = 0;
    for (const auto& line : rec.lines) {
      if (const auto* s = std::get_if<io::RecordedSample>(&line.value)) {
        test_util::expect_state_eq(r->poll(s->t_ns), from_recorded_sample(*s), 1e-12);
        ++samples;
      }
    }
    EXPECT_EQ(samples, 31);
  }
}

}  // namespace
}  // namespace vdfx::xr
