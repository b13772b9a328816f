/// @file
/// @brief The knobs `vdfx bench` measures and their settings, as a registry of cases.
///
/// Each area registers its knobs in its own file (app/bench/rbf.cpp, bench_lens.cpp, ...) through
/// one function listed in build_registry(); a case fills its row (time, peer time, error, extras).
/// Adding a knob is a Knob and one add() per setting; adding an area is one more file and one
/// line in build_registry().
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/bench/report.h"
#include "app/bench/timing.h"

namespace vdfx::app::bench {

/// What a case gets to run with.
struct Context {
  bool quick = false;
  Budget budget;
};

/// Fills `row` (knob, setting, peer and reference are preset from the knob). Throwing marks the
/// row failed with the message; GL cases run only with a current GL context.
using CaseFn = std::function<void(Row& row, const Context& ctx)>;

struct Case {
  std::string setting;
  CaseFn run;
  bool gl = false;  //!< needs a GL context (else listed as skipped, with the reason)
};

struct KnobCases {
  Knob knob;
  std::vector<Case> cases;
};

class Registry {
 public:
  /// Adds a knob (ids are unique; throws std::logic_error on a repeat).
  void knob(Knob k);
  /// Adds a setting of an already added knob; it needs GL when the knob does.
  void add(const std::string& knob_id, std::string setting, CaseFn run);
  /// Adds a setting that needs a GL context whatever its knob says (a GL row of a mixed knob).
  void add_gl(const std::string& knob_id, std::string setting, CaseFn run);
  const std::vector<KnobCases>& knobs() const { return knobs_; }

 private:
  void add_case(const std::string& knob_id, Case c);
  std::vector<KnobCases> knobs_;
};

// One function per area, each in its own file; `quick` selects the smaller settings list.
void add_rbf_knobs(Registry& r, bool quick);         // app/bench/rbf.cpp
void add_lens_knobs(Registry& r, bool quick);        // app/bench/lens.cpp
void add_lens_gl_knobs(Registry& r, bool quick);     // app/bench/lens_gl.cpp
void add_blur_knobs(Registry& r, bool quick);        // app/bench/blur.cpp
void add_sampling_knobs(Registry& r, bool quick);    // app/bench/sampling_gl.cpp
void add_effects_gl_knobs(Registry& r, bool quick);  // app/bench/effects_gl.cpp
void add_flare_knobs(Registry& r, bool quick);       // app/bench/flare_gl.cpp
void add_grain_knobs(Registry& r, bool quick);       // app/bench/grain_gl.cpp
void add_decode_knobs(Registry& r, bool quick);      // app/bench/decode.cpp
void add_export_knobs(Registry& r, bool quick);      // app/bench/export.cpp
void add_openxr_knobs(Registry& r, bool quick);      // app/bench/openxr_gl.cpp
void add_suggest_knobs(Registry& r, bool quick);     // app/bench/suggest.cpp
void add_anchor_knobs(Registry& r, bool quick);      // app/bench/anchor.cpp
void add_track_knobs(Registry& r, bool quick);       // app/bench/track.cpp

/// Every knob with the settings of a quick or a full run, in report order.
Registry build_registry(bool quick);

}  // namespace vdfx::app::bench
