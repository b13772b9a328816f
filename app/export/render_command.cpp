/// @file
/// @brief `vdfx render`: one view of a panorama or video frame with the sidecar's effects, on the
/// CPU reference path or (--gpu) through the GL compositor, optionally as one HMD eye with lens
/// pre-distortion.
#include <iostream>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "app/cli/cli_util.h"
#include "app/cli/command_functions.h"
#include "app/export/view_render.h"
#include "io/excerpt.h"
#include "io/image_write.h"
#include "io/input_error.h"
#include "io/output_path.h"
#include "io/sidecar.h"
#include "xr/blur_method.h"
#include "xr/hmd_profile.h"

namespace vdfx::app {

namespace {

/// Options that would have no effect in this combination are usage errors, not silently
/// ignored (`--eye right` without `--hmd` rendered the plain view, exit 0).
void check_option_combinations(const CLI::App& cli, const std::string& hmd_name,
                               const RenderRequest& r) {
  if (cli.count("--eye") > 0 && hmd_name.empty())
    throw CLI::ValidationError("--eye", "needs --hmd (the eye is one of the headset's)");
  if (cli.count("--no-lca") > 0 && r.distortion.method == xr::DistortionMethod::None)
    throw CLI::ValidationError("--no-lca", "needs --distort pixel or mesh:N");
  if (cli.count("--bake") > 0 && !(r.gpu && r.mode == effects::RenderMode::Pixel))
    throw CLI::ValidationError("--bake",
                               "needs --gpu --mode pixel (the CPU's pixel mode is exact)");
}

}  // namespace

int cmd_render(const Args& args) {
  CLI::App cli{
      "Renders one view of INPUT (a panorama image or a video, equirectangular) with the\n"
      "sidecar's view-dependent effects to an 8-bit sRGB PNG.",
      "vdfx render"};
  std::string input, sidecar_path, view_text, size_text, mode_text = "view", out_path;
  std::string hmd_name, eye_text = "left", distort_text = "none", blur_text = "exact";
  std::string bake_text = "1024x512";
  std::int64_t frame = 0;
  double fov = 0.0;
  bool gpu = false, no_lca = false;
  cli.add_option("INPUT", input, "equirect image (PNG, JPEG, EXR, HDR) or video")->required();
  cli.add_option("--sidecar", sidecar_path, "the effects (.vdfx.json)")->required();
  cli.add_option("--view", view_text, "where to look: AZ,ALT[,ROLL] in degrees")->required();
  cli.add_option("--frame", frame, "video frame index (0-based)")
      ->check(whole_range(0, std::numeric_limits<std::int64_t>::max()));
  cli.add_option("--fov", fov, "horizontal field of view in degrees (not with --hmd)")
      ->check(finite_range(1.0, 179.0));
  cli.add_option("--size", size_text, "output size WxH (with --hmd: default the eye's size)");
  cli.add_option("--mode", mode_text,
                 "view: parameters interpolated once at the view centre (the paper's method);\n"
                 "pixel: at each pixel's own direction (the static per-pixel baseline)")
      ->check(CLI::IsMember({"view", "pixel"}));
  cli.add_flag("--gpu", gpu, "render through the OpenGL compositor (offscreen)");
  cli.add_option(
         "--blur", blur_text,
         "with --gpu: exact (full-resolution separable Gaussian, the contract's kernel) or\n"
         "pyramid (halvings + a small residual blur; faster, small error)")
      ->capture_default_str();
  cli.add_option("--bake", bake_text,
                 "with --gpu --mode pixel: the parameter grid WxH the GPU reads per pixel")
      ->capture_default_str();
  cli.add_option("--hmd", hmd_name, "render one eye of this headset profile (vdfx hmd list)");
  cli.add_option("--eye", eye_text, "with --hmd: left or right")
      ->check(CLI::IsMember({"left", "right"}));
  cli.add_option("--distort", distort_text,
                 "with --hmd: lens pre-distortion none, pixel (exact per pixel) or mesh:N "
                 "(N x N vertex grid)");
  cli.add_flag("--no-lca", no_lca, "with --distort: no inverse lateral chromatic aberration");
  cli.add_option("--out", out_path, "the PNG to write")->required();
  if (auto code = parse_cli(cli, args)) return *code;

  RenderRequest request;
  try {
    const ViewSpec view = parse_view(view_text);
    request.look = view.direction;
    request.roll_deg = view.roll_deg;
    request.mode = mode_text == "pixel" ? effects::RenderMode::Pixel : effects::RenderMode::View;
    request.gpu = gpu;
    request.sidecar_name = sidecar_path;
    request.frame = frame;
    try {
      request.distortion = parse_distortion(distort_text);
    } catch (const std::invalid_argument& e) {
      throw CLI::ValidationError("--distort", e.what());
    }
    request.distortion.correct_lca = !no_lca;
    if (!size_text.empty()) {
      const ImageSize s = parse_size(size_text, "--size", kOutputSizeLimit);
      request.width = s.width;
      request.height = s.height;
    }
    if (hmd_name.empty()) {
      if (fov <= 0.0) throw CLI::ValidationError("--fov", "required (unless --hmd is given)");
      if (size_text.empty())
        throw CLI::ValidationError("--size", "required (unless --hmd is given)");
      if (request.distortion.method != xr::DistortionMethod::None)
        throw CLI::ValidationError("--distort", "needs --hmd (the lens comes from the profile)");
      request.hfov_deg = fov;
    } else if (fov > 0.0) {
      throw CLI::ValidationError("--fov", "the eye's field of view comes from --hmd; drop --fov");
    }
    check_option_combinations(cli, hmd_name, request);
    const std::optional<xr::BlurMethod> blur = xr::blur_method_from_name(blur_text);
    if (!blur)
      throw CLI::ValidationError("--blur",
                                 "'" + io::excerpt(blur_text, 40) + "': expected exact or pyramid");
    request.blur = *blur;
    if (!gpu && request.blur != xr::BlurMethod::Exact)
      throw CLI::ValidationError("--blur", "the CPU reference blur is exact; pyramid needs --gpu");
    const ImageSize bake = parse_size(bake_text, "--bake", kBakeSizeLimit);
    request.bake_width = bake.width;
    request.bake_height = bake.height;
  } catch (const CLI::ValidationError& e) {
    std::cerr << "vdfx render: " << e.what() << "\n";
    return kExitUsage;
  }
  if (!hmd_name.empty()) {
    request.hmd = xr::load_hmd_profile(hmd_name);
    request.eye = eye_text == "right" ? xr::Eye::Right : xr::Eye::Left;
    const xr::EyeProfile& ep = request.hmd->eye(request.eye);
    if (size_text.empty() && std::int64_t{ep.width} * ep.height > kOutputSizeLimit.max_pixels)
      throw io::InputError(request.hmd->source + ": the " + std::string(xr::eye_name(request.eye)) +
                           " eye's " + std::to_string(ep.width) + "x" + std::to_string(ep.height) +
                           " pixels are more than a render may have (" +
                           std::to_string(kOutputSizeLimit.max_pixels) + "); give --size");
  }
  // Before any work: an --out that would destroy an input, or a device, is refused up front.
  std::vector<io::NamedInput> inputs = {{"INPUT", input}, {"--sidecar", sidecar_path}};
  if (request.hmd) inputs.push_back({"--hmd", request.hmd->source});
  io::check_output_is_not_input("--out", out_path, inputs);
  io::resolve_output_path(out_path);

  const io::Sidecar sidecar = io::read_sidecar(sidecar_path);
  if (const auto g = first_gpu_only_grain(sidecar); g && !gpu) {
    std::cerr << "vdfx render: " << sidecar_path << ": grain #" << *g + 1 << " ("
              << effects::grain_style_name(sidecar.grains[*g].style)
              << ") is volumetric and renders on the GPU only: add --gpu\n";
    return kExitUsage;
  }
  const cv::Mat rgb8 = render_request(input, sidecar, request);
  cv::Mat bgr;
  cv::cvtColor(rgb8, bgr, cv::COLOR_RGB2BGR);
  io::write_png(out_path, bgr);
  std::cout << out_path << ": " << rgb8.cols << "x" << rgb8.rows << "\n";
  return kExitOk;
}

}  // namespace vdfx::app
