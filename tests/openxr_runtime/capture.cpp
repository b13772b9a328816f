/// @file
/// @brief Writing the read-back folder: PNGs through stb_image_write, JSON through nlohmann, each
/// file through a temporary name and a rename, so a test never reads half a file (a frame's
/// frame.json is written after its PNGs).
#include "tests/openxr_runtime/capture.h"

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace vdfx::test_runtime {
namespace {

using nlohmann::json;

void write_atomically(const std::filesystem::path& path, const std::string& bytes) {
  const std::filesystem::path tmp =
      path.parent_path() / ("." + path.filename().string() + ".tmp" + std::to_string(getpid()));
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  std::filesystem::rename(tmp, path);
}

std::string png_bytes(const CapturedImage& image) {
  std::string out;
  const auto sink = [](void* ctx, void* data, int size) {
    static_cast<std::string*>(ctx)->append(static_cast<const char*>(data),
                                           static_cast<std::size_t>(size));
  };
  if (!stbi_write_png_to_func(sink, &out, image.width, image.height, 4, image.rgba.data(),
                              image.width * 4)) {
    throw std::runtime_error("PNG encoding failed");
  }
  return out;
}

json pose_json(const Pose& p) {
  const glm::dquat q = glm::normalize(p.q);
  return {{"q", {q.w, q.x, q.y, q.z}}, {"p", {p.p.x, p.p.y, p.p.z}}};
}

json fov_json(const XrFovf& f) {
  return {{"angleLeft", f.angleLeft},
          {"angleRight", f.angleRight},
          {"angleUp", f.angleUp},
          {"angleDown", f.angleDown}};
}

json view_json(const CapturedView& v, const std::string& file) {
  json j{{"image", file},
         {"encoding", v.image.encoding},
         {"pose", pose_json(from_xr(v.pose))},
         {"pose_in_local", v.pose_in_local ? pose_json(*v.pose_in_local) : json(nullptr)},
         {"swapchain",
          {{"format", v.format}, {"width", v.swapchain_width}, {"height", v.swapchain_height}}},
         {"image_rect",
          {{"x", v.rect.offset.x},
           {"y", v.rect.offset.y},
           {"width", v.rect.extent.width},
           {"height", v.rect.extent.height}}},
         {"image_array_index", v.array_index},
         {"swapchain_image_index", v.image_index}};
  if (v.fov) j["fov"] = fov_json(*v.fov);
  return j;
}

json flags_json(XrCompositionLayerFlags flags) {
  json out = json::array();
  if (flags & XR_COMPOSITION_LAYER_CORRECT_CHROMATIC_ABERRATION_BIT) {
    out.push_back("correct_chromatic_aberration");
  }
  if (flags & XR_COMPOSITION_LAYER_BLEND_TEXTURE_SOURCE_ALPHA_BIT) {
    out.push_back("blend_texture_source_alpha");
  }
  if (flags & XR_COMPOSITION_LAYER_UNPREMULTIPLIED_ALPHA_BIT)
    out.push_back("unpremultiplied_alpha");
  return out;
}

std::string frame_name(std::int64_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame-%06lld", static_cast<long long>(frame));
  return name;
}

}  // namespace

Recorder::Recorder(const Instance& inst)
    : dir_(inst.config.output_dir),
      spec_(inst.config.capture),
      hmd_name_(inst.hmd.name),
      script_(inst.config.script_path),
      period_ns_(display_period_ns(inst)) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec || !std::filesystem::is_directory(dir_)) {
    throw std::runtime_error("VDFX_TEST_RUNTIME_OUTPUT_DIR=" + dir_.string() +
                             ": cannot make the folder (" + ec.message() + ")");
  }
}

void Recorder::state(XrSessionState state, XrTime time) {
  states_.emplace_back(state, time);
}

void Recorder::interaction_profile(const std::string& path, XrTime time) {
  profiles_.emplace_back(path, time);
}

void Recorder::haptic(HapticRecord record) {
  haptics_.push_back(std::move(record));
}

std::optional<CapturedFrame> Recorder::frame(CapturedFrame frame) {
  if (spec_.mode != CaptureSpec::Mode::Last) {
    write_frame(frame);
    return std::nullopt;
  }
  // The last frame that showed something: the frames on the way out submit no layers.
  if (frame.layers.empty()) return frame;
  std::optional<CapturedFrame> old = std::move(last_);
  last_ = std::move(frame);
  return old;
}

void Recorder::write_frame(const CapturedFrame& frame) {
  const std::string name = frame_name(frame.frame);
  const std::filesystem::path folder = dir_ / name;
  std::filesystem::create_directories(folder);
  json layers = json::array();
  for (std::size_t l = 0; l < frame.layers.size(); ++l) {
    const CapturedLayer& layer = frame.layers[l];
    json views = json::array();
    for (std::size_t v = 0; v < layer.views.size(); ++v) {
      const std::string file =
          "layer" + std::to_string(l) +
          (layer.type == "quad" ? std::string("-quad") : "-view" + std::to_string(v)) + ".png";
      write_atomically(folder / file, png_bytes(layer.views[v].image));
      views.push_back(view_json(layer.views[v], file));
    }
    json j{{"type", layer.type}, {"space", layer.space}, {"flags", flags_json(layer.flags)}};
    if (layer.type == "quad") {
      j["eye_visibility"] = layer.eye_visibility;
      j["size_m"] = {layer.size.width, layer.size.height};
      j.update(views[0]);
    } else {
      j["views"] = views;
    }
    layers.push_back(j);
  }
  const json doc{{"frame", frame.frame},
                 {"display_time_ns", frame.display_time},
                 {"predicted_display_time_ns", frame.predicted_display_time},
                 {"layers", layers}};
  write_atomically(folder / "frame.json", doc.dump(2) + "\n");
  written_.push_back(frame.frame);
}

void Recorder::call(const char* function, std::int64_t frames_waited) {
  calls_.emplace_back(function, frames_waited);
}

void Recorder::finish(std::int64_t frames_waited, std::int64_t frames_ended) {
  if (finished_) return;
  finished_ = true;
  if (last_) write_frame(*last_);
  json states = json::array();
  for (const auto& [s, t] : states_) {
    states.push_back({{"state", session_state_name(s)}, {"time_ns", t}});
  }
  json profiles = json::array();
  for (const auto& [p, t] : profiles_) profiles.push_back({{"profile", p}, {"time_ns", t}});
  json calls = json::array();
  for (const auto& [c, frame] : calls_) calls.push_back({{"call", c}, {"frames_waited", frame}});
  json haptics = json::array();
  for (const HapticRecord& h : haptics_) {
    haptics.push_back({{"time_ns", h.time},
                       {"frame", h.frame},
                       {"action", h.action},
                       {"subaction", h.subaction},
                       {"outputs", h.outputs},
                       {"stop", h.stop},
                       {"duration_ns", h.duration_ns},
                       {"frequency", h.frequency},
                       {"amplitude", h.amplitude}});
  }
  const json doc{{"runtime", "vdfx test runtime"},
                 {"hmd", hmd_name_},
                 {"script", script_.empty() ? json(nullptr) : json(script_)},
                 {"clock_origin_ns", kClockOriginNs},
                 {"display_period_ns", period_ns_},
                 {"frames_waited", frames_waited},
                 {"frames_ended", frames_ended},
                 {"frames_captured", written_},
                 {"states", states},
                 {"lifecycle_calls", calls},
                 {"interaction_profiles", profiles},
                 {"haptics", haptics}};
  write_atomically(dir_ / "session.json", doc.dump(2) + "\n");
}

}  // namespace vdfx::test_runtime
