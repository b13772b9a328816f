/// @file
/// @brief Baked export knob of `vdfx bench`: the export pipeline (decode, per-pixel render of a
/// typical sidecar, encode with `vdfx export`'s defaults) over a generated H.264 clip, against
/// the same pipeline passing every frame through unchanged (the encoder's floor). The error is
/// that of the export's one approximation, the effect parameters interpolated on a grid
/// (app/export/baked_export.h, automatic step) rather than exactly at every pixel, on the clip's
/// first frame before encoding; the encoder's own loss is not counted.
///
/// 10 bits (docs/export.md, "10 bits"): the same colour export encoded with libx265 as Main10
/// (rendered in float, converted once to 10-bit codes) against the same with libx265 at 8 bits,
/// timed beside it: what a 10-bit master costs over an 8-bit one.
#include <filesystem>

#include "app/bench/error.h"
#include "app/bench/media.h"
#include "app/bench/registry.h"
#include "app/export/baked_export.h"
#include "io/sidecar_sets.h"

namespace vdfx::app::bench {
namespace {

constexpr const char* kKnob = "video.export";

/// Frame 0 of the clip's source (before encoding) baked with the automatic grid against exact
/// per-pixel parameters.
ErrorStats grid_error(const effects::StackInterpolator& stack, int w, int h, double* mean) {
  cv::Mat rgb;
  media_frame(0, w, h).convertTo(rgb, CV_32FC3, 1.0 / 255.0);
  BakedOptions exact;
  exact.param_step = 1;
  return steps_error(render_baked(rgb, stack, 0), render_baked(rgb, stack, 0, exact), mean);
}

/// The 10-bit row: h265 Main10 against h265 8-bit, the same clip and sidecar.
void add_depth_row(Registry& r, int w, int frames) {
  r.add(kKnob, "colour, h265 Main10 vs 8-bit", [=](Row& row, const Context& ctx) {
    namespace fs = std::filesystem;
    const int h = w / 2;
    const fs::path clip = media_clip("vdfx_bench_" + std::to_string(w) + "x" + std::to_string(h) +
                                         "_" + std::to_string(frames) + "_h264.mp4",
                                     w, h, frames);
    const io::Sidecar sc = media_sidecar(false);
    const effects::StackInterpolator stack = io::stack_of(sc);
    const fs::path out = fs::temp_directory_path() / "vdfx_bench_export.mp4";
    const FrameRenderer ten = baked_renderer(stack, {}, 10), eight = baked_renderer(stack, {}, 8);
    const auto t = measure_pair(Timed(
                                    [&] {
                                      export_clip(clip, ten, out, {true, 10});
                                    },
                                    frames),
                                Timed(
                                    [&] {
                                      export_clip(clip, eight, out, {true, 8});
                                    },
                                    frames),
                                ctx.budget);
    std::error_code ec;
    fs::remove(out, ec);
    row.peer = "the same export at 8 bits (libx265 medium crf 20, yuv420p)";
    row.time = t.subject;
    row.peer_time = t.peer;
    double mean = 0.0;
    row.error = grid_error(stack, w, h, &mean);
    row.add("mean_error", mean);
    row.add("frames_per_s", 1.0 / t.subject.median_s);
    row.add("peer_frames_per_s", 1.0 / t.peer.median_s);
    row.note = std::to_string(w) + "x" + std::to_string(h) + ", " + std::to_string(frames) +
               " frames; tint, exposure, saturation; libx265 medium crf 20, Main10 "
               "(yuv420p10le) against 8-bit";
  });
}

}  // namespace

void add_export_knobs(Registry& r, bool quick) {
  r.knob({kKnob,
          "baked export (decode, render, encode: libx264 medium crf 18) of a generated H.264 clip",
          "frame", "8-bit steps",
          "the same frame baked with exact per-pixel parameters (param_step 1), before encoding",
          "the same pipeline with no effects (decode, encode: the encoder's floor)", PlotError::Max,
          false, false});
  const int w = quick ? 960 : 1920, frames = quick ? 6 : 8;
  struct Case {
    bool blur;
    bool stereo;  //!< top-bottom: the frame w x w, each eye's half w x w/2
  };
  std::vector<Case> cases{{false, false}};
  if (!quick) cases.insert(cases.end(), {{true, false}, {false, true}});
  for (const Case c : cases) {
    const std::string name =
        std::string(c.blur ? "colour + blur" : "colour") + (c.stereo ? ", top-bottom stereo" : "");
    r.add(kKnob, name, [=](Row& row, const Context& ctx) {
      namespace fs = std::filesystem;
      const int h = c.stereo ? w : w / 2;
      const fs::path clip = media_clip("vdfx_bench_" + std::to_string(w) + "x" + std::to_string(h) +
                                           "_" + std::to_string(frames) + "_h264.mp4",
                                       w, h, frames);
      const io::Sidecar sc = media_sidecar(c.blur);
      const effects::StackInterpolator stack = io::stack_of(sc);
      const fs::path out = fs::temp_directory_path() / "vdfx_bench_export.mp4";
      const effects::StereoLayout layout{
          c.stereo ? effects::StereoMode::TopBottom : effects::StereoMode::Mono, 360};
      const FrameRenderer baked = baked_renderer(stack, layout), floor = unchanged_renderer();
      const auto t =
          measure_pair(Timed([&] { export_clip(clip, baked, out); }, frames),
                       Timed([&] { export_clip(clip, floor, out); }, frames), ctx.budget);
      std::error_code ec;
      fs::remove(out, ec);
      row.time = t.subject;
      row.peer_time = t.peer;
      double mean = 0.0;
      row.error = grid_error(stack, w, w / 2, &mean);  // one eye's (or the mono) frame
      row.add("mean_error", mean);
      row.add("param_step", baked_param_step({}, w));
      row.add("frames_per_s", 1.0 / t.subject.median_s);
      row.add("peer_frames_per_s", 1.0 / t.peer.median_s);
      // Per pixel, so that the stereo row compares with the mono one (docs/stereo.md).
      row.add("megapixels_per_s", w * static_cast<double>(h) / 1e6 / t.subject.median_s);
      row.note = std::to_string(w) + "x" + std::to_string(h) + ", " + std::to_string(frames) +
                 " frames; tint, exposure, saturation" + (c.blur ? ", blur 0..3 deg" : "") +
                 (c.stereo ? "; each eye's half baked alone" : "") +
                 "; threads: the pipeline's workers, the decoder's and x264's";
    });
  }
  if (!quick) add_depth_row(r, w, frames);
}

}  // namespace vdfx::app::bench
