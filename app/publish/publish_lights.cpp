/// @file
/// @brief track_auto_lights: the tracker over the whole video.
#include "app/publish/publish_lights.h"

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <variant>

#include "app/cli/stop_signals.h"
#include "effects/coords.h"
#include "effects/flare_set_cv.h"
#include "io/frame_decoder.h"
#include "io/input_error.h"
#include "io/sidecar_sets.h"

namespace vdfx::app {

namespace {

/// The first flare with an auto light (every auto flare shares the set's one tracker).
std::optional<std::size_t> first_auto_flare(const io::Sidecar& sidecar) {
  for (std::size_t k = 0; k < sidecar.flares.size(); ++k)
    if (std::holds_alternative<effects::AutoLight>(sidecar.flares[k].light)) return k;
  return std::nullopt;
}

nlohmann::ordered_json light_json(const std::optional<Eigen::Vector3d>& light) {
  if (!light) return nullptr;
  const effects::Direction d = effects::from_unit(*light);
  return {{"azimuth_deg", d.azimuth_deg}, {"altitude_deg", d.altitude_deg}};
}

}  // namespace

bool uses_auto_light(const io::Sidecar& sidecar) {
  return first_auto_flare(sidecar).has_value();
}

nlohmann::ordered_json track_auto_lights(const std::filesystem::path& video,
                                         const io::Sidecar& sidecar) {
  effects::FlareSet flares = io::flare_set_of(sidecar);
  const std::size_t k = first_auto_flare(sidecar).value_or(0);
  io::DecoderOptions options;
  options.format = io::PixelFormat::RgbF32;  // as vdfx render's frames (load_equirect_frame)
  const auto decoder = io::open_frame_decoder(video, options);
  const std::int64_t frames = decoder->properties().frames;
  nlohmann::ordered_json lights = nlohmann::ordered_json::array();
  // Frame by frame in order: the light at f is fitted from frames f - window .. f, all measured
  // by then, so each frame's light is the one a render of that frame alone finds.
  for (std::int64_t f = 0; f < frames; ++f) {
    if (stop_requested()) throw Stopped("");  // run_publish says what became of OUT
    cv::Mat image;
    if (decoder->read(image) != io::DecodeStatus::Ok || image.empty())
      throw io::InputError(video.string() + ": frame " + std::to_string(f) +
                           " could not be decoded (finding the flares' auto light)");
    if (image.type() != CV_32FC3) image.convertTo(image, CV_32FC3, 1.0 / 255.0);
    effects::observe_frame(flares, f, image);
    lights.push_back(light_json(flares.light(k, f)));
  }
  nlohmann::ordered_json j;
  j["format"] = "vdfx.lights";
  j["version"] = 1;
  j["frames"] = frames;
  j["lights"] = std::move(lights);
  return j;
}

}  // namespace vdfx::app
