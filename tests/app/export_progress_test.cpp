/// @file
/// @brief Export progress: the bar's and the lines' text, and how often each is written.
#include <gtest/gtest.h>

#include <sstream>

#include "app/cli/progress.h"

namespace vdfx::app {
namespace {

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(ExportProgress, BarAndLineSayFramesRateAndEta) {
  EXPECT_EQ(ProgressReporter::bar_text(12, 48, 4.0),
            "[#####               ]  25%  12/48 frames  3.0 frames/s  ETA 0:12");
  EXPECT_EQ(ProgressReporter::line_text(12, 48, 4.0), "12/48 frames (25%), 3.0 frames/s, ETA 0:12");
  EXPECT_EQ(ProgressReporter::line_text(0, 48, 0.0), "0/48 frames (0%), 0.0 frames/s, ETA --:--");
  EXPECT_NE(ProgressReporter::line_text(1, 9000, 1.0).find("ETA 2:29:59"), std::string::npos);
}

TEST(ExportProgress, OtherCommandsNameWhatTheyCountAndThemselves) {
  std::ostringstream lines;
  ProgressReporter p(lines, false, 40, 5.0, "suggest", "keyframes");
  p.update(10, 2.0);
  EXPECT_EQ(lines.str(), "suggest: 10/40 keyframes (25%), 5.0 keyframes/s, ETA 0:06\n");
}

TEST(ExportProgress, LinesComeEveryIntervalAndTheBarRedrawsInPlace) {
  std::ostringstream lines;
  ProgressReporter p(lines, false, 100, 5.0);
  for (int k = 1; k <= 100; ++k) p.update(k, 0.2 * k);  // 20 s in all
  p.finish(100, 20.0);
  // At 0.2 s, then every 5 s (5.2, 10.2, 15.2), and the last frame once.
  EXPECT_EQ(count(lines.str(), "\n"), 5) << lines.str();
  EXPECT_EQ(count(lines.str(), "100/100 frames (100%)"), 1) << lines.str();
  EXPECT_EQ(lines.str().find('\r'), std::string::npos);

  std::ostringstream bar;
  ProgressReporter b(bar, true, 10);
  for (int k = 1; k <= 10; ++k) b.update(k, 0.5 * k);
  b.finish(10, 5.0);
  EXPECT_EQ(count(bar.str(), "\r"), 11);  // every update (0.5 s apart) and the final one
  EXPECT_EQ(count(bar.str(), "\n"), 1);   // one newline, after the last bar
}

}  // namespace
}  // namespace vdfx::app
