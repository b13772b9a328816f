/// @file
/// @brief `vdfx suggest exposure|guide|comfort VIDEO ...` (docs/suggest.md): options into a
/// suggest::SuggestRequest, then suggest::run_suggest and its report.
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/suggest/suggest.h"

namespace vdfx::app {

namespace {

struct CommonOptions {
  std::string video, in, out;
  std::int64_t every = 0;
  std::size_t max_keyframes = 256;
};

/// The options every suggestion takes.
void add_common(CLI::App& sub, CommonOptions& c, suggest::SuggestRequest& r) {
  sub.add_option("video", c.video, "the video or panorama")->required();
  sub.add_option("--sidecar-in", c.in,
                 "add to this sidecar (default: --sidecar-out when it exists, else a new one)");
  add_layout_options(sub, r.layout);
  sub.add_option("--sidecar-out", c.out, "write the sidecar with the suggestion here")->required();
  sub.add_option("--strength", r.strength, "0: neutral, 1: the whole suggestion (default 1)")
      ->check(finite_range(0.0, 1.0));
  sub.add_option("--every", c.every, "frames between sampled frames (default: about 1 s)")
      ->check(whole_range(1, 1'000'000));
  sub.add_option("--max-keyframes", c.max_keyframes, "keyframes the suggestion may add (256)")
      ->check(whole_range(1, 4096));
  sub.add_option("--directions", r.directions, "view directions sampled (400)")
      ->check(whole_range(16, 20000));
  sub.add_flag("--merge", r.merge, "add to keyframes the sidecar already has for the effect");
  sub.add_flag("--force", r.force,
               "replace an existing --sidecar-out (without it, an existing --sidecar-out is "
               "added to)");
}

void print_report(const suggest::SuggestRequest& r, const suggest::SuggestReport& report) {
  if (!report.transfer.empty())
    std::printf("metered %zu frames as %s, reference level %.2f stops\n", report.frames.size(),
                report.transfer.c_str(), report.reference_level);
  if (!report.speed_deg_per_s.empty()) {
    const auto fastest =
        std::max_element(report.speed_deg_per_s.begin(), report.speed_deg_per_s.end());
    std::printf("camera turns at most %.1f deg/s (frame %td)\n", *fastest,
                fastest - report.speed_deg_per_s.begin());
  }
  for (const auto& e : report.effects) {
    std::printf("%-10s %zu keyframes, error max %.3f rms %.3f (tolerance %.3f)%s\n",
                std::string(effects::effect_name(e.type)).c_str(), e.fit.added.size(),
                e.fit.max_error, e.fit.rms_error, e.tolerance,
                e.fit.within_tolerance ? "" : ": the keyframe budget ran out first");
  }
  if (!report.sidecar_note.empty()) std::printf("%s\n", report.sidecar_note.c_str());
  std::printf("%zu samples (%zu frames) in %.2f s -> %s\n", report.samples, report.frames.size(),
              report.seconds, r.sidecar_out.string().c_str());
}

}  // namespace

int cmd_suggest(const Args& args) {
  CLI::App cli{"propose keyframes from the video itself, as ordinary keyframes (docs/suggest.md)",
               "vdfx suggest"};
  cli.require_subcommand(1);
  suggest::SuggestRequest r;
  CommonOptions c;
  double tolerance = 0.0;

  CLI::App* exposure = cli.add_subcommand(
      "exposure", "exposure adaptation: darker toward bright views, brighter toward dark ones");
  add_common(*exposure, c, r);
  exposure->add_option("--tolerance", tolerance, "largest error allowed, in stops (0.25)")
      ->check(finite_range(1e-4, 8.0));
  exposure->add_option("--fov", r.metering.fov_deg, "field of view metered, degrees (90)")
      ->check(finite_range(10.0, 180.0));

  CLI::App* guide = cli.add_subcommand(
      "guide", "gaze guidance: desaturate and/or darken views away from a point of interest");
  add_common(*guide, c, r);
  std::vector<std::string> pois;
  std::string effect = "saturation";
  guide->add_option("--poi", pois, "AZ,ALT[,FROM-TO]: a point of interest (repeat for several)")
      ->required();
  guide->add_option("--effect", effect, "saturation, exposure or both (saturation)")
      ->check(CLI::IsMember({"saturation", "exposure", "both"}));
  guide
      ->add_option("--tolerance", tolerance,
                   "largest error allowed (0.05 saturation, 0.25 stops exposure)")
      ->check(finite_range(1e-4, 8.0));

  CLI::App* comfort = cli.add_subcommand(
      "comfort", "comfort vignette: narrow the view while the camera turns fast");
  add_common(*comfort, c, r);
  comfort->add_option("--tolerance", tolerance, "largest error allowed, in degrees (3)")
      ->check(finite_range(1e-3, 90.0));

  if (const auto code = parse_cli(cli, args)) return *code;
  r.kind = exposure->parsed()  ? suggest::Kind::Exposure
           : comfort->parsed() ? suggest::Kind::Comfort
                               : suggest::Kind::Guide;
  r.video = c.video;
  if (!c.in.empty()) r.sidecar_in = c.in;
  r.sidecar_out = c.out;
  r.every = c.every;
  r.max_keyframes = c.max_keyframes;
  if (tolerance > 0.0) r.tolerance = tolerance;
  for (const auto& p : pois) {
    try {
      r.points.push_back(suggest::parse_point_of_interest(p));
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
  }
  r.guide_effect = effect == "both"       ? suggest::GuideEffect::Both
                   : effect == "exposure" ? suggest::GuideEffect::Exposure
                                          : suggest::GuideEffect::Saturation;
  print_report(r, suggest::run_suggest(r));
  return kExitOk;
}

}  // namespace vdfx::app
