/// @file
/// @brief The registry of bench cases and the list of areas that fill it.
#include "app/bench/registry.h"

#include <stdexcept>

namespace vdfx::app::bench {

void Registry::knob(Knob k) {
  for (const KnobCases& kc : knobs_)
    if (kc.knob.id == k.id) throw std::logic_error("bench knob '" + k.id + "' added twice");
  knobs_.push_back({std::move(k), {}});
}

void Registry::add_case(const std::string& knob_id, Case c) {
  for (KnobCases& kc : knobs_) {
    if (kc.knob.id != knob_id) continue;
    c.gl = c.gl || kc.knob.needs_gl;
    kc.cases.push_back(std::move(c));
    return;
  }
  throw std::logic_error("bench setting '" + c.setting + "' of unknown knob '" + knob_id + "'");
}

void Registry::add(const std::string& knob_id, std::string setting, CaseFn run) {
  add_case(knob_id, {std::move(setting), std::move(run), false});
}

void Registry::add_gl(const std::string& knob_id, std::string setting, CaseFn run) {
  add_case(knob_id, {std::move(setting), std::move(run), true});
}

Registry build_registry(bool quick) {
  Registry r;
  add_rbf_knobs(r, quick);
  add_lens_knobs(r, quick);
  add_lens_gl_knobs(r, quick);
  add_blur_knobs(r, quick);
  add_sampling_knobs(r, quick);
  add_effects_gl_knobs(r, quick);
  add_flare_knobs(r, quick);
  add_grain_knobs(r, quick);
  add_decode_knobs(r, quick);
  add_export_knobs(r, quick);
  add_openxr_knobs(r, quick);
  add_suggest_knobs(r, quick);
  add_anchor_knobs(r, quick);
  add_track_knobs(r, quick);
  // A new area registers here: one line, its function in its own file (app/bench/registry.h).
  return r;
}

}  // namespace vdfx::app::bench
