/// @file
/// @brief The deterministic generator of recordings/: scripted sim sessions (desktop events fed
/// to the sim backend through the recording decorator) and HID report streams built from the
/// documented byte layouts. Set VDFX_REGENERATE_RECORDINGS=1 and run vdfx_test_xr_input to rewrite
/// the committed files; otherwise the test checks they still match what this generator produces.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vdfx::xr::scripts {

/// Frame period of the sim sessions: 30 Hz.
inline constexpr std::int64_t kFrameNs = 33'333'333;
/// HID report period of the HID streams: 50 Hz; their sample lines come every 100 ms.
inline constexpr std::int64_t kReportNs = 20'000'000;
inline constexpr std::int64_t kHidSampleNs = 100'000'000;

struct Script {
  std::string file_name;
  std::function<void(const std::filesystem::path&)> write;
};

const std::vector<Script>& all();

/// Keys of the buttons tour, in order: key k is held from frame 9k+3 to 9k+8 inclusive.
struct TourStep {
  int key;  //!< xr::Key as int (kept out of this header's includes)
  const char* path;
  double value;
};
const std::vector<TourStep>& buttons_tour();

}  // namespace vdfx::xr::scripts
