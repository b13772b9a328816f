/// @file
/// @brief `vdfx render`: one view of a panorama or video frame with the sidecar's effects, on the
/// CPU reference path or (--gpu) through the GL compositor, optionally as one HMD eye with lens
/// pre-distortion.
/// The command parses; app/export/view_render.h renders.
#include <iostream>
#include <limits>
#include <optional>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/cli/layout_options.h"
#include "app/export/view_render.h"
#include "io/excerpt.h"
#include "io/input_error.h"
#include "xr/headset/hmd_profile.h"
#include "xr/render/blur_method.h"

namespace vdfx::app {

namespace {

/// The option texts that need parsing after CLI11.
struct RenderTexts {
  std::string input, sidecar, view, size, mode = "view", out;
  std::string hmd, eye = "left", distort = "none", blur = "exact", bake = "1024x512";
  double fov = 0.0;
  bool no_lca = false;
};

void add_render_options(CLI::App& cli, RenderRequest& r, RenderTexts& t) {
  cli.add_option("INPUT", t.input, "equirect image (PNG, JPEG, EXR, HDR) or video")->required();
  cli.add_option("--sidecar", t.sidecar, "the effects (.vdfx.json)")->required();
  cli.add_option("--view", t.view, "where to look: AZ,ALT[,ROLL] in degrees")->required();
  cli.add_option("--frame", r.frame, "video frame index (0-based)")
      ->check(whole_range(0, std::numeric_limits<std::int64_t>::max()));
  cli.add_option("--fov", t.fov, "horizontal field of view in degrees (not with --hmd)")
      ->check(finite_range(1.0, 179.0));
  cli.add_option("--size", t.size, "output size WxH (with --hmd: default the eye's size)");
  cli.add_option("--mode", t.mode,
                 "view: parameters interpolated once at the view centre (the paper's method);\n"
                 "pixel: at each pixel's own direction (the static per-pixel baseline)")
      ->check(CLI::IsMember({"view", "pixel"}));
  cli.add_flag("--gpu", r.gpu, "render through the OpenGL compositor (offscreen)");
  cli.add_option(
         "--blur", t.blur,
         "with --gpu: exact (full-resolution separable Gaussian, the contract's kernel) or\n"
         "pyramid (halvings + a small residual blur; faster, small error)")
      ->capture_default_str();
  cli.add_option("--bake", t.bake,
                 "with --gpu --mode pixel: the parameter grid WxH the GPU reads per pixel")
      ->capture_default_str();
  cli.add_option("--hmd", t.hmd, "render one eye of this headset profile (vdfx hmd list)");
  cli.add_option("--eye", t.eye,
                 "left or right: the headset's eye (with --hmd) and the stereo video's half")
      ->check(CLI::IsMember({"left", "right"}));
  add_layout_options(cli, r.layout);
  cli.add_option("--distort", t.distort,
                 "with --hmd: lens pre-distortion none, pixel (exact per pixel) or mesh:N "
                 "(N x N vertex grid)");
  cli.add_flag("--no-lca", t.no_lca, "with --distort: no inverse lateral chromatic aberration");
  cli.add_option("--out", t.out, "the PNG to write")->required();
}

/// Options that would have no effect in this combination are usage errors, not silently
/// ignored (`--eye right` without `--hmd` rendered the plain view, exit 0).
/// (--eye without --hmd is checked once the video's layout is known: it needs stereo video.)
void check_option_combinations(const CLI::App& cli, const RenderRequest& r) {
  if (cli.count("--no-lca") > 0 && r.distortion.method == xr::DistortionMethod::None)
    throw CLI::ValidationError("--no-lca", "needs --distort pixel or mesh:N");
  if (cli.count("--bake") > 0 && !(r.gpu && r.mode == effects::RenderMode::Pixel))
    throw CLI::ValidationError("--bake",
                               "needs --gpu --mode pixel (the CPU's pixel mode is exact)");
}

/// The camera: a view with --fov and --size, or (with --hmd) the eye's own.
void parse_camera(const CLI::App& cli, const RenderTexts& t, RenderRequest& r) {
  if (!t.size.empty()) {
    const ImageSize s = parse_size(t.size, "--size", kOutputSizeLimit);
    r.width = s.width;
    r.height = s.height;
  }
  if (t.hmd.empty()) {
    if (t.fov <= 0.0) throw CLI::ValidationError("--fov", "required (unless --hmd is given)");
    if (t.size.empty()) throw CLI::ValidationError("--size", "required (unless --hmd is given)");
    if (r.distortion.method != xr::DistortionMethod::None)
      throw CLI::ValidationError("--distort", "needs --hmd (the lens comes from the profile)");
    r.hfov_deg = t.fov;
  } else if (t.fov > 0.0) {
    throw CLI::ValidationError("--fov", "the eye's field of view comes from --hmd; drop --fov");
  }
  check_option_combinations(cli, r);
}

/// The parsed options as a request (the HMD not loaded yet); throws CLI::ValidationError.
RenderRequest render_request_of(const CLI::App& cli, RenderRequest r, const RenderTexts& t) {
  const ViewSpec view = parse_view(t.view);
  r.look = view.direction;
  r.roll_deg = view.roll_deg;
  r.mode = t.mode == "pixel" ? effects::RenderMode::Pixel : effects::RenderMode::View;
  r.sidecar_name = t.sidecar;
  r.eye_given = cli.count("--eye") > 0;
  r.eye = t.eye == "right" ? xr::Eye::Right : xr::Eye::Left;
  try {
    r.distortion = parse_distortion(t.distort);
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError("--distort", e.what());
  }
  r.distortion.correct_lca = !t.no_lca;
  parse_camera(cli, t, r);
  const std::optional<xr::BlurMethod> blur = xr::blur_method_from_name(t.blur);
  if (!blur)
    throw CLI::ValidationError("--blur",
                               "'" + io::excerpt(t.blur, 40) + "': expected exact or pyramid");
  r.blur = *blur;
  if (!r.gpu && r.blur != xr::BlurMethod::Exact)
    throw CLI::ValidationError("--blur", "the CPU reference blur is exact; pyramid needs --gpu");
  const ImageSize bake = parse_size(t.bake, "--bake", kBakeSizeLimit);
  r.bake_width = bake.width;
  r.bake_height = bake.height;
  return r;
}

/// --hmd's profile and eye; without --size the eye's own size, within the output limit.
void load_eye(RenderRequest& r, const RenderTexts& t) {
  r.hmd = xr::load_hmd_profile(t.hmd);
  const xr::EyeProfile& ep = r.hmd->eye(r.eye);
  if (t.size.empty() && std::int64_t{ep.width} * ep.height > kOutputSizeLimit.max_pixels)
    throw io::InputError(r.hmd->source + ": the " + std::string(xr::eye_name(r.eye)) + " eye's " +
                         std::to_string(ep.width) + "x" + std::to_string(ep.height) +
                         " pixels are more than a render may have (" +
                         std::to_string(kOutputSizeLimit.max_pixels) + "); give --size");
}

}  // namespace

int cmd_render(const Args& args) {
  CLI::App cli{
      "Renders one view of INPUT (a panorama image or a video, equirectangular) with the\n"
      "sidecar's view-dependent effects to an 8-bit sRGB PNG.",
      "vdfx render"};
  RenderRequest options;
  RenderTexts texts;
  add_render_options(cli, options, texts);
  if (auto code = parse_cli(cli, args)) return *code;
  RenderRequest request = parse_request([&] { return render_request_of(cli, options, texts); });
  if (!texts.hmd.empty()) load_eye(request, texts);
  const cv::Size size = render_to_png(texts.input, texts.sidecar, request, texts.out);
  std::cout << texts.out << ": " << size.width << "x" << size.height << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
