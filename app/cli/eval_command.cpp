/// @file
/// @brief `vdfx eval SIDECAR --at AZ,ALT,FRAME [--at ...]`: the interpolated parameters of every
/// effect, one JSON object per --at and per line (JSON Lines), for scripts.
#include <iostream>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/finite_params.h"
#include "effects/stack_interpolator.h"
#include "io/input_error.h"
#include "io/sidecar.h"
#include "io/sidecar_sets.h"

namespace vdfx::app {

int cmd_eval(const Args& args) {
  CLI::App cli{
      "Prints the interpolated parameters of every effect at the given views as JSON, one\n"
      "object per --at and per line. Effects without keyframes print their neutral\n"
      "values with \"active\": false; flares print their intensity, grains their intensity\n"
      "and size, each in file order.",
      "vdfx eval"};
  std::string path;
  std::vector<std::string> at_texts;
  cli.add_option("SIDECAR", path, "the sidecar file")->required();
  cli.add_option("--at", at_texts, "a view: AZ,ALT,FRAME (degrees, degrees, frame index)")
      ->required()
      ->allow_extra_args(false);
  if (auto code = parse_cli(cli, args)) return *code;
  std::vector<EvalPoint> points;
  try {
    for (const auto& t : at_texts) points.push_back(parse_eval_point(t));
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx eval: " << e.what() << "\n";
    return kExitUsage;
  }

  const io::Sidecar sidecar = io::read_sidecar(path);
  for (const EvalPoint& p : points) {
    if (p.frame >= sidecar.video.frames)
      throw io::InputError(path + ": --at frame " + std::to_string(p.frame) +
                           " is beyond the video's " + std::to_string(sidecar.video.frames) +
                           " frames (/video/frames)");
  }
  const effects::StackInterpolator stack = io::stack_of(sidecar);
  const effects::FlareSet flares = io::flare_set_of(sidecar);
  const effects::GrainSet grains = io::grain_set_of(sidecar);
  for (const EvalPoint& p : points) {
    const effects::StackParams params = stack.evaluate(p.direction, p.frame);
    require_finite(params, path, p.direction, p.frame);  // never print "null"
    nlohmann::ordered_json out;
    out["at"] = {{"azimuth_deg", p.direction.azimuth_deg},
                 {"altitude_deg", p.direction.altitude_deg},
                 {"frame", p.frame}};
    out["effects"] = io::stack_params_to_json(stack, params);
    // Flares (any number, in file order): their keyframed intensity at the view.
    nlohmann::ordered_json fl = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < flares.size(); ++k)
      fl.push_back({{"intensity", flares.intensity(k, effects::to_unit(p.direction), p.frame)}});
    out["flares"] = std::move(fl);
    // Grain effects (any number, in file order): keyframed intensity and size at the view.
    nlohmann::ordered_json gr = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < grains.size(); ++k) {
      const effects::GrainParams g = grains.params(k, effects::to_unit(p.direction), p.frame);
      gr.push_back({{"style", effects::grain_style_name(grains.effect(k).style)},
                    {"intensity", g.intensity},
                    {"size", g.size}});
    }
    out["grains"] = std::move(gr);
    std::cout << out.dump() << "\n";
  }
  return kExitOk;
}

}  // namespace vdfx::app
