/// @file
/// @brief `vdfx validate SIDECAR`: exit 0 when valid, 1 with every problem listed otherwise.
#include <algorithm>
#include <iostream>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "effects/rbf_windows.h"
#include "io/sidecar_validate.h"

namespace vdfx::app {

namespace {

/// One line per effect interpolated locally in time (effects/rbf_windows.h): its reach and
/// windows; effects solved globally print nothing.
void print_local_interpolation(const io::Sidecar& s) {
  const auto line = [&](const std::string& name, const std::vector<effects::Keyframe>& keyframes,
                        const std::optional<effects::InterpolationSettings>& own) {
    std::vector<std::int64_t> frames;
    for (const effects::Keyframe& k : keyframes) frames.push_back(k.frame);
    std::sort(frames.begin(), frames.end());
    if (const auto summary =
            effects::window_summary(own.value_or(s.interpolation), s.video.fps, frames))
      std::cout << "  " << name << ": " << keyframes.size() << " keyframes " << *summary << "\n";
  };
  for (const auto& t : s.effects)
    line(std::string(effects::effect_name(t.type)), t.keyframes, t.interpolation);
  for (std::size_t i = 0; i < s.flares.size(); ++i)
    line("flare " + std::to_string(i), s.flares[i].keyframes, s.flares[i].interpolation);
  for (std::size_t i = 0; i < s.grains.size(); ++i)
    line("grain " + std::to_string(i), s.grains[i].keyframes, s.grains[i].interpolation);
}

}  // namespace

int cmd_validate(const Args& args) {
  CLI::App cli{
      "Checks a sidecar file (.vdfx.json) against format 1 and lists every problem with\n"
      "its JSON pointer. Exit 0 when valid, 1 otherwise.",
      "vdfx validate"};
  std::string path;
  bool quiet = false;
  cli.add_option("SIDECAR", path, "the sidecar file")->required();
  cli.add_flag("-q,--quiet", quiet, "print nothing when the file is valid");
  if (auto code = parse_cli(cli, args)) return *code;

  const io::SidecarReport report = io::validate_sidecar_file(path);
  if (!report.ok()) {
    std::cerr << report.to_string();
    if (!report.to_string().ends_with('\n')) std::cerr << '\n';
    std::cerr << path << ": " << report.problems.size()
              << (report.problems.size() == 1 ? " problem\n" : " problems\n");
    return kExitBadInput;
  }
  if (!quiet) {
    std::size_t keyframes = 0;
    for (const auto& track : report.sidecar->effects) keyframes += track.keyframes.size();
    for (const auto& flare : report.sidecar->flares) keyframes += flare.keyframes.size();
    for (const auto& grain : report.sidecar->grains) keyframes += grain.keyframes.size();
    std::cout << path << ": valid ("
              << report.sidecar->effects.size() + report.sidecar->flares.size() +
                     report.sidecar->grains.size()
              << " effects, " << keyframes << " keyframes)\n";
    print_local_interpolation(*report.sidecar);
  }
  return kExitOk;
}

}  // namespace vdfx::app
