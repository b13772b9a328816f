/// @file
/// @brief The factory: backend name -> backend.
#include "xr/input/input_backend.h"

#include "io/input_error.h"

namespace vdfx::xr {

std::unique_ptr<InputBackend> create_input_backend(std::string_view spec,
                                                   const InputBackendOptions& options) {
  if (spec == "sim") return create_sim_backend(options.sim);
  if (spec == "hid") return create_hid_backend({}, options);
  if (spec.starts_with("hid:")) {
    std::vector<std::string> selectors;
    std::string_view rest = spec.substr(4);
    while (!rest.empty()) {
      const auto comma = rest.find(',');
      selectors.emplace_back(rest.substr(0, comma));
      rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
    return create_hid_backend(selectors, options);
  }
  if (spec.starts_with("replay:") && spec.size() > 7) {
    return create_replay_backend(std::filesystem::path(std::string(spec.substr(7))), options);
  }
  throw io::InputError("unknown backend '" + std::string(spec) +
                       "' (expected sim, hid, hid:VID:PID|PATH[,...] or replay:FILE)");
}

}  // namespace vdfx::xr
