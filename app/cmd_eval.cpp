/// @file
/// @brief `vdfx eval SIDECAR --at AZ,ALT,FRAME [--at ...]`: the interpolated parameters of every
/// effect, one JSON object per --at and per line (JSON Lines), for scripts.
#include <iostream>

#include "app/cli_util.h"
#include "app/view_render.h"
#include "effects/stack_interpolator.h"
#include "io/input_error.h"
#include "io/sidecar.h"

namespace vdfx::app {

int cmd_eval(const Args& args) {
  CLI::App cli{"Prints the interpolated parameters of every effect at the given views as JSON, one\n"
               "object per --at and per line. Effects without keyframes print their neutral\n"
               "values with \"active\": false.",
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
  const effects::StackInterpolator stack(sidecar.effects, sidecar.interpolation, sidecar.video.fps);
  for (const EvalPoint& p : points) {
    const effects::StackParams params = stack.evaluate(p.direction, p.frame);
    require_finite(params, path, p.direction, p.frame);  // never print "null"
    nlohmann::ordered_json out;
    out["at"] = {{"azimuth_deg", p.direction.azimuth_deg},
                 {"altitude_deg", p.direction.altitude_deg},
                 {"frame", p.frame}};
    nlohmann::ordered_json fx = nlohmann::ordered_json::object();
    for (const effects::EffectSpec& spec : effects::all_effect_specs()) {
      nlohmann::ordered_json e = io::params_to_json(spec.type, params.get(spec.type));
      e["active"] = stack.active(spec.type);
      fx[std::string(spec.name)] = std::move(e);
    }
    out["effects"] = std::move(fx);
    std::cout << out.dump() << "\n";
  }
  return kExitOk;
}

}  // namespace vdfx::app
