/// @file
/// @brief Record-then-replay round trip (sim and hid), step semantics, the factory, and the hid
/// backend surviving unplug with a mock device whose reads fail then recover.
#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <mutex>
#include <thread>

#include "hid_test_data.h"
#include "input_test_util.h"
#include "io/input_error.h"
#include "tests/support/test_paths.h"
#include "xr/input/input_backend.h"

namespace vdfx::xr {
namespace {

std::filesystem::path out_file(const std::string& name) {
  const auto dir = std::filesystem::path(VDFX_TEST_OUTPUT_DIR) / "replay";
  std::filesystem::create_directories(dir);
  return dir / name;
}

constexpr std::int64_t kFrame = 11'111'111;  // 90 Hz

TEST(Replay, SimSessionRoundTripsExactly) {
  const auto file = out_file("sim_roundtrip.vdrec.jsonl");
  std::vector<InputState> live;
  {
    SimConfig cfg;
    cfg.hfov_deg = 100;
    auto rec =
        create_recording_backend(create_sim_backend(cfg), file, {"sim", "demo.mp4", "round trip"});
    for (int f = 0; f < 120; ++f) {
      if (f == 5) rec->push_event(MouseButtonEvent{MouseButton::Right, true});
      if (f > 5 && f < 40) rec->push_event(MouseMoveEvent{640.0 + 7.3 * f, 360.0 - 1.7 * f});
      if (f == 40) rec->push_event(MouseButtonEvent{MouseButton::Right, false});
      if (f > 40 && f < 80)
        rec->push_event(MouseMoveEvent{300.0 + 9.1 * (f - 40), 100.0 + 5.5 * (f - 40)});
      if (f == 50) rec->push_event(KeyEvent{Key::Space, true});
      if (f == 60) rec->push_event(KeyEvent{Key::Space, false});
      if (f == 70) rec->push_event(KeyEvent{Key::A, true});
      if (f == 75) rec->push_event(KeyEvent{Key::W, true});
      if (f == 90) rec->push_event(KeyEvent{Key::M, true});
      live.push_back(rec->poll(1000 + f * kFrame));
    }
  }
  auto replay = create_input_backend("replay:" + file.string());
  const auto times = replay->timeline();
  ASSERT_EQ(times.size(), live.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    EXPECT_EQ(times[i], live[i].t_ns);
    const InputState r = replay->poll(live[i].t_ns);
    EXPECT_EQ(r.t_ns, live[i].t_ns);
    test_util::expect_state_eq(r, live[i]);  // bit-exact
  }
  // Step: between samples the earlier one holds; before the first nothing is tracked.
  test_util::expect_state_eq(replay->poll(live[50].t_ns + kFrame / 2), live[50]);
  const InputState before = replay->poll(0);
  EXPECT_FALSE(before.head_tracked || before.left.tracked || before.right.tracked);
  test_util::expect_state_eq(replay->poll(live.back().t_ns + 5 * kFrame), live.back());
}

TEST(Replay, RepeatedPollTimesAreRecordedOnce) {
  const auto file = out_file("repeat.vdrec.jsonl");
  {
    auto rec = create_recording_backend(create_sim_backend({}), file, {});
    rec->poll(10);
    rec->poll(10);
    rec->poll(5);
    rec->poll(20);
  }
  EXPECT_EQ(io::read_recording(file).lines.size(), 2u);
}

TEST(Replay, FactoryRejectsBadSpecsWithClearMessages) {
  struct Row {
    std::string spec;
    const char* what;
  };
  const Row rows[] = {
      {"vr", "unknown backend 'vr'"},
      {"replay:", "unknown backend"},
      {"replay:/nonexistent.vdrec.jsonl", "/nonexistent.vdrec.jsonl"},
      {"hid:12", "neither vendor:product"},
  };
  for (const Row& r : rows) {
    try {
      create_input_backend(r.spec);
      ADD_FAILURE() << "accepted " << r.spec;
    } catch (const io::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(r.what), std::string::npos) << e.what();
    }
  }
}

TEST(Replay, HidReportOfAnUnknownDeviceIsRejectedWithItsLine) {
  const auto file = out_file("unknown_device.vdrec.jsonl");
  {
    io::RecordingWriter w(file, {});
    w.write(io::RecordedHid{0, "1234:5678", {0x01, 0x02}, false});
  }
  try {
    create_input_backend("replay:" + file.string());
    FAIL();
  } catch (const io::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown_device.vdrec.jsonl:2:"), std::string::npos)
        << e.what();
  }
}

// [SECTION] hid backend with a mock system

struct MockBus {
  std::mutex mutex;
  bool plugged = true;
  std::deque<std::vector<std::uint8_t>> reports;  // what the next reads return
  bool fail_next_read = false;
  int opens = 0;
};

class MockDevice final : public io::HidDevice {
 public:
  explicit MockDevice(MockBus& bus) : bus_(bus) {}
  int read(std::span<std::uint8_t> buffer, int timeout_ms) override {
    {
      std::lock_guard<std::mutex> lock(bus_.mutex);
      if (bus_.fail_next_read || !bus_.plugged) {
        bus_.fail_next_read = false;
        return -1;
      }
      if (!bus_.reports.empty()) {
        const auto r = bus_.reports.front();
        bus_.reports.pop_front();
        std::copy(r.begin(), r.end(), buffer.begin());
        return static_cast<int>(r.size());
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
    return 0;
  }
  int write(std::span<const std::uint8_t>) override { return -1; }
  int get_feature(std::span<std::uint8_t>) override { return -1; }
  std::vector<std::uint8_t> report_descriptor() override { return {}; }
  std::string last_error() const override { return "device disconnected"; }
  void close() override {}

 private:
  MockBus& bus_;
};

io::HidSystem mock_system(MockBus& bus) {
  io::HidSystem sys;
  sys.enumerate = [&bus] {
    std::lock_guard<std::mutex> lock(bus.mutex);
    std::vector<io::HidDeviceInfo> out;
    if (bus.plugged)
      out.push_back({"/dev/mock0", 0x054c, 0x05c4, "Sony", "Wireless Controller", "", 1, 5, 3});
    return out;
  };
  sys.open = [&bus](const std::string&) -> std::unique_ptr<io::HidDevice> {
    std::lock_guard<std::mutex> lock(bus.mutex);
    if (!bus.plugged) return nullptr;
    ++bus.opens;
    return std::make_unique<MockDevice>(bus);
  };
  return sys;
}

// Polls (at increasing times) until pred holds or ~5 s pass.
template <class Pred>
InputState poll_until(InputBackend& b, std::int64_t& t, Pred pred) {
  InputState s;
  for (int i = 0; i < 1000; ++i) {
    t += kFrame;
    s = b.poll(t);
    if (pred(s)) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ADD_FAILURE() << "condition not reached; status: " << b.status();
  return s;
}

TEST(HidBackend, TapBetweenPollsIsDownInExactlyOnePoll) {
  // Cross pressed and released in two reports that both arrive before one poll: the poll shows
  // it down (the release waits for the next poll), so the tap is one press, not lost.
  MockBus bus;
  InputBackendOptions opt;
  opt.hid_system = mock_system(bus);
  opt.hid_reader.read_timeout_ms = 2;
  auto hid = create_input_backend("hid", opt);
  std::int64_t t = 0;
  poll_until(*hid, t, [&](const InputState&) {
    return hid->status().find("connected") != std::string::npos;
  });
  {
    std::lock_guard<std::mutex> lock(bus.mutex);
    bus.reports.push_back(test_data::ds4_report({{5, 0x28}}));  // cross down
    bus.reports.push_back(test_data::ds4_report({{5, 0x08}}));  // cross up
  }
  for (int i = 0; i < 500; ++i) {  // both read by the worker before the next poll
    {
      std::lock_guard<std::mutex> lock(bus.mutex);
      if (bus.reports.empty()) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  int pressed = 0, released = 0, down = 0;
  for (int i = 0; i < 6; ++i) {
    const InputState s = hid->poll(t += kFrame);
    pressed += s.edges.was_pressed(Hand::Right, Control::Primary);
    released += s.edges.was_released(Hand::Right, Control::Primary);
    down += s.edges.is_down(Hand::Right, Control::Primary);
  }
  EXPECT_EQ(pressed, 1);
  EXPECT_EQ(released, 1);
  EXPECT_EQ(down, 1);
}

TEST(HidBackend, UnplugGoesNeutralThenRecoversAndReplaysTheSame) {
  MockBus bus;
  InputBackendOptions opt;
  opt.hid_system = mock_system(bus);
  opt.hid_reader.reopen_interval_ms = 10;
  opt.hid_reader.read_timeout_ms = 2;
  const auto file = out_file("hid_unplug.vdrec.jsonl");
  std::vector<InputState> live;
  {
    auto hid = create_recording_backend(create_input_backend("hid", opt), file,
                                        {"none", std::nullopt, "mock DS4"});
    std::int64_t t = 0;
    {
      std::lock_guard<std::mutex> lock(bus.mutex);
      bus.reports.push_back(test_data::ds4_report({{9, 0xFF}, {5, 0x28}}));  // R2 full, cross
    }
    live.push_back(poll_until(*hid, t, [](const InputState& s) { return s.right.trigger == 1.0; }));
    EXPECT_TRUE(live.back().right.primary);
    EXPECT_NE(hid->status().find("054c:05c4: connected"), std::string::npos) << hid->status();

    {
      std::lock_guard<std::mutex> lock(bus.mutex);  // unplug
      bus.plugged = false;
    }
    live.push_back(poll_until(*hid, t, [](const InputState& s) { return s.right.trigger == 0.0; }));
    EXPECT_FALSE(live.back().right.primary);
    EXPECT_NE(hid->status().find("lost (device disconnected)"), std::string::npos) << hid->status();
    EXPECT_NE(hid->status().find("retrying"), std::string::npos) << hid->status();

    {
      std::lock_guard<std::mutex> lock(bus.mutex);  // replug, the stick pushed left
      bus.plugged = true;
      bus.reports.push_back(test_data::ds4_report({{3, 0x00}}));
    }
    live.push_back(
        poll_until(*hid, t, [](const InputState& s) { return s.right.thumbstick.x < -0.99; }));
    EXPECT_NE(hid->status().find("connected"), std::string::npos) << hid->status();
    EXPECT_GE(bus.opens, 2);
  }
  // The recording holds the raw reports (and the loss); replaying it gives the same actions.
  const io::Recording rec = io::read_recording(file);
  int reports = 0, losses = 0;
  for (const auto& line : rec.lines) {
    if (const auto* h = std::get_if<io::RecordedHid>(&line.value))
      (h->bytes.empty() ? losses : reports)++;
  }
  EXPECT_EQ(reports, 2);
  EXPECT_EQ(losses, 1);
  auto replay = create_replay_backend(rec, opt);
  for (const InputState& s : live) test_util::expect_state_eq(replay->poll(s.t_ns), s);
}

TEST(HidBackend, NoDeviceFoundIsAnInputError) {
  MockBus bus;
  bus.plugged = false;
  InputBackendOptions opt;
  opt.hid_system = mock_system(bus);
  EXPECT_THROW(create_input_backend("hid", opt), io::InputError);
  EXPECT_THROW(create_input_backend("hid:/dev/none", opt), io::InputError);
  // A named vendor:product waits for the device instead.
  auto b = create_input_backend("hid:054c:05c4", opt);
  EXPECT_EQ(b->poll(0).right.trigger, 0.0);
}

}  // namespace
}  // namespace vdfx::xr
