/// @file
/// @brief Anchor knobs of `vdfx bench` (docs/anchors.md, "Measured: anchor cost and the turning
/// clip"):
/// - anchor.cost: a frame's evaluation of a stack (the per-pixel parameter grid, 256 x 128 cells,
///   each one stack evaluation) with every effect anchored to the world, timed beside the same
///   stack without anchors: the ratio is what the anchors cost (each anchored effect's centres
///   turned once for the frame, effects::StackAtFrame).
/// - anchor.world_turn: the demo room's panorama turned a full turn in 10 s, the sidecar's camera
///   given; an exposure keyframe on the window in the world. At every frame the view at the
///   window's direction of the video frame is rendered with the anchored sidecar and without
///   effects, and the exposure actually applied (log2 of the two views' ratio) is compared with
///   the keyframe's; the same with the keyframes fixed in the picture (today's video anchor) is
///   the extra video_anchor_max_dev.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/bench/inputs.h"
#include "app/bench/registry.h"
#include "app/bench/turning_clip.h"
#include "effects/equirect_sampler.h"
#include "effects/view_camera.h"
#include "effects/view_renderer.h"
#include "io/sidecar_sets.h"
#include "xr/render/param_grid.h"

namespace vdfx::app::bench {
namespace {

volatile double g_sink = 0.0;  // keeps timed results alive

constexpr int kGridW = 256, kGridH = 128, kCostFrame = 150, kCostFrames = 300;

/// `effects` stack effects (blur excluded: tint, exposure, ...) of `keyframes` random keyframes
/// each over 300 frames, every one anchored as `anchor`.
io::Sidecar cost_sidecar(int effects, int keyframes, const effects::Anchor& anchor) {
  io::Sidecar s = turning_sidecar({"clip.mp4", 30.0, kCostFrames, 3840, 1920},
                                  turning_camera(kCostFrames, 360.0), anchor);
  s.effects.clear();
  for (int e = 0; e < effects; ++e) {
    const auto type = static_cast<effects::EffectType>(1 + e % (effects::kEffectCount - 1));
    const effects::EffectSpec& spec = effects::effect_spec(type);
    effects::EffectTrack t;
    t.type = type;
    t.anchor = anchor;
    t.keyframes = random_keyframes(keyframes, spec.dimension(), 100 + static_cast<std::uint64_t>(e),
                                   kCostFrames - 1);
    s.effects.push_back(std::move(t));
  }
  return s;
}

/// Sum of one parameter over a baked grid (so the work cannot be optimised away).
double grid_sum(const xr::ParamGrid& g) {
  double s = 0.0;
  for (const effects::StackParams& p : g.cells) s += p.exposure_stops + p.saturation;
  return s;
}

/// The unit directions of the grid's cells, as bake_param_grid visits them.
std::vector<Eigen::Vector3d> grid_directions() {
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(kGridW) * kGridH);
  for (int j = 0; j < kGridH; ++j)
    for (int i = 0; i < kGridW; ++i)
      out.push_back(
          effects::to_unit(effects::from_equirect_uv({(i + 0.5) / kGridW, (j + 0.5) / kGridH})));
  return out;
}

/// Every cell's direction turned into the anchor's frame at the cost frame, as an evaluation
/// does; a sum so that the work cannot be optimised away.
double turn_all(const effects::AnchorFrames& frames, const std::vector<Eigen::Vector3d>& cells) {
  double s = 0.0;
  for (const Eigen::Vector3d& u : cells) s += frames.apply(u, kCostFrame).x();
  return s;
}

void add_cost(Registry& r, bool quick) {
  r.knob({"anchor.cost",
          "a frame's evaluation (256 x 128 cells) with every effect anchored to the world", "frame",
          "parameter units", "none: a time only", "the same stack without anchors (video)",
          PlotError::Max, false, false});
  struct Setting {
    int effects, keyframes;
  };
  const std::vector<Setting> settings =
      quick ? std::vector<Setting>{{5, 16}}
            : std::vector<Setting>{{1, 4}, {1, 16}, {5, 4}, {5, 16}, {5, 64}};
  for (const Setting s : settings) {
    r.add("anchor.cost",
          std::to_string(s.effects) + " effects x " + std::to_string(s.keyframes) + " keyframes",
          [s](Row& row, const Context& ctx) {
            const effects::Anchor world{effects::Anchor::Kind::World, {}};
            const io::Sidecar anchored = cost_sidecar(s.effects, s.keyframes, world);
            const io::Sidecar plain = cost_sidecar(s.effects, s.keyframes, {});
            const effects::StackInterpolator a = io::stack_of(anchored), p = io::stack_of(plain);
            // As every per-pixel bake does: the stack at the frame (effects::StackAtFrame),
            // whose anchored effects have their centres turned once, then every cell.
            const auto bake = [](const effects::StackInterpolator& stack) {
              const effects::StackAtFrame at(stack, kCostFrame);
              g_sink = grid_sum(xr::bake_param_grid(
                  [&](const effects::Direction& d) { return at.evaluate(d); }, kGridW, kGridH));
            };
            const auto times = measure_pair({[&] { bake(a); }}, {[&] { bake(p); }}, ctx.budget);
            row.time = times.subject;
            row.peer_time = times.peer;
            row.add("overhead_pct", (row.ratio() - 1.0) * 100.0);
            // The anchor's own step alone (turning the anchored effects' centres for the frame),
            // beside the whole frame without anchors in the same loop: a difference of two
            // frames' times is lost in their spread when it is under a few percent, this is not.
            const auto step = measure_pair({[&] {
                                             g_sink = effects::StackAtFrame(a, kCostFrame)
                                                          .evaluate(Eigen::Vector3d::UnitZ())
                                                          .exposure_stops;
                                           }},
                                           {[&] { bake(p); }}, ctx.budget);
            row.add("anchor_step_ms", step.subject.median_s * 1e3);
            row.add("anchor_step_pct", step.subject.median_s / step.peer.median_s * 100.0);
            // The other way, each cell's direction turned (StackInterpolator::evaluate at a
            // frame, one view: the headset's view-dependent mode), for comparison.
            const std::vector<Eigen::Vector3d> cells = grid_directions();
            const effects::AnchorFrames& frames = a.anchor(anchored.effects.front().type);
            const auto per_cell = measure_pair({[&] { g_sink = turn_all(frames, cells); }},
                                               {[&] { bake(p); }}, ctx.budget);
            row.add("per_cell_turn_pct",
                    per_cell.subject.median_s / per_cell.peer.median_s * 100.0);
            row.note = "the stack's per-pixel grid at frame " + std::to_string(kCostFrame) +
                       " of a camera turning once in 300 frames; random keyframes over the "
                       "frames, exponent 1";
          });
  }
}

/// The exposure (stops) a render applied at the centre of a view: log2 of the ratio of the
/// view's sums with and without the effect.
double applied_stops(const cv::Mat& with, const cv::Mat& without) {
  const cv::Scalar a = cv::sum(with), b = cv::sum(without);
  return std::log2((a[0] + a[1] + a[2]) / (b[0] + b[1] + b[2]));
}

struct TurnResult {
  std::vector<double> deviation;  //!< per frame: applied stops - the keyframe's
  double video_max_dev = 0.0;
};

/// The turn's views at the window, each frame's picture turned from `world`; `frames` in 10 s.
TurnResult measure_turn(const cv::Mat& world, int frames) {
  const io::VideoInfo video{"turn.mp4", frames / 10.0, frames, world.cols, world.rows};
  const effects::CameraMotion camera = turning_camera(frames, 360.0);
  const io::Sidecar anchored = turning_sidecar(video, camera, {effects::Anchor::Kind::World, {}});
  const io::Sidecar fixed = turning_sidecar(video, camera, {});
  const effects::StackInterpolator a = io::stack_of(anchored), v = io::stack_of(fixed);
  TurnResult out;
  for (int f = 0; f < frames; ++f) {
    const double yaw = turning_yaw_deg(f, frames, 360.0);
    const effects::EquirectSampler sampler(turned_panorama(world, yaw));
    const effects::Direction at = video_direction(kRoomWindow, yaw);
    const auto camera_at = effects::ViewCamera::from_horizontal_fov({at, 0.0}, 30.0, 48, 48);
    const cv::Mat plain = effects::render_view(sampler, camera_at, effects::StackParams{});
    const double got =
        applied_stops(effects::render_view(sampler, camera_at, a.evaluate(at, f)), plain);
    const double today =
        applied_stops(effects::render_view(sampler, camera_at, v.evaluate(at, f)), plain);
    out.deviation.push_back(got - kWindowStops);
    out.video_max_dev = std::max(out.video_max_dev, std::abs(today - kWindowStops));
  }
  return out;
}

void add_world_turn(Registry& r, bool quick) {
  r.knob({"anchor.world_turn",
          "world anchor on a turning clip: the exposure applied at the window against its keyframe",
          "frame", "stops", "the window's keyframe (-1.2 stops)",
          "the same frame with the keyframes fixed in the picture (video anchor)", PlotError::Max,
          false, false});
  const int frames = quick ? 60 : 300;
  r.add("anchor.world_turn", "full turn in 10 s, " + std::to_string(frames) + " frames",
        [frames](Row& row, const Context& ctx) {
          const cv::Mat world = interior_panorama(1024);
          const TurnResult t = measure_turn(world, frames);
          double max = 0.0, sq = 0.0;
          for (const double d : t.deviation) max = std::max(max, std::abs(d)), sq += d * d;
          row.error.max = max;
          row.error.rms = std::sqrt(sq / static_cast<double>(t.deviation.size()));
          row.add("video_anchor_max_dev", t.video_max_dev);
          // Time: one frame's evaluation and window view, anchored against the video anchor, on
          // ten frames of the turn held in memory.
          const io::VideoInfo video{"turn.mp4", frames / 10.0, frames, world.cols, world.rows};
          const effects::CameraMotion camera = turning_camera(frames, 360.0);
          const effects::StackInterpolator a =
              io::stack_of(turning_sidecar(video, camera, {effects::Anchor::Kind::World, {}}));
          const effects::StackInterpolator v = io::stack_of(turning_sidecar(video, camera, {}));
          std::vector<cv::Mat> pictures;
          std::vector<int> at_frames;
          for (int f = 0; f < frames; f += frames / 10) {
            pictures.push_back(turned_panorama(world, turning_yaw_deg(f, frames, 360.0)));
            at_frames.push_back(f);
          }
          const auto view = [&](const effects::StackInterpolator& stack) {
            double s = 0.0;
            for (std::size_t i = 0; i < pictures.size(); ++i) {
              const effects::Direction at =
                  video_direction(kRoomWindow, turning_yaw_deg(at_frames[i], frames, 360.0));
              const effects::EquirectSampler sampler(pictures[i]);
              s += cv::sum(effects::render_view(
                  sampler, effects::ViewCamera::from_horizontal_fov({at, 0.0}, 30.0, 48, 48),
                  stack.evaluate(at, at_frames[i])))[0];
            }
            g_sink = s;
          };
          const auto times =
              measure_pair({[&] { view(a); }, static_cast<double>(pictures.size())},
                           {[&] { view(v); }, static_cast<double>(pictures.size())}, ctx.budget);
          row.time = times.subject;
          row.peer_time = times.peer;
          row.note = "Blender's interior.exr at 1024 x 512 turned 360 deg over " +
                     std::to_string(frames) + " frames (camera given); 48 x 48 views of 30 deg";
        });
}

}  // namespace

void add_anchor_knobs(Registry& r, bool quick) {
  add_cost(r, quick);
  add_world_turn(r, quick);
}

}  // namespace vdfx::app::bench
