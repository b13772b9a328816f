/// @file
/// @brief HidReader survives unplug and replug of a mock device whose reads fail then recover.
#include "io/hid_reader.h"

#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <thread>

namespace vdfx::io {
namespace {

// A device that plays a script: each entry is a report, or an empty entry for "read fails".
class MockDevice final : public HidDevice {
 public:
  explicit MockDevice(std::deque<std::vector<std::uint8_t>> script) : script_(std::move(script)) {}
  int read(std::span<std::uint8_t> buffer, int timeout_ms) override {
    if (script_.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(timeout_ms));
      return 0;
    }
    auto r = script_.front();
    script_.pop_front();
    if (r.empty()) return -1;
    std::copy(r.begin(), r.end(), buffer.begin());
    return static_cast<int>(r.size());
  }
  int write(std::span<const std::uint8_t>) override { return -1; }
  int get_feature(std::span<std::uint8_t>) override { return -1; }
  std::vector<std::uint8_t> report_descriptor() override { return {0x05, 0x01}; }
  std::string last_error() const override { return "unplugged"; }
  void close() override {}

 private:
  std::deque<std::vector<std::uint8_t>> script_;
};

template <class Pred>
bool wait_for(Pred pred) {
  for (int i = 0; i < 500; ++i) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(HidReader, ReportsThenLossThenReopen) {
  int opens = 0;
  auto opener = [&opens]() -> std::unique_ptr<HidDevice> {
    ++opens;
    if (opens == 1)
      return std::make_unique<MockDevice>(std::deque<std::vector<std::uint8_t>>{{1, 2}, {3}, {}});
    if (opens == 2) return nullptr;  // still unplugged at the first retry
    return std::make_unique<MockDevice>(std::deque<std::vector<std::uint8_t>>{{4, 5, 6}});
  };
  HidReaderOptions opt;
  opt.reopen_interval_ms = 5;
  opt.read_timeout_ms = 5;
  HidReader reader("mock", opener, opt);
  std::vector<HidReaderEvent> events;
  ASSERT_TRUE(wait_for([&] {
    for (auto& e : reader.drain()) events.push_back(std::move(e));
    return events.size() >= 6;
  }));
  using K = HidReaderEvent::Kind;
  ASSERT_EQ(events.size(), 6u);
  EXPECT_EQ(events[0].kind, K::Connected);
  EXPECT_EQ(events[0].bytes, (std::vector<std::uint8_t>{0x05, 0x01}));
  EXPECT_EQ(events[1].bytes, (std::vector<std::uint8_t>{1, 2}));
  EXPECT_EQ(events[2].bytes, (std::vector<std::uint8_t>{3}));
  EXPECT_EQ(events[3].kind, K::Disconnected);
  EXPECT_NE(events[3].message.find("lost (unplugged)"), std::string::npos) << events[3].message;
  EXPECT_EQ(events[4].kind, K::Connected);
  EXPECT_EQ(events[5].bytes, (std::vector<std::uint8_t>{4, 5, 6}));
  EXPECT_GE(opens, 3);
  EXPECT_TRUE(reader.connected());
}

TEST(HidReader, NeverOpeningDeviceReportsStatusAndStopsCleanly) {
  HidReaderOptions opt;
  opt.reopen_interval_ms = 5;
  HidReader reader(
      "0000:0001", [] { return std::unique_ptr<HidDevice>(); }, opt);
  ASSERT_TRUE(wait_for([&] { return reader.status().find("not found") != std::string::npos; }));
  EXPECT_FALSE(reader.connected());
  EXPECT_TRUE(reader.drain().empty());
}

}  // namespace
}  // namespace vdfx::io
