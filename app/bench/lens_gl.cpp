/// @file
/// @brief Lens knobs of `vdfx bench` that need the GPU for their time: the distortion mesh's
/// vertex count against the per-pixel pre-distortion (error of the mesh's sample positions
/// against the exact map, time per eye), and inverse lateral chromatic aberration on and off
/// (each channel's position as the wearer sees it against where it belongs).
#include <epoxy/gl.h>

#include <cmath>

#include "app/bench/gl_rows.h"
#include "app/bench/inputs.h"
#include "effects/distortion_mesh.h"
#include "xr/render/distortion_gl.h"

namespace vdfx::app::bench {
namespace {

/// generic90's left eye lens at the bench eye's size (half in a quick run).
effects::EyeLens eye_lens(bool quick) {
  effects::EyeLens e = generic90_left_lens();
  const BenchEye b = bench_eye(quick);
  e.width = b.width;
  e.height = b.height;
  return e;
}

/// Times `subject` beside `peer` pre-distorting the bench eye's input into a panel.
PairTimes time_predistort(const Context& ctx, const xr::DistortionSettings& subject,
                          const xr::DistortionSettings& peer) {
  const BenchEye eye = bench_eye(ctx.quick);
  xr::DistortionGl d;
  const xr::GlTarget panel(eye.width, eye.height, xr::TexFormat::RGBA16F);
  const effects::LensModel& lens = generic90_left_lens().lens;
  const xr::GlTexture& src = eye_input(ctx.quick);
  return measure_pair(gl_timed([&] { d.predistort(src, panel, eye.view, lens, subject); }),
                      gl_timed([&] { d.predistort(src, panel, eye.view, lens, peer); }),
                      ctx.budget);
}

/// How far each of R and B lands, as the wearer sees it through the lens, from where the image
/// puts it: the panel point where the eye looking at t_u sees channel c holds the image content
/// of the pre-distortion's source for that channel there.
ErrorStats lca_error(bool correct) {
  const effects::EyeLens& e = generic90_left_lens();
  double worst = 0.0, sum2 = 0.0;
  long n = 0;
  for (int y = 4; y < e.height; y += 8) {
    for (int x = 4; x < e.width; x += 8) {
      const Eigen::Vector2d t_u = e.pixel_to_tan({x + 0.5, y + 0.5});
      for (const int c : {0, 2}) {
        const auto panel = e.lens.view_to_panel(t_u, c);
        if (!panel) continue;
        const auto seen =
            e.lens.source_for_panel(*panel, c, correct, effects::InverseMethod::Newton);
        if (!seen) continue;
        const double err = (e.tan_to_pixel(*seen) - e.tan_to_pixel(t_u)).norm();
        worst = std::max(worst, err);
        sum2 += err * err;
        ++n;
      }
    }
  }
  return {worst, n ? std::sqrt(sum2 / static_cast<double>(n)) : kNaN};
}

}  // namespace

void add_lens_gl_knobs(Registry& r, bool quick) {
  r.knob({"lens.mesh", "lens pre-distortion by an N x N mesh, generic90 left eye", "eye",
          "px (eye image)", "exact per-pixel map (Newton) at every pixel, all channels",
          "per-pixel pre-distortion on the GPU (Newton, 8 iterations)", PlotError::Max, true});
  const std::vector<int> ns =
      quick ? std::vector<int>{9, 33, 65} : std::vector<int>{5, 9, 17, 33, 65};
  for (const int n : ns) {
    r.add("lens.mesh", "N=" + std::to_string(n), [n](Row& row, const Context& ctx) {
      const xr::DistortionSettings mesh{xr::DistortionMethod::Mesh, n, 0, true, false};
      const xr::DistortionSettings pixel{xr::DistortionMethod::Pixel, 0, 8, true, false};
      const PairTimes t = time_predistort(ctx, mesh, pixel);
      row.time = t.subject;
      row.peer_time = t.peer;
      const effects::EyeLens e = eye_lens(ctx.quick);
      const effects::MeshError err =
          effects::measure_mesh_error(e, effects::build_distortion_mesh(e, n), ctx.quick ? 2 : 1);
      row.error = {err.max_px, err.rms_px};
      row.note = std::to_string(e.width) + "x" + std::to_string(e.height) + " eye" +
                 (ctx.quick ? ", every 2nd pixel" : "");
    });
  }

  r.knob({"lens.lca", "inverse lateral chromatic aberration (0.985, 1, 1.015) on and off, mesh 65",
          "eye", "px (eye image)",
          "where each of R and B should be seen (lens model: forward, and Newton inverse)",
          "the other setting", PlotError::Max, true});
  for (const bool on : {true, false}) {
    r.add("lens.lca", on ? "correction on" : "correction off", [on](Row& row, const Context& ctx) {
      const xr::DistortionSettings s{xr::DistortionMethod::Mesh, 65, 0, on, false};
      xr::DistortionSettings other = s;
      other.correct_lca = !on;
      const PairTimes t = time_predistort(ctx, s, other);
      row.time = t.subject;
      row.peer_time = t.peer;
      row.peer = on ? "the same mesh without the correction" : "the same mesh with the correction";
      row.error = lca_error(on);
      row.note = "R and B at every 8th pixel of the 1440x1600 eye";
    });
  }
}

}  // namespace vdfx::app::bench
